// The lean fuzzing build compiles the glint model descriptors (their
// parameter tables, which the scene reader uses) but not the models. A model
// that shades some lights itself names its lighting functions in its
// descriptor through GLINTLAB_SHADES_LIGHT_HOOK / GLINTLAB_LIGHT_RADIANCE_HOOK
// (glint_model_descriptor.h), which in this build (GLINTLAB_NO_MODEL_LIGHTING)
// point every such model at these two. Only the renderers call them; loading
// a scene never does. They abort loudly should a loader ever reach one.
#include <cstdio>
#include <cstdlib>

#include "glintlab/glints/glint_model_descriptor.h"

namespace glintlab {

namespace {
[[noreturn]] void not_in_fuzz_build(const char* function) {
    std::fprintf(stderr, "%s: model lighting is not part of the fuzzing build\n", function);
    std::abort();
}
}  // namespace

bool shades_light_outside_this_build(const GlintDesc&, const Scene&, int) {
    not_in_fuzz_build(__func__);
}
glm::vec3 light_radiance_outside_this_build(const GlintLightingContext&, int) {
    not_in_fuzz_build(__func__);
}

}  // namespace glintlab
