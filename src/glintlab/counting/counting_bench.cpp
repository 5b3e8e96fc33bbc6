// Nanoseconds per sample of each counting law across N: the gated
// laws must cost the same for every N; zirr2016 loops over up to 16 Bernoulli
// trials while N p <= 5 (000 §7.1), so its cost grows with N up to there.
// Uniforms are pre-generated so that only the law is timed; each law is one
// out-of-line call (laws.cpp), as a shader would inline it the call overhead
// (~1 ns) is part of every figure.
#include <benchmark/benchmark.h>

#include <array>
#include <vector>

#include "glintlab/core/rng.h"
#include "glintlab/counting/exact_binomial.h"
#include "glintlab/counting/laws.h"

namespace glintlab {
namespace {

// p = 0.3: N p crosses zirr2016's threshold 5 between N = 16 and N = 17.
constexpr float kP = 0.3f;
constexpr std::array<float, 11> kN = {0.3f,  1.0f,   2.0f, 4.0f, 8.0f, 16.0f,
                                      17.0f, 100.0f, 1e3f, 1e4f, 1e6f};
constexpr size_t kTable = 4096;  // uniforms cycled through (fits in L1)

struct Uniforms {
    std::vector<float> a, b;
    std::vector<glsl::mat4> trials;
    Uniforms() {
        Pcg32 rng(1u, 2u);
        for (size_t i = 0; i < kTable; ++i) {
            a.push_back(rng.next_float());
            b.push_back(rng.next_float());
            glsl::mat4 m;
            for (int k = 0; k < 16; ++k) m[k / 4][k % 4] = rng.next_float();
            trials.push_back(m);
        }
    }
};

const Uniforms& uniforms() {
    static const Uniforms u;
    return u;
}

template <typename Law>
void run(benchmark::State& state, Law law) {
    const float N = kN[static_cast<size_t>(state.range(0))];
    const Uniforms& u = uniforms();
    size_t i = 0;
    float sum = 0.0f;
    for (auto _ : state) {
        sum += law(N, u, i);
        i = (i + 1) & (kTable - 1);
    }
    benchmark::DoNotOptimize(sum);
    state.SetLabel("N=" + std::to_string(N).substr(0, 9));
    state.SetItemsProcessed(state.iterations());
}

void BM_Gaussian(benchmark::State& s) {
    run(s, [](float N, const Uniforms& u, size_t i) {
        return shader::binomial_gaussian(N, kP, u.a[i]);
    });
}
void BM_Zirr2016(benchmark::State& s) {
    run(s, [](float N, const Uniforms& u, size_t i) {
        return shader::binomial_zirr2016(N, kP, u.a[i], u.trials[i]);
    });
}
void BM_Deliot2023(benchmark::State& s) {
    run(s, [](float N, const Uniforms& u, size_t i) {
        return shader::binomial_deliot2023(N, kP, u.a[i], u.b[i]);
    });
}
void BM_SingleGated(benchmark::State& s) {
    run(s, [](float N, const Uniforms& u, size_t i) {
        return shader::binomial_single_gated(N, kP, u.a[i], u.b[i]);
    });
}
void BM_DualGated(benchmark::State& s) {
    run(s, [](float N, const Uniforms& u, size_t i) {
        return shader::binomial_dual_gated(N, kP, u.a[i], u.b[i], false).x;
    });
}
void BM_Multinomial4(benchmark::State& s) {
    run(s, [](float N, const Uniforms& u, size_t i) {
        const glsl::vec4 c = shader::multinomial4(N, glsl::vec4(0.1f, 0.2f, 0.3f, 0.4f),
                                                  glsl::vec4(u.a[i]), glsl::vec4(u.b[i]));
        return c.x;
    });
}
// The exact reference: inversion of a precomputed CDF table (binary search,
// so log(sigma) cost; building the table is not timed).
void BM_ExactInversion(benchmark::State& state) {
    const float N = kN[static_cast<size_t>(state.range(0))];
    const BinomialReference ref(N, kP);
    Pcg32 rng(3u, 4u);
    std::vector<double> u(kTable);
    for (double& x : u) x = rng.next_double();
    size_t i = 0;
    int64_t sum = 0;
    for (auto _ : state) {
        sum += ref.sample(u[i]);
        i = (i + 1) & (kTable - 1);
    }
    benchmark::DoNotOptimize(sum);
    state.SetLabel("N=" + std::to_string(N).substr(0, 9));
    state.SetItemsProcessed(state.iterations());
}

#define COUNTING_BENCH(f) BENCHMARK(f)->DenseRange(0, static_cast<int>(kN.size()) - 1)
COUNTING_BENCH(BM_Gaussian);
COUNTING_BENCH(BM_Zirr2016);
COUNTING_BENCH(BM_Deliot2023);
COUNTING_BENCH(BM_SingleGated);
COUNTING_BENCH(BM_DualGated);
COUNTING_BENCH(BM_Multinomial4);
COUNTING_BENCH(BM_ExactInversion);

}  // namespace
}  // namespace glintlab
