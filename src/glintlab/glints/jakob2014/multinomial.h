// Top-down generation of particle counts (002 §3.4): a node's n particles are
// split among its four children by a multinomial draw seeded by the node id,
// and (002 §3.5) the node's particle "areas" by a Dirichlet draw.
#pragma once

#include <array>
#include <cstdint>

namespace glintlab::jakob2014 {

// Multinomial(n, p) (p sums to 1; entries may be 0). Exact for n <= 8 (n
// categorical draws); for n > 8 the paper's approximation: a 4-D normal with
// mean n p and covariance n (diag p - p p^T), rounded to the nearest
// non-negative integers, then components i drawn with probability p_i are
// incremented (or decremented, if positive) until the sum is n.
// Deterministic in (n, p, node_id, seed).
std::array<int64_t, 4> sample_multinomial4(int64_t n, const std::array<double, 4>& p,
                                           uint64_t node_id, uint32_t seed);

// Dirichlet(k_0..k_3) (002 §3.5, Devroye 1986 ch. XI: normalised Gamma(k_j)
// variates); components with k_j = 0 are 0. `channel` selects an independent
// stream per colour channel.
std::array<double, 4> sample_dirichlet4(const std::array<int64_t, 4>& k, uint64_t node_id,
                                        uint32_t seed, uint32_t channel);

}  // namespace glintlab::jakob2014
