// The experiment of 000 Fig. 4: successes counted in a window whose size lies
// between two stratified LOD levels. Trials are stratified (one jittered
// facet per texel, each a Bernoulli trial of probability p) on a 32 x 32 texel
// grid. The bottom LOD cell is 8 x 8 texels (64 trials), the top one 16 x 16
// (256); the window is 16 x 7 texels (112 trials, texel-aligned so that it
// holds exactly floor(N P) = 112 trials, Eq. 9), i.e. w_top = 1/4 in Eq. 10.
//  - truth: the simulated count of successes among the facets in the window;
//  - distributed: Eq. 10, b(w_top N P_top) + b(w_bottom N P_bottom), exact
//    binomials (the two trial counts 64 and 48 are integers here);
//  - output blend: Eq. 7, mix of b(256) and b(64) with weight w_top, rounded;
//  - uniform: Eq. 8, the window's trial count is b(1024, 112/1024).
// Each is compared with the law of the stratified count, Bin(112, p), by a
// chi-square goodness-of-fit test (bins merged to >= 5 expected samples).
#pragma once

#include <cstdint>

namespace glintlab {

struct LodBlendResult {
    double p = 0.0;
    int samples = 0;
    double chi2_p_truth = 0.0;         // sanity: the simulation against its own law
    double chi2_p_distributed = 0.0;   // must pass (000 Eq. 10 is exact here)
    double chi2_p_output_blend = 0.0;  // must fail (000 Eq. 7 halves the variance)
    double chi2_p_uniform = 0.0;       // informative: Eq. 8 is another process
    double variance_truth = 0.0, variance_distributed = 0.0, variance_output_blend = 0.0;
};

LodBlendResult run_lod_blend_experiment(double p, int samples, uint64_t seed);

}  // namespace glintlab
