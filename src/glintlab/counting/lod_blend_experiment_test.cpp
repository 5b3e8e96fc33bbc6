#include <gtest/gtest.h>

#include "glintlab/counting/lod_blend_experiment.h"

namespace glintlab {
namespace {

// 000 Fig. 4. The window holds 112 stratified trials; Eq. 10 splits them into
// 64 + 48 trials of two independent binomials, which by additivity is exactly
// Bin(112, p): its chi-square p-value is uniform, > 0.01 with probability
// 0.99 (fixed seed: deterministic). Eq. 7 gives variance
// (w^2 256 + (1 - w)^2 64) p q = 52 p q instead of 112 p q: with 20000
// samples the chi-square statistic is in the thousands, p-value ~ 0.
TEST(CountingLodBlend, DistributedBinomialPassesOutputBlendingFails) {
    const LodBlendResult r = run_lod_blend_experiment(0.3, 20000, 77u);
    EXPECT_GT(r.chi2_p_truth, 0.01);  // the simulated stratified count is Bin(112, p)
    EXPECT_GT(r.chi2_p_distributed, 0.01);
    EXPECT_LT(r.chi2_p_output_blend, 0.01);
    EXPECT_NEAR(r.variance_output_blend / r.variance_truth, 52.0 / 112.0, 0.05);
}

}  // namespace
}  // namespace glintlab
