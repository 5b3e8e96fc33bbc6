#include "glintlab/scene/environment_sources.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "glintlab/core/error.h"
#include "glintlab/core/radical_inverse.h"

namespace glintlab {
namespace {

constexpr double kPi = std::numbers::pi;

glm::vec3 map_direction(double u, double v) {
    const double theta = v * kPi, phi = (u - 0.5) * 2.0 * kPi;
    const double s = std::sin(theta);
    return glm::vec3(glm::dvec3(s * std::sin(phi), std::cos(theta), -s * std::cos(phi)));
}

struct Texel {
    int x, y;
    glm::vec3 rest;    // the surroundings' mean, per channel at most the texel's radiance
    glm::vec3 excess;  // the texel's radiance above it
    double power;      // luminance of the excess × solid angle
};

// The solid-angle-weighted mean radiance of the texels outside the sources
// in the smallest window around a texel that holds any: 3x3 blocks of level
// l of a pyramid of 2^l-texel blocks (wrapping in u), l = 0, 1, ... A lamp's
// edge texels take its halo, its inner texels a wider ring of its
// surroundings. Level 0 is read from the map itself; the coarser levels
// hold (Σ ω L, Σ ω) in floats, a third of the map's own memory.
class Surroundings {
  public:
    Surroundings(const Image& map, const std::vector<char>& in_source,
                 const std::vector<double>& texel_omega)
        : map_(map), in_source_(in_source), texel_omega_(texel_omega) {
        int w = map.width, h = map.height;
        while (w > 1 || h > 1) {
            const int cw = (w + 1) / 2, ch = (h + 1) / 2;
            std::vector<glm::vec4> c(size_t(cw) * size_t(ch), glm::vec4(0.0f));
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    c[size_t(y / 2) * size_t(cw) + size_t(x / 2)] +=
                        levels_.empty() ? base(x, y)
                                        : levels_.back()[size_t(y) * size_t(w) + size_t(x)];
            levels_.push_back(std::move(c));
            widths_.push_back(cw), heights_.push_back(ch);
            w = cw, h = ch;
        }
    }

    glm::vec3 mean(int x, int y) const {
        for (size_t l = 0; l <= levels_.size(); ++l) {
            const int lw = l == 0 ? map_.width : widths_[l - 1];
            const int lh = l == 0 ? map_.height : heights_[l - 1];
            const int cx = x >> l, cy = y >> l;
            glm::dvec4 sum(0.0);
            for (int dy = -1; dy <= 1; ++dy) {
                const int yy = cy + dy;
                if (yy < 0 || yy >= lh) continue;
                for (int dx = -1; dx <= 1; ++dx) {
                    const int xx = ((cx + dx) % lw + lw) % lw;
                    sum +=
                        glm::dvec4(l == 0 ? base(xx, yy)
                                          : levels_[l - 1][size_t(yy) * size_t(lw) + size_t(xx)]);
                }
            }
            if (sum.w > 0.0) return glm::vec3(glm::dvec3(sum) / sum.w);
        }
        return glm::vec3(0.0f);  // every texel a source: not reached (they exceed 50x the mean)
    }

  private:
    glm::vec4 base(int x, int y) const {
        if (in_source_[size_t(y) * size_t(map_.width) + size_t(x)]) return glm::vec4(0.0f);
        const float omega = float(texel_omega_[size_t(y)]);
        return glm::vec4(omega * map_.at(x, y), omega);
    }

    const Image& map_;
    const std::vector<char>& in_source_;
    const std::vector<double>& texel_omega_;
    std::vector<std::vector<glm::vec4>> levels_;  // levels 1, 2, ...
    std::vector<int> widths_, heights_;
};

// The connected sets (8-neighbours, wrapping in u) of the texels marked in
// in_source, each texel with its excess over its surroundings' mean; texels
// without excess are left out, sources without any dropped.
struct Source {
    std::vector<Texel> texels;  // row-major
    double power = 0.0;
};
std::vector<Source> bright_sources(const Image& map, const std::vector<char>& in_source,
                                   const std::vector<double>& texel_omega) {
    const int w = map.width, h = map.height;
    const Surroundings surroundings(map, in_source, texel_omega);
    std::vector<char> seen(in_source.size(), 0);
    std::vector<Source> sources;
    std::vector<size_t> stack;
    for (size_t start = 0; start < in_source.size(); ++start) {
        if (!in_source[start] || seen[start]) continue;
        Source s;
        stack.assign(1, start);
        seen[start] = 1;
        while (!stack.empty()) {
            const size_t i = stack.back();
            stack.pop_back();
            const int x = int(i % size_t(w)), y = int(i / size_t(w));
            const glm::vec3 l = map.at(x, y);
            // Per channel, so that residual + excess is the texel exactly.
            const glm::vec3 rest = glm::min(surroundings.mean(x, y), l);
            Texel t{x, y, rest, l - rest, 0.0};
            t.power = texel_omega[size_t(y)] * luminance(t.excess);
            if (t.power > 0.0) s.texels.push_back(t), s.power += t.power;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int yy = y + dy, xx = ((x + dx) % w + w) % w;
                    if (yy < 0 || yy >= h) continue;
                    const size_t j = size_t(yy) * size_t(w) + size_t(xx);
                    if (in_source[j] && !seen[j]) seen[j] = 1, stack.push_back(j);
                }
        }
        if (s.power > 0.0) {
            std::ranges::sort(s.texels, {}, [](const Texel& t) { return std::pair{t.y, t.x}; });
            sources.push_back(std::move(s));
        }
    }
    return sources;
}

// Samples per source: at least one each, `samples` in all, the rest by
// largest remainder of samples × the source's share of the power (an equal
// share per sample over all sources moved a lamp's 1/K rounding error onto
// another lamp: −15 % on a sphere lit by blender's studio lamps at K = 16).
std::vector<int> allocate_samples(const std::vector<Source>& sources, double total, int samples) {
    const size_t n = sources.size();
    std::vector<double> ideal(n);
    std::vector<int> counts(n);
    int used = 0;
    for (size_t c = 0; c < n; ++c) {
        ideal[c] = samples * sources[c].power / total;
        counts[c] = std::max(1, int(std::floor(ideal[c])));
        used += counts[c];
    }
    while (used < samples) {  // the largest shortfall gets one more
        size_t best = 0;
        for (size_t c = 1; c < n; ++c)
            if (ideal[c] - counts[c] > ideal[best] - counts[best]) best = c;
        ++counts[best], ++used;
    }
    while (used > samples) {  // the largest surplus among those with two or more gives one
        size_t best = n;
        for (size_t c = 0; c < n; ++c)
            if (counts[c] > 1 && (best == n || counts[c] - ideal[c] > counts[best] - ideal[best]))
                best = c;
        --counts[best], --used;
    }
    return counts;
}

}  // namespace

EnvironmentSourceSplit split_environment_sources(const Image& map, int samples,
                                                 float texel_contrast) {
    if (samples < 1) fail("environment sources: at least one sample is needed, got {}", samples);
    if (!(texel_contrast >= 0.0f))
        fail("environment sources: texel_contrast must be >= 0, got {}", texel_contrast);
    const int w = map.width, h = map.height;
    EnvironmentSourceSplit split{map, {}, {}, {}};
    if (w < 1 || h < 1) return split;
    std::vector<double> texel_omega(static_cast<size_t>(h));
    for (int y = 0; y < h; ++y)
        texel_omega[size_t(y)] =
            2.0 * kPi / w * (std::cos(kPi * y / h) - std::cos(kPi * (y + 1) / h));
    double power = 0.0;
    float peak = -1.0f;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float l = luminance(map.at(x, y));
            power += texel_omega[size_t(y)] * l;
            peak = std::max(peak, l);
        }
    const double mean = power / (4.0 * kPi);
    if (!(peak > EnvironmentSourceCriteria::kContrast * mean)) return split;
    const double threshold = texel_contrast > 0.0f
                                 ? texel_contrast * mean
                                 : std::max(double(EnvironmentSourceCriteria::kFraction) * peak,
                                            double(EnvironmentSourceCriteria::kContrast) * mean);
    std::vector<char> in_source(size_t(w) * size_t(h), 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            in_source[size_t(y) * size_t(w) + size_t(x)] = luminance(map.at(x, y)) >= threshold;
    std::vector<Source> sources = bright_sources(map, in_source, texel_omega);
    // The brightest source and each other worth half a sample or more, at
    // most `samples`; the rest stay in the residual as they are in the map.
    if (sources.empty()) return split;
    std::ranges::sort(sources, std::ranges::greater{}, &Source::power);
    double all = 0.0;
    for (const Source& s : sources) all += s.power;
    size_t kept = 1;
    while (kept < sources.size() && kept < size_t(samples) &&
           samples * sources[kept].power >= 0.5 * all)
        ++kept;
    sources.resize(kept);
    double total = 0.0;
    for (const Source& s : sources) total += s.power;
    const std::vector<int> counts = allocate_samples(sources, total, samples);
    for (size_t c = 0; c < sources.size(); ++c) {
        const Source& s = sources[c];
        for (const Texel& t : s.texels) split.residual.at(t.x, t.y) = t.rest;
        // Hammersley points ((k + 1/2) / n, radical inverse of k) through the
        // source's power distribution: the first picks the row and the
        // height in it by the rows' powers, the second the texel and the
        // position in it along the row. Each carries 1/n of the source's
        // power in its texel's colour.
        std::vector<size_t> row_start;  // index in s.texels of each row's first texel
        std::vector<double> row_power;
        for (size_t i = 0; i < s.texels.size(); ++i) {
            if (i == 0 || s.texels[i].y != s.texels[i - 1].y)
                row_start.push_back(i), row_power.push_back(0.0);
            row_power.back() += s.texels[i].power;
        }
        row_start.push_back(s.texels.size());
        double omega = 0.0;
        for (const Texel& t : s.texels) omega += texel_omega[size_t(t.y)];
        const float radius = float(std::sqrt(omega / (kPi * counts[c])));
        size_t r = 0;
        double below = 0.0;  // power of the rows before row r
        for (int k = 0; k < counts[c]; ++k) {
            const double q = (k + 0.5) / counts[c] * s.power;
            while (r + 1 < row_power.size() && below + row_power[r] <= q) below += row_power[r++];
            const double v = std::clamp((q - below) / row_power[r], 0.0, 1.0);
            double along = radical_inverse(unsigned(k)) * row_power[r];
            size_t j = row_start[r];
            while (j + 1 < row_start[r + 1] && s.texels[j].power <= along)
                along -= s.texels[j++].power;
            const Texel& t = s.texels[j];
            const double u = std::clamp(along / t.power, 0.0, 1.0);
            split.directions.push_back(map_direction((t.x + u) / w, (t.y + v) / h));
            split.powers.push_back(t.excess / luminance(t.excess) * float(s.power / counts[c]));
            split.radii.push_back(radius);
        }
    }
    return split;
}

}  // namespace glintlab
