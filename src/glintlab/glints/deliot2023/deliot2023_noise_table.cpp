// The noise-texture variant of deliot2023 (000 §6.3): the two uniforms of each
// gated-Gaussian evaluation come from a table of 64 x 64 precomputed pairs
// indexed by the angular cell's hash, instead of two more hash rounds. Only for
// the speed comparison of deliot2023_bench.cpp; renders use the hash.
#include <array>

#include "glintlab/core/glsl.h"
#include "glintlab/core/rng.h"
#include "glintlab/glints/deliot2023/deliot2023.h"

namespace glintlab {
namespace {

constexpr uint32_t kNoiseTexels = 64 * 64;

// Filled once at startup (the paper: "precompute once at startup").
const std::array<glm::vec2, kNoiseTexels> kNoise = [] {
    std::array<glm::vec2, kNoiseTexels> t{};
    Pcg32 rng(0x6465'6c69'6f74ull, 2023);
    for (glm::vec2& v : t) {
        // Sequenced (C++ leaves constructor argument order unspecified): the
        // GPU table (realtime/glint_programs.cpp) pairs (first, second) draw.
        const float first = rng.next_float();
        const float second = rng.next_float();
        v = glm::vec2(first, second);
    }
    return t;
}();

}  // namespace

const std::array<glm::vec2, 64 * 64>& deliot2023_noise_table() {
    return kNoise;
}

}  // namespace glintlab

GLINTLAB_SHADER_FUNCTIONS_BEGIN
// This back end's fetch function of the noise texture.
vec2 deliot2023_noise_fetch(uint cell_hash) {
    return glintlab::kNoise[cell_hash % glintlab::kNoiseTexels];
}
#define GLINTLAB_DELIOT2023_NOISE_TEXTURE 1
#include "glintlab/glints/deliot2023/deliot2023.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {

float deliot2023_ndf_noise_table(glm::vec3 h, const Footprint& footprint,
                                 const Deliot2023Target& target, const Deliot2023Params& params) {
    return shader::deliot2023_ndf(
        h, footprint, target.ndf, target.alpha_x, target.alpha_y, target.rho, target.log_density,
        target.seed, params.microfacet_roughness, params.screen_space_scale,
        params.density_randomization, params.original_defects, params.conditional_gaussian);
}

}  // namespace glintlab
