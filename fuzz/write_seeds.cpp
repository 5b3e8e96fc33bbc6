// glintlab_fuzz_seeds TARGET DIR SOURCE_DIR: writes the seed corpus of one
// fuzz target (glintlab::fuzz::write_seeds) into DIR; SOURCE_DIR is the
// repository root (its scenes/ become scene seeds).
#include <cstdio>
#include <exception>

#include "glintlab/fuzz/fuzz_entries.h"

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: %s scene|gltf|obj|image DIR SOURCE_DIR\n", argv[0]);
        return 2;
    }
    const auto target = glintlab::fuzz::target_from_name(argv[1]);
    if (!target) {
        std::fprintf(stderr, "unknown fuzz target '%s' (scene, gltf, obj, image)\n", argv[1]);
        return 2;
    }
    try {
        const size_t n = glintlab::fuzz::write_seeds(*target, argv[2], argv[3]);
        std::printf("%zu seeds for %s in %s\n", n, argv[1], argv[2]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
