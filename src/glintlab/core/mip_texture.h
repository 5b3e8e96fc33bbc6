// A texture of 1 to 4 float channels with its mip chain and the filtered
// lookups the CPU renderer makes over a pixel footprint. The lookups follow
// OpenGL's (4.5 core §8.14, and the anisotropic filtering of
// EXT_texture_filter_anisotropic as ARB_texture_filter_anisotropic leaves
// it to the implementation: up to 16 trilinear probes along the footprint's
// major axis), so the GPU's textureGrad over the same mip chain sees the
// same filter.
//
// Coordinates: (u, v) = (0, 0) is the top-left corner of the image, u to
// the right, v down (glTF's convention; rows are uploaded to OpenGL in file
// order, so its t = v). Texel (x, y)'s centre is ((x + 1/2)/w, (y + 1/2)/h).
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace glintlab {

enum class TextureWrap { Repeat, Clamp, Mirror };

// The wrap along u (OpenGL's s) and along v (its t); glTF samplers set the
// two apart (wrapS, wrapT), e.g. a label repeating around a bottle and
// clamped at its top and bottom.
struct TextureWraps {
    TextureWrap u = TextureWrap::Repeat, v = TextureWrap::Repeat;
    constexpr TextureWraps() = default;
    constexpr TextureWraps(TextureWrap both) : u(both), v(both) {}  // NOLINT: one mode for both
    constexpr TextureWraps(TextureWrap u_wrap, TextureWrap v_wrap) : u(u_wrap), v(v_wrap) {}
    bool operator==(const TextureWraps&) const = default;
};

// Index i of a row or column of n texels under `wrap`.
int wrap_texel_index(int i, int n, TextureWrap wrap);

class MipTexture {
  public:
    static constexpr int kMaxAnisotropy = 16;

    // `texels`: width × height × channels floats, row-major from the top row.
    // Builds levels 1.. down to 1 × 1, each level's size OpenGL's (halved and
    // floored, at least 1). Each texel of a level is the exact mean of level
    // 0 over the texel's own rectangle of the unit square (fractional
    // overlaps where a size is odd), so a constant image stays constant and
    // every level keeps the image's mean.
    MipTexture(int width, int height, int channels, std::vector<float> texels, TextureWraps wrap);

    int width(int level = 0) const { return levels_[size_t(level)].width; }
    int height(int level = 0) const { return levels_[size_t(level)].height; }
    int channels() const { return channels_; }
    int level_count() const { return int(levels_.size()); }
    TextureWraps wrap() const { return wrap_; }
    // Texel (x, y) of `level`, channel c (no wrapping: x, y inside the level).
    float texel(int level, int x, int y, int c) const {
        const Level& l = levels_[size_t(level)];
        return l.texels[(size_t(y) * size_t(l.width) + size_t(x)) * size_t(channels_) + size_t(c)];
    }
    const std::vector<float>& level_texels(int level) const {
        return levels_[size_t(level)].texels;
    }

    // Bilinear interpolation of one level at uv (wrap mode applied). The
    // unused channels of the result are 0.
    glm::vec4 bilinear(int level, glm::vec2 uv) const;
    // Bilinear between the two levels around a fractional level of detail
    // (GL_LINEAR_MIPMAP_LINEAR), lod clamped to [0, level_count − 1].
    glm::vec4 trilinear(float lod, glm::vec2 uv) const;
    // The filtered value over the footprint uv + s·duvdx + t·duvdy: the
    // trilinear probes of the anisotropic filter (N = ⌈Pmax/Pmin⌉ ≤ 16 probes
    // along the longer derivative, λ = log2(Pmax/N) in texels).
    // `lod_bias` is added to λ (OpenGL's TEXTURE_LOD_BIAS); the probes'
    // positions stay.
    glm::vec4 filtered(glm::vec2 uv, glm::vec2 duvdx, glm::vec2 duvdy, float lod_bias = 0.0f) const;
    // The λ (bias included) `filtered` reads its probes at; +∞ for a
    // footprint that is not finite, −∞ for an empty one.
    float filter_lod(glm::vec2 duvdx, glm::vec2 duvdy, float lod_bias = 0.0f) const;
    // The largest texel value of level 0 in each channel.
    glm::vec4 max_value() const { return max_; }

  private:
    struct Level {
        int width = 0, height = 0;
        std::vector<float> texels;
    };
    std::vector<Level> levels_;
    int channels_ = 1;
    TextureWraps wrap_;
    glm::vec4 max_{0.0f};
};

}  // namespace glintlab
