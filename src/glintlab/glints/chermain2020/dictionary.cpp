#include "glintlab/glints/chermain2020/dictionary.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>

#include <tbb/parallel_for.h>

#include <fmt/format.h>

#include "glintlab/core/disk_cache.h"
#include "glintlab/core/error.h"
#include "glintlab/core/progress.h"
#include "glintlab/core/rng.h"

namespace glintlab {
namespace {

// One marginal: all its levels, appended to `out` (n_levels * table_size).
void generate_marginal(const DictionaryParams& p, float slope_max, int dist, float* out) {
    const int T = p.table_size;
    const double dx = slope_max / T;
    const double sigma = p.alpha_dict / std::sqrt(2.0);  // Beckmann slope std-dev per axis
    const double inv_2s2 = 1.0 / (2.0 * double(p.lobe_sigma) * p.lobe_sigma);
    // Lobes are cut at 6 lobe std-devs, where they fall below 1.6e-8 of their peak.
    const int reach = static_cast<int>(std::ceil(6.0 * p.lobe_sigma / dx));
    std::vector<double> acc(T, 0.0);
    Pcg32 rng(static_cast<uint64_t>(dist), p.seed);
    auto add_lobe = [&](double mu) {
        const int c = static_cast<int>(std::floor(mu / dx));
        for (int k = std::max(0, c - reach); k <= std::min(T - 1, c + reach + 1); ++k) {
            const double d = k * dx - mu;
            acc[k] += std::exp(-d * d * inv_2s2);
        }
    };
    long draws = 0;
    for (int level = 0; level < p.n_levels; ++level) {
        const long target = 1L << level;  // 2^l nested draws at level l (004 §4.4)
        for (; draws < target; ++draws) {
            // Box-Muller from two 53-bit uniforms (1 - u keeps the log finite),
            // redrawn beyond the table (|mu| >= 4 sigma, p = 6e-5): the tables
            // represent the target truncated there, and a level-0 lobe outside
            // would leave a marginal with no mass to renormalise.
            double mu;
            do {
                const double u1 = 1.0 - rng.next_double(), u2 = rng.next_double();
                mu = sigma * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
            } while (std::abs(mu) >= slope_max);
            // Even density (004 Eq. 5, Fig. 4): the lobe and its mirror.
            add_lobe(mu);
            add_lobe(-mu);
        }
        // Integral over R of the interpolant (zero at slope_max) is
        // 2 dx (sum - v0 / 2): trapezoids over [0, slope_max], doubled by symmetry.
        double sum = 0.0;
        for (double v : acc) sum += v;
        const double integral = 2.0 * dx * (sum - 0.5 * acc[0]);
        float* row = out + static_cast<size_t>(level) * T;
        for (int k = 0; k < T; ++k) row[k] = static_cast<float>(acc[k] / integral);
    }
}

}  // namespace

void check_dictionary_params(const DictionaryParams& p) {
    // 2^(n_levels-1) draws per marginal; 20 levels is ~1e6 draws each.
    if (p.n_levels < 1 || p.n_levels > 20)
        fail("dictionary: n_levels = {} must be in [1, 20]", p.n_levels);
    if (p.n_dists < 1 || p.n_dists > 4096)
        fail("dictionary: n_dists = {} must be in [1, 4096]", p.n_dists);
    if (!(p.alpha_dict >= 0.01f && p.alpha_dict <= 2.0f))
        fail("dictionary: alpha_dict = {} must be in [0.01, 2]", p.alpha_dict);
    // A lobe wider than the target's std-dev would smear it; narrower than
    // 1e-4 would need more table samples than any table holds.
    if (!(p.lobe_sigma >= 1e-4f && p.lobe_sigma <= 0.5f * p.alpha_dict))
        fail("dictionary: lobe_sigma = {} must be in [1e-4, alpha_dict / 2 = {}]", p.lobe_sigma,
             0.5f * p.alpha_dict);
    if (p.table_size < 4 || p.table_size > 4096)
        fail("dictionary: table_size = {} must be in [4, 4096]", p.table_size);
}

namespace {

void fill_running_integrals(Dictionary& d) {
    const size_t width = static_cast<size_t>(d.params.table_size);
    const double step = double(d.slope_max) / double(width);
    d.running_integrals.assign(d.values.size(), 0.0f);
    double integral = 0.0;
    for (size_t i = 0; i < d.values.size(); ++i) {
        if (i % width == 0) integral = 0.0;  // a new row
        const float next = (i % width) + 1 < width ? d.values[i + 1] : 0.0f;
        d.running_integrals[i] = static_cast<float>(integral);
        integral += 0.5 * step * (double(d.values[i]) + double(next));
    }
}

Dictionary generate(const DictionaryParams& params, ProgressReporter* progress) {
    check_dictionary_params(params);
    Dictionary d;
    d.params = params;
    d.slope_max = 4.0f * params.alpha_dict / std::sqrt(2.0f);
    const size_t per_dist = static_cast<size_t>(params.n_levels) * params.table_size;
    d.values.assign(per_dist * params.n_dists, 0.0f);
    // Each marginal has its own PCG32 stream: the result does not depend on
    // the thread count.
    tbb::parallel_for(0, params.n_dists, [&](int i) {
        generate_marginal(params, d.slope_max, i, d.values.data() + per_dist * i);
        if (progress) progress->update();
    });
    fill_running_integrals(d);
    return d;
}

// Bumped whenever generate_marginal changes what it computes.
constexpr uint32_t kDictionaryTableVersion = 1;
constexpr const char* kDictionaryCacheName = "chermain2020_dictionary";

}  // namespace

Dictionary generate_dictionary(const DictionaryParams& params) {
    return generate(params, nullptr);
}

uint64_t dictionary_cache_key(const DictionaryParams& p) {
    CacheKey key(kDictionaryCacheName, kDictionaryTableVersion);
    key.add(p.n_levels).add(p.n_dists).add(p.alpha_dict).add(p.lobe_sigma).add(p.table_size);
    key.add(p.seed);
    return key.value();
}

Dictionary load_or_generate_dictionary(const DictionaryParams& params) {
    check_dictionary_params(params);
    const uint64_t key = dictionary_cache_key(params);
    if (const auto bytes = disk_cache_load(kDictionaryCacheName, key)) {
        ByteReader in(*bytes);
        Dictionary d;
        d.params = params;
        const size_t expected =
            size_t(params.n_dists) * size_t(params.n_levels) * size_t(params.table_size);
        if (in.get(d.slope_max) && in.get_vector(d.values) && in.at_end() &&
            d.values.size() == expected) {
            fill_running_integrals(d);
            return d;
        }
    }
    ProgressReporter progress(params.n_dists,
                              fmt::format("chermain2020 dictionary, {} marginals x {} levels "
                                          "(cached afterwards)",
                                          params.n_dists, params.n_levels),
                              false);
    Dictionary d = generate(params, &progress);
    progress.done();
    ByteWriter out;
    out.put(d.slope_max);
    out.put_vector(d.values);
    disk_cache_store(kDictionaryCacheName, key, out.bytes);
    return d;
}

const Dictionary& default_dictionary() {
    static const Dictionary dict = load_or_generate_dictionary(DictionaryParams{});
    return dict;
}

std::vector<float> chermain2020_dictionary_pairs(const Dictionary& dict) {
    const size_t width = static_cast<size_t>(dict.params.table_size);
    std::vector<float> pairs(dict.values.size() * 2);
    for (size_t i = 0; i < dict.values.size(); ++i) {
        pairs[2 * i] = dict.values[i];
        pairs[2 * i + 1] = (i % width) + 1 < width ? dict.values[i + 1] : 0.0f;
    }
    return pairs;
}

std::vector<float> chermain2020_dictionary_filter_texels(const Dictionary& dict) {
    const size_t width = static_cast<size_t>(dict.params.table_size);
    std::vector<float> texels(dict.values.size() * 3);
    for (size_t i = 0; i < dict.values.size(); ++i) {
        texels[3 * i] = dict.values[i];
        texels[3 * i + 1] = (i % width) + 1 < width ? dict.values[i + 1] : 0.0f;
        texels[3 * i + 2] = dict.running_integrals[i];
    }
    return texels;
}

void write_dictionary(const Dictionary& dict, const std::filesystem::path& path) {
    static_assert(std::endian::native == std::endian::little, "the file format is little-endian");
    std::ofstream out(path, std::ios::binary);
    if (!out) fail("{}: cannot open for writing", path.string());
    const DictionaryParams& p = dict.params;
    const int32_t ints[3] = {p.n_levels, p.n_dists, p.table_size};
    const float floats[3] = {p.alpha_dict, p.lobe_sigma, dict.slope_max};
    out.write("GLDICT01", 8);
    out.write(reinterpret_cast<const char*>(ints), sizeof ints);
    out.write(reinterpret_cast<const char*>(floats), sizeof floats);
    out.write(reinterpret_cast<const char*>(&p.seed), sizeof p.seed);
    out.write(reinterpret_cast<const char*>(dict.values.data()),
              static_cast<std::streamsize>(dict.values.size() * sizeof(float)));
    if (!out) fail("{}: write failed", path.string());
}

}  // namespace glintlab
