// The libFuzzer main of one target (docs/VALIDATION.md, "Fuzzing"): built
// once per target by fuzz/CMakeLists.txt with GLINTLAB_FUZZ_TARGET set to
// its name. The work is in glintlab::fuzz::run (src/glintlab/fuzz), which
// the regression test of the ordinary suite replays crashing inputs through.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "glintlab/fuzz/fuzz_entries.h"

namespace {

glintlab::fuzz::Target target() {
    static const glintlab::fuzz::Target t = [] {
        const auto found = glintlab::fuzz::target_from_name(GLINTLAB_FUZZ_TARGET);
        if (!found) {
            std::fprintf(stderr, "unknown fuzz target %s\n", GLINTLAB_FUZZ_TARGET);
            std::abort();
        }
        return *found;
    }();
    return t;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    glintlab::fuzz::run(target(), data, size);
    return 0;
}
