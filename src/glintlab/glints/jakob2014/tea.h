// Counter-based pseudorandom numbers for the stochastic process of 002 §3.4:
// 8 rounds of the Tiny Encryption Algorithm (Wheeler & Needham 1994), keyed by
// the material seed and indexed by the tree node's id (root 1, child j of
// node i is 4i + j - 2), so a node's random choices never depend on the query
// or on the order in which nodes are visited.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>

namespace glintlab::jakob2014 {

inline void tea8(uint32_t& v0, uint32_t& v1, const uint32_t k[4]) {
    uint32_t sum = 0u;
    for (int i = 0; i < 8; ++i) {
        sum += 0x9e3779b9u;
        v0 += ((v1 << 4u) + k[0]) ^ (v1 + sum) ^ ((v1 >> 5u) + k[1]);
        v1 += ((v0 << 4u) + k[2]) ^ (v0 + sum) ^ ((v0 >> 5u) + k[3]);
    }
}

// The stream of uniforms of one node: TEA(node id, counter) under the seed key.
// `salt` separates independent streams of the same node (counts, areas).
class TeaStream {
  public:
    TeaStream(uint64_t node_id, uint32_t seed, uint32_t salt)
        : id_(node_id), key_{seed, seed ^ 0xa341316cu, 0xc8013ea4u ^ salt, 0xad90777du} {}

    uint32_t next_u32() {
        if (have_) {
            have_ = false;
            return spare_;
        }
        uint32_t v0 = static_cast<uint32_t>(id_);
        uint32_t v1 = static_cast<uint32_t>(id_ >> 32u) ^ (counter_++ * 0x9e3779b9u);
        tea8(v0, v1, key_);
        spare_ = v1;
        have_ = true;
        return v0;
    }
    // Uniform in [0, 1) with 32 random bits.
    double next_double() { return next_u32() * 0x1p-32; }
    // Uniform in (0, 1].
    double next_open() { return (next_u32() + 1.0) * 0x1p-32; }
    // Standard normal (Box-Muller; the second value is kept for the next call).
    double next_normal() {
        if (have_normal_) {
            have_normal_ = false;
            return spare_normal_;
        }
        const double r = std::sqrt(-2.0 * std::log(next_open()));
        const double phi = 2.0 * std::numbers::pi * next_double();
        spare_normal_ = r * std::sin(phi);
        have_normal_ = true;
        return r * std::cos(phi);
    }

  private:
    uint64_t id_;
    uint32_t key_[4];
    uint32_t counter_ = 0u;
    uint32_t spare_ = 0u;
    bool have_ = false;
    double spare_normal_ = 0.0;
    bool have_normal_ = false;
};

}  // namespace glintlab::jakob2014
