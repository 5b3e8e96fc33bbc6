// The loop every model's robustness experiment runs: `evaluations` random
// queries, in blocks of 2^14 evaluated in parallel, each block drawing from
// its own PCG32 stream (block index, seed) so the counts depend only on the
// seed, never on the thread schedule; plus the parameter draws that hit a
// range's ends exactly (where defects hide) a third of the time each.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <tbb/parallel_for.h>

#include "glintlab/core/rng.h"
#include "glintlab/validate/random_queries.h"

namespace glintlab {

// Calls eval(rng, i, query) for every i in [0, evaluations), with the
// query drawn first from the block's stream; eval may draw more.
template <class Eval>
void for_each_robustness_query(int64_t evaluations, uint64_t seed, Eval&& eval) {
    constexpr int64_t kBlock = 1 << 14;
    const int64_t blocks = (evaluations + kBlock - 1) / kBlock;
    tbb::parallel_for(int64_t{0}, blocks, [&](int64_t b) {
        Pcg32 rng(static_cast<uint64_t>(b), seed);
        const int64_t end = std::min(evaluations, (b + 1) * kBlock);
        for (int64_t i = b * kBlock; i < end; ++i) {
            const RobustnessQuery q = draw_robustness_query(rng);
            eval(rng, i, q);
        }
    });
}

// A model target (ndf, roughness, log density, seed) filled from a query.
template <class Target>
Target robustness_target(const RobustnessQuery& q) {
    Target t;
    t.ndf = q.ndf;
    t.alpha_x = q.alpha_x;
    t.alpha_y = q.alpha_y;
    t.log_density = q.log_density;
    t.seed = q.seed;
    return t;
}

// lo, hi, or lo + (hi - lo) u, each with probability 1/3.
inline float draw_with_ends(Pcg32& rng, float lo, float hi) {
    const uint32_t k = rng.next_uint(3);
    return k == 0 ? lo : k == 1 ? hi : lo + (hi - lo) * rng.next_float();
}

// 10^lo, 10^hi, or log-uniform between them, each with probability 1/3.
inline float draw_log_with_ends(Pcg32& rng, double lo_exp10, double hi_exp10) {
    const uint32_t k = rng.next_uint(3);
    const double e = k == 0 ? lo_exp10 : hi_exp10;
    return static_cast<float>(k <= 1 ? std::pow(10.0, e) : pow10_uniform(rng, lo_exp10, hi_exp10));
}

}  // namespace glintlab
