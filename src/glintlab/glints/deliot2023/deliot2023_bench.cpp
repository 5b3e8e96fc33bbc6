// Nanoseconds per D_P(h) evaluation of deliot2023 (48 binomial evaluations
// for every footprint, 000 §6.2), with the gated Gaussian's uniforms from a
// hash or from a precomputed noise texture (000 §6.3). Inputs (h near the
// normal, random footprints of 1-8 anisotropy, 1e2-1e5 facets) are
// pre-generated and cycled, so that only the model is timed.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "glintlab/core/rng.h"
#include "glintlab/glints/deliot2023/deliot2023.h"

namespace glintlab {
namespace {

struct Inputs {
    std::vector<glm::vec3> h;
    std::vector<Footprint> fp;
    std::vector<Deliot2023Target> target;
    Inputs() {
        Pcg32 rng(3u, 4u);
        for (int i = 0; i < 1024; ++i) {
            h.push_back(glm::normalize(glm::vec3(0.3f * (rng.next_float() - 0.5f),
                                                 0.3f * (rng.next_float() - 0.5f), 1.0f)));
            const float a = 3.14159265f * rng.next_float();
            const float minor = 1e-3f, ratio = std::exp2(3.0f * rng.next_float());
            fp.push_back(Footprint{glm::vec2(rng.next_float(), rng.next_float()),
                                   glm::vec2(std::cos(a), std::sin(a)) * (minor * ratio),
                                   glm::vec2(-std::sin(a), std::cos(a)) * minor});
            Deliot2023Target t;
            t.alpha_x = t.alpha_y = 0.3f;
            t.log_density = 18.0f + 7.0f * rng.next_float();
            t.seed = rng.next_uint();
            target.push_back(t);
        }
    }
};

template <float (*Eval)(glm::vec3, const Footprint&, const Deliot2023Target&,
                        const Deliot2023Params&)>
void BM_Deliot2023(benchmark::State& state) {
    static const Inputs in;
    const Deliot2023Params params;
    size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(Eval(in.h[i], in.fp[i], in.target[i], params));
        i = (i + 1) & 1023u;
    }
}

BENCHMARK(BM_Deliot2023<deliot2023_ndf>)->Name("deliot2023/hash");
BENCHMARK(BM_Deliot2023<deliot2023_ndf_noise_table>)->Name("deliot2023/noise_table");

}  // namespace
}  // namespace glintlab
