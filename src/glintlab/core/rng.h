// PCG32 (O'Neill 2014, pcg-random.org: XSH-RR output on a 64-bit LCG), the
// offline sample generator, as in pbrt-v4's RNG. Per-pixel streams are made
// deterministic by seeding with (pixel index, user seed): the same seed gives
// the same image for any thread count or tile order.
#pragma once

#include <cstdint>

namespace glintlab {

class Pcg32 {
  public:
    static constexpr uint64_t kDefaultState = 0x853c49e6748fea9bULL;
    static constexpr uint64_t kDefaultStream = 0xda3e39cb94b95bdbULL;
    static constexpr uint64_t kMultiplier = 0x5851f42d4c957f2dULL;

    Pcg32() = default;
    Pcg32(uint64_t sequence_index, uint64_t seed) { set_sequence(sequence_index, seed); }

    void set_sequence(uint64_t sequence_index, uint64_t seed) {
        state_ = 0u;
        inc_ = (sequence_index << 1u) | 1u;
        next_uint();
        state_ += seed;
        next_uint();
    }

    uint32_t next_uint() {
        const uint64_t old = state_;
        state_ = old * kMultiplier + inc_;
        const auto xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31u));
    }

    // Uniform in [0, bound) without modulo bias.
    uint32_t next_uint(uint32_t bound) {
        const uint32_t threshold = (~bound + 1u) % bound;
        for (;;) {
            const uint32_t r = next_uint();
            if (r >= threshold) return r % bound;
        }
    }

    // Uniform float in [0, 1): 24 random mantissa bits, never 1.
    float next_float() { return static_cast<float>(next_uint() >> 8) * 0x1p-24f; }

    // Uniform double in [0, 1) with 53 random bits.
    double next_double() {
        const uint64_t hi = next_uint();
        const uint64_t lo = next_uint();
        return static_cast<double>(((hi << 32) | lo) >> 11) * 0x1p-53;
    }

    // Skips `delta` outputs in O(log delta) (Brown, "Random number generation
    // with arbitrary strides", 1994), so sample i of a pixel can be reached directly.
    void advance(int64_t delta) {
        uint64_t cur_mult = kMultiplier, cur_plus = inc_, acc_mult = 1u, acc_plus = 0u;
        auto d = static_cast<uint64_t>(delta);
        while (d > 0) {
            if (d & 1u) {
                acc_mult *= cur_mult;
                acc_plus = acc_plus * cur_mult + cur_plus;
            }
            cur_plus = (cur_mult + 1u) * cur_plus;
            cur_mult *= cur_mult;
            d /= 2;
        }
        state_ = acc_mult * state_ + acc_plus;
    }

  private:
    uint64_t state_ = kDefaultState;
    uint64_t inc_ = kDefaultStream;
};

// splitmix64 finaliser (Steele et al. 2014): mixes a 64-bit key into a seed.
constexpr uint64_t mix_bits(uint64_t v) {
    v ^= v >> 31;
    v *= 0x7fb5d329728ea185ULL;
    v ^= v >> 27;
    v *= 0x81dadef4bc2d9cd3ULL;
    v ^= v >> 33;
    return v;
}

// The sample stream of one pixel: independent of tiles and threads.
inline Pcg32 pixel_stream(int x, int y, uint64_t seed) {
    const uint64_t pixel =
        (static_cast<uint64_t>(static_cast<uint32_t>(y)) << 32) | static_cast<uint32_t>(x);
    return Pcg32(mix_bits(pixel), mix_bits(seed ^ 0x9e3779b97f4a7c15ULL));
}

}  // namespace glintlab
