#include "glintlab/counting/robustness.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include <tbb/parallel_for.h>

#include "glintlab/core/rng.h"
#include "glintlab/counting/laws.h"

namespace glintlab {
namespace {

float log_uniform(Pcg32& rng, double lo_exp, double hi_exp) {
    return static_cast<float>(std::pow(10.0, lo_exp + (hi_exp - lo_exp) * rng.next_double()));
}

// N: 0, huge (1e15 to 5.5e34 = e^80, the most trials the models draw), or
// log-uniform over [1e-3, 1e16].
float draw_N(Pcg32& rng) {
    switch (rng.next_uint(4)) {
        case 0:
            return 0.0f;
        case 1:
            return log_uniform(rng, 15.0, 34.74);
        default:
            return log_uniform(rng, -3.0, 16.0);
    }
}

// p: 0, 1, below 1e-30 (down to denormals), 1 - tiny, or log-uniform [1e-16, 1].
float draw_p(Pcg32& rng) {
    switch (rng.next_uint(6)) {
        case 0:
            return 0.0f;
        case 1:
            return 1.0f;
        case 2:
            return log_uniform(rng, -44.0, -30.0);
        case 3:
            return 1.0f - log_uniform(rng, -8.0, -1.0);
        default:
            return log_uniform(rng, -16.0, 0.0);
    }
}

// Uniforms including the ends of [0, 1).
float draw_xi(Pcg32& rng) {
    switch (rng.next_uint(16)) {
        case 0:
            return 0.0f;
        case 1:
            return shader::ONE_MINUS_EPSILON;
        default:
            return rng.next_float();
    }
}

bool invalid(float x) {
    return !std::isfinite(x) || x < 0.0f;
}

}  // namespace

RobustnessResult sweep_counting_laws(int64_t samples, uint64_t seed) {
    constexpr int64_t kChunk = 1 << 16;
    const int64_t chunks = (samples + kChunk - 1) / kChunk;
    std::atomic<int64_t> bad{0}, evaluations{0};
    tbb::parallel_for(int64_t{0}, chunks, [&](int64_t c) {
        Pcg32 rng(mix_bits(static_cast<uint64_t>(c)), mix_bits(seed));
        int64_t local_bad = 0, local_evals = 0;
        const int64_t end = std::min(samples, (c + 1) * kChunk);
        for (int64_t i = c * kChunk; i < end; ++i) {
            const float N = draw_N(rng), p = draw_p(rng);
            const float xi1 = draw_xi(rng), xi2 = draw_xi(rng);
            glsl::mat4 trials;
            for (int k = 0; k < 16; ++k) trials[k / 4][k % 4] = draw_xi(rng);
            const glsl::vec2 dual = shader::binomial_dual_gated(N, p, xi1, xi2, false);
            const glsl::vec2 dual_int = shader::binomial_dual_gated(N, p, xi1, xi2, true);
            // kneiphof2025's conditional law, with the integer N it is given there.
            const glsl::vec2 cond =
                shader::binomial_dual_gated_conditional(std::floor(N), p, xi1, xi2, true);
            const float values[] = {shader::binomial_gaussian(N, p, xi2),
                                    shader::binomial_zirr2016(N, p, xi2, trials),
                                    shader::binomial_deliot2023(N, p, xi1, xi2),
                                    shader::binomial_single_gated(N, p, xi1, xi2),
                                    shader::binomial_single_gated_conditional(N, p, xi1, xi2),
                                    dual.x,
                                    dual.y,
                                    dual_int.x,
                                    dual_int.y,
                                    cond.x,
                                    cond.y,
                                    shader::pow_one_minus_stable(p, N)};
            for (float v : values) local_bad += invalid(v) ? 1 : 0;
            local_evals += 12;
            // Multinomial over 4 bins with a random split of the probability.
            const glsl::vec4 probs(rng.next_float(), rng.next_float(), rng.next_float(), p);
            const glsl::vec4 counts =
                shader::multinomial4(N, probs, glsl::vec4(xi1, draw_xi(rng), draw_xi(rng), 0.0f),
                                     glsl::vec4(xi2, draw_xi(rng), draw_xi(rng), 0.0f));
            for (int k = 0; k < 4; ++k) local_bad += invalid(counts[k]) ? 1 : 0;
            local_evals += 4;
        }
        bad += local_bad;
        evaluations += local_evals;
    });
    return {evaluations.load(), bad.load()};
}

}  // namespace glintlab
