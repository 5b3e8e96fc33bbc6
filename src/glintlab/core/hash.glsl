// Integer hashes and hash-based random numbers shared by CPU and GPU code.
//  - pcg_hash, pcg3d, pcg4d: Jarzynski & Olano, "Hash Functions for GPU
//    Rendering", JCGT 9(3), 2020 (PCG-RXS-M-XS 32 and its 3-D/4-D variants).
//  - xxhash32: Yann Collet's xxHash32 avalanche, as in Jarzynski & Olano.
//  - tea: Tiny Encryption Algorithm (Wheeler & Needham 1994); jakob2014 seeds
//    its stochastic hierarchy with 8 rounds (Zafar et al. 2010).
#ifndef GLINTLAB_CORE_HASH_GLSL
#define GLINTLAB_CORE_HASH_GLSL

uint pcg_hash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

uvec3 pcg3d(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v = v ^ (v >> 16u);
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

uvec4 pcg4d(uvec4 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    v = v ^ (v >> 16u);
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    return v;
}

uint xxhash32(uint p) {
    const uint PRIME32_2 = 2246822519u;
    const uint PRIME32_3 = 3266489917u;
    const uint PRIME32_4 = 668265263u;
    const uint PRIME32_5 = 374761393u;
    uint h32 = p + PRIME32_5;
    h32 = PRIME32_4 * ((h32 << 17u) | (h32 >> 15u));
    h32 = PRIME32_2 * (h32 ^ (h32 >> 15u));
    h32 = PRIME32_3 * (h32 ^ (h32 >> 13u));
    return h32 ^ (h32 >> 16u);
}

// Order-dependent combination of two 32-bit values into one hash.
uint hash_combine(uint seed, uint v) {
    return xxhash32(seed ^ (v + 0x9e3779b9u + (seed << 6u) + (seed >> 2u)));
}

// Hash of an integer cell coordinate and a seed (grids of the glint models).
uint hash_cell(ivec2 cell, uint seed) {
    return hash_combine(hash_combine(seed, uint(cell.x)), uint(cell.y));
}

uint hash_cell3(ivec3 cell, uint seed) {
    return hash_combine(hash_cell(ivec2(cell.x, cell.y), seed), uint(cell.z));
}

// TEA with a configurable number of rounds (jakob2014 uses 8).
uvec2 tea(uvec2 v, int rounds) {
    uint v0 = v.x;
    uint v1 = v.y;
    uint sum = 0u;
    for (int i = 0; i < rounds; ++i) {
        sum += 0x9e3779b9u;
        v0 += ((v1 << 4u) + 0xa341316cu) ^ (v1 + sum) ^ ((v1 >> 5u) + 0xc8013ea4u);
        v1 += ((v0 << 4u) + 0xad90777du) ^ (v0 + sum) ^ ((v0 >> 5u) + 0x7e95761eu);
    }
    return uvec2(v0, v1);
}

// Uniform float in [0, 1) from the top 24 bits of a 32-bit integer: every
// value is exactly representable, and 1 is never returned.
float uint_to_unit_float(uint x) {
    return float(x >> 8u) * (1.0f / 16777216.0f);
}

// Hash-driven stream of uniform numbers for shaders: state advanced by
// pcg_hash. Good enough for per-cell decisions; offline code uses PCG32 (rng.h).
float hash_random(INOUT(uint) state) {
    state = pcg_hash(state);
    return uint_to_unit_float(state);
}

#endif
