// The lean fuzzing build compiles the glint model descriptors (their
// parameter tables, which the scene reader uses) but not the models. Three
// descriptors point at their model's lighting functions, which only the
// renderers call; loading a scene never does. These definitions satisfy the
// linker and abort loudly should a loader ever reach one.
#include <cstdio>
#include <cstdlib>

#include "glintlab/glints/explicit/explicit_model.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025.h"
#include "glintlab/glints/wang2020/wang2020_model.h"

namespace glintlab {

namespace {
[[noreturn]] void not_in_fuzz_build(const char* function) {
    std::fprintf(stderr, "%s: model lighting is not part of the fuzzing build\n", function);
    std::abort();
}
}  // namespace

bool explicit_shades_light(const GlintDesc&, const Scene&, int) {
    not_in_fuzz_build(__func__);
}
glm::vec3 explicit_light_radiance(const GlintLightingContext&, int) {
    not_in_fuzz_build(__func__);
}
bool kneiphof2025_shades_light(const GlintDesc&, const Scene&, int) {
    not_in_fuzz_build(__func__);
}
glm::vec3 kneiphof2025_light_radiance(const GlintLightingContext&, int) {
    not_in_fuzz_build(__func__);
}
bool wang2020_shades_light(const GlintDesc&, const Scene&, int) {
    not_in_fuzz_build(__func__);
}
glm::vec3 wang2020_light_radiance(const GlintLightingContext&, int) {
    not_in_fuzz_build(__func__);
}

}  // namespace glintlab
