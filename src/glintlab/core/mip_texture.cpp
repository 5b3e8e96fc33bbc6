#include "glintlab/core/mip_texture.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "glintlab/core/error.h"

namespace glintlab {
namespace {

// Weights of the fine cells (n over [0, 1]) that make up coarse cell j (of
// m): the overlap of each with the coarse cell, divided by its length, so
// the weights sum to 1.
struct Row {
    int first = 0;
    std::vector<double> weights;
};
std::vector<Row> box_weights(int m, int n) {
    std::vector<Row> rows(static_cast<size_t>(m));
    for (int j = 0; j < m; ++j) {
        const double a = double(j) / m, b = double(j + 1) / m;
        const int first = int(int64_t(j) * n / m);
        const int last = int((int64_t(j + 1) * n + m - 1) / m);
        rows[size_t(j)].first = first;
        for (int i = first; i < last; ++i) {
            const double lo = std::max(a, double(i) / n), hi = std::min(b, double(i + 1) / n);
            rows[size_t(j)].weights.push_back(std::max(0.0, hi - lo) * m);
        }
    }
    return rows;
}

}  // namespace

MipTexture::MipTexture(int width, int height, int channels, std::vector<float> texels,
                       TextureWraps wrap)
    : channels_(channels), wrap_(wrap) {
    if (width < 1 || height < 1 || channels < 1 || channels > 4)
        fail("texture: {}x{} with {} channels (need a size of at least 1x1 and 1 to 4 channels)",
             width, height, channels);
    if (texels.size() != size_t(width) * size_t(height) * size_t(channels))
        fail("texture: {} texels given for {}x{}x{}", texels.size(), width, height, channels);
    for (size_t i = 0; i < texels.size(); ++i)
        max_[int(i % size_t(channels))] = std::max(max_[int(i % size_t(channels))], texels[i]);
    int count = 1;
    for (int w = width, h = height; w > 1 || h > 1; w = std::max(1, w / 2), h = std::max(1, h / 2))
        ++count;
    levels_.reserve(size_t(count));  // `base` stays valid while levels are appended
    levels_.push_back({width, height, std::move(texels)});
    const std::vector<float>& base = levels_[0].texels;
    const size_t c = size_t(channels);
    int w = width, h = height;
    while (w > 1 || h > 1) {
        w = std::max(1, w / 2), h = std::max(1, h / 2);
        // Separable: each row of level 0 to width w, then each column to h.
        const std::vector<Row> cols = box_weights(w, width), rows = box_weights(h, height);
        std::vector<double> narrow(size_t(w) * size_t(height) * c, 0.0);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < w; ++x) {
                const Row& r = cols[size_t(x)];
                for (size_t k = 0; k < r.weights.size(); ++k)
                    for (size_t ch = 0; ch < c; ++ch)
                        narrow[(size_t(y) * size_t(w) + size_t(x)) * c + ch] +=
                            r.weights[k] *
                            base[(size_t(y) * size_t(width) + size_t(r.first) + k) * c + ch];
            }
        Level level{w, h, std::vector<float>(size_t(w) * size_t(h) * c)};
        for (int y = 0; y < h; ++y) {
            const Row& r = rows[size_t(y)];
            for (int x = 0; x < w; ++x)
                for (size_t ch = 0; ch < c; ++ch) {
                    double sum = 0.0;
                    for (size_t k = 0; k < r.weights.size(); ++k)
                        sum += r.weights[k] *
                               narrow[((size_t(r.first) + k) * size_t(w) + size_t(x)) * c + ch];
                    level.texels[(size_t(y) * size_t(w) + size_t(x)) * c + ch] = float(sum);
                }
        }
        levels_.push_back(std::move(level));
    }
}

int wrap_texel_index(int i, int n, TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::Clamp:
            return std::clamp(i, 0, n - 1);
        case TextureWrap::Mirror: {
            const int period = 2 * n;
            int k = i % period;
            if (k < 0) k += period;
            return k < n ? k : period - 1 - k;
        }
        case TextureWrap::Repeat:
            break;
    }
    const int k = i % n;
    return k < 0 ? k + n : k;
}

glm::vec4 MipTexture::bilinear(int level, glm::vec2 uv) const {
    level = std::clamp(level, 0, level_count() - 1);
    const Level& l = levels_[size_t(level)];
    // Far-out coordinates (a huge uv_transform scale) lose the fraction in
    // float; the wrap of a double keeps it for repeat and mirror.
    const double x = double(uv.x) * l.width - 0.5, y = double(uv.y) * l.height - 0.5;
    if (!std::isfinite(x) || !std::isfinite(y)) return glm::vec4(0.0f);
    const double fx0 = std::floor(x), fy0 = std::floor(y);
    const float tx = float(x - fx0), ty = float(y - fy0);
    // Indices of the two texels around f (texel units) under the wrap mode;
    // repeat and mirror first reduce f modulo 2n in double.
    auto indices = [&](double f, int n, TextureWrap wrap, int out[2]) {
        if (wrap == TextureWrap::Clamp) {
            const int i = int(std::clamp(f, -1.0, double(n)));
            out[0] = std::clamp(i, 0, n - 1), out[1] = std::clamp(i + 1, 0, n - 1);
            return;
        }
        const double period = 2.0 * n;
        const int i = int(f - period * std::floor(f / period));
        out[0] = wrap_texel_index(i, n, wrap), out[1] = wrap_texel_index(i + 1, n, wrap);
    };
    int cx[2], cy[2];
    indices(fx0, l.width, wrap_.u, cx);
    indices(fy0, l.height, wrap_.v, cy);
    glm::vec4 out(0.0f);
    for (int ch = 0; ch < channels_; ++ch) {
        auto t = [&](int i, int j) {
            return l.texels[(size_t(cy[j]) * size_t(l.width) + size_t(cx[i])) * size_t(channels_) +
                            size_t(ch)];
        };
        const float top = t(0, 0) + tx * (t(1, 0) - t(0, 0));
        const float bottom = t(0, 1) + tx * (t(1, 1) - t(0, 1));
        out[ch] = top + ty * (bottom - top);
    }
    return out;
}

glm::vec4 MipTexture::trilinear(float lod, glm::vec2 uv) const {
    if (!(lod > 0.0f)) return bilinear(0, uv);  // magnification: GL_LINEAR
    const float top = float(level_count() - 1);
    if (lod >= top) return bilinear(level_count() - 1, uv);
    const int l0 = int(lod);
    const float f = lod - float(l0);
    const glm::vec4 a = bilinear(l0, uv);
    return f > 0.0f ? a + f * (bilinear(l0 + 1, uv) - a) : a;
}

namespace {
struct Probes {
    int count;
    float lod;
};
// N = ⌈Pmax/Pmin⌉ ≤ 16 probes at λ = log2(Pmax/N) + bias (texture_filter.glsl).
Probes probes_of(float px, float py, float lod_bias) {
    const float pmax = std::max(px, py), pmin = std::min(px, py);
    const int n = int(std::min<float>(float(MipTexture::kMaxAnisotropy),
                                      std::ceil(pmax / std::max(pmin, pmax * 1e-6f))));
    return {n, std::log2(pmax / float(n)) + lod_bias};
}
}  // namespace

float MipTexture::filter_lod(glm::vec2 duvdx, glm::vec2 duvdy, float lod_bias) const {
    const glm::vec2 size = glm::vec2(float(width()), float(height()));
    const float px = glm::length(duvdx * size), py = glm::length(duvdy * size);
    if (!std::isfinite(px) || !std::isfinite(py)) return std::numeric_limits<float>::infinity();
    if (!(std::max(px, py) > 0.0f)) return -std::numeric_limits<float>::infinity();
    return probes_of(px, py, lod_bias).lod;
}

glm::vec4 MipTexture::filtered(glm::vec2 uv, glm::vec2 duvdx, glm::vec2 duvdy,
                               float lod_bias) const {
    const glm::vec2 size = glm::vec2(float(width()), float(height()));
    const float px = glm::length(duvdx * size), py = glm::length(duvdy * size);
    if (!std::isfinite(px) || !std::isfinite(py)) return trilinear(float(level_count() - 1), uv);
    if (!(std::max(px, py) > 0.0f)) return bilinear(0, uv);
    const Probes p = probes_of(px, py, lod_bias);
    const glm::vec2 major = px >= py ? duvdx : duvdy;
    glm::vec4 sum(0.0f);
    for (int i = 0; i < p.count; ++i)
        sum += trilinear(p.lod, uv + major * ((float(i) + 0.5f) / float(p.count) - 0.5f));
    return sum / float(p.count);
}

}  // namespace glintlab
