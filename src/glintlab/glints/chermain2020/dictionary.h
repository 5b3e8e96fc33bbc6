// The chermain2020 dictionary of multiscale marginal slope distributions
// (Chermain et al. 2020, 004 §4.4-4.5): N even 1-D densities P_i(x, l), tabulated over
// |x| in [0, 4 sigma) for every level l in [0, nLevels), each converging to
// the Beckmann marginal of roughness alpha_dict as l grows.
// Generated deterministically in memory (never committed as a binary);
// `glintlab dict` writes it to a file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace glintlab {

struct DictionaryParams {
    int n_levels = 16;            // nLevels (004 §4.4)
    int n_dists = 192;            // N marginal distributions (004 §4.5)
    float alpha_dict = 0.5f;      // roughness of the target Beckmann SDF
    float lobe_sigma = 0.02f;     // std-dev of each Gaussian lobe
    int table_size = 64;          // samples per 1-D table
    uint64_t seed = 0x43686572u;  // PCG32 seed of the lobe means
};

// Throws glintlab::Error naming the parameter and its allowed range.
void check_dictionary_params(const DictionaryParams& p);

struct Dictionary {
    DictionaryParams params;
    // Table values, index ((dist * n_levels) + level) * table_size + bin;
    // bin k holds P(x_k) at x_k = k * slope_max / table_size.
    std::vector<float> values;
    float slope_max = 0.0f;  // 4 sigma, sigma = alpha_dict / sqrt(2)
    // Each row's integral from 0 to bin k's slope, exact for the
    // piecewise-linear interpolant (trapezoids), in the layout of `values`:
    // what geometric glint anti-aliasing's box filter reads.
    std::vector<float> running_integrals;

    float at(int dist, int level, int bin) const {
        return values[(static_cast<size_t>(dist) * params.n_levels + level) * params.table_size +
                      bin];
    }
};

// 004 §4.4: level l of marginal i is the mean of 2^l mirrored Gaussian lobes
// whose means are the first 2^l draws of N(0, sigma) of that marginal
// (levels are nested), renormalised so that the piecewise-linear
// interpolant (zero at slope_max) integrates to 1 over the real line.
Dictionary generate_dictionary(const DictionaryParams& params);

// generate_dictionary through the on-disk table cache (core/disk_cache.h;
// ~4 s of CPU for the default parameters): a hit returns the generated
// values bit for bit; otherwise the dictionary is generated with a progress
// bar (on a terminal) and stored. The key hashes every parameter and a
// table version (dictionary_cache_key).
Dictionary load_or_generate_dictionary(const DictionaryParams& params);
uint64_t dictionary_cache_key(const DictionaryParams& params);

// The dictionary with the default parameters, loaded or generated on first
// use (load_or_generate_dictionary; thread-safe function-local static) and
// shared by all evaluations.
const Dictionary& default_dictionary();

// The values as pairs for a two-channel texture (the GPU forward pass and
// `glintlab export`): element 2 i holds values[i], element 2 i + 1 the next
// sample of the same row, 0 after the row's last sample; one fetch then
// gives both values of chermain2020.glsl's linear interpolation.
std::vector<float> chermain2020_dictionary_pairs(const Dictionary& dict);

// Texels of three values for geometric glint anti-aliasing (chermain2020.glsl
// chermain2020_marginal_box; the GPU forward pass and the C++ back end):
// element 3 i holds values[i], 3 i + 1 the next sample of the same row (0
// after the row's last), 3 i + 2 the row's integral from 0 to the sample's
// slope (Dictionary::running_integrals).
std::vector<float> chermain2020_dictionary_filter_texels(const Dictionary& dict);

// Binary file: "GLDICT01", int32 n_levels, n_dists, table_size, float32
// alpha_dict, lobe_sigma, slope_max, uint64 seed, then the float32 values
// (little-endian, the layout of Dictionary::values).
void write_dictionary(const Dictionary& dict, const std::filesystem::path& path);

}  // namespace glintlab
