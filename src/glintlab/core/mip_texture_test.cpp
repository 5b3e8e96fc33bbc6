// MipTexture: the mip chain's levels are exact box means of level 0, the
// lookups wrap as asked, and the anisotropic filter converges to the
// footprint's average where the isotropic one would blur or alias.
#include <gtest/gtest.h>

#include <cmath>

#include "glintlab/core/mip_texture.h"

namespace glintlab {
namespace {

// The exact mean of level 0 over [x0, x1] × [y0, y1] (texel units),
// by brute force over fine subdivisions of each texel.
double box_mean(const std::vector<float>& t, int w, double x0, double x1, double y0, double y1) {
    double sum = 0.0, area = 0.0;
    for (int y = int(y0); y < int(std::ceil(y1)); ++y)
        for (int x = int(x0); x < int(std::ceil(x1)); ++x) {
            const double a = std::max(0.0, std::min(x1, x + 1.0) - std::max(x0, double(x))) *
                             std::max(0.0, std::min(y1, y + 1.0) - std::max(y0, double(y)));
            sum += a * t[size_t(y) * size_t(w) + size_t(x)];
            area += a;
        }
    return sum / area;
}

TEST(MipTexture, LevelsAreExactBoxMeansOfLevelZeroForOddSizes) {
    const int w = 7, h = 5;
    std::vector<float> t(size_t(w * h));
    for (int i = 0; i < w * h; ++i) t[size_t(i)] = float((i * 37) % 11);
    const MipTexture tex(w, h, 1, t, TextureWrap::Repeat);
    ASSERT_EQ(tex.level_count(), 3);  // 7x5, 3x2, 1x1 (OpenGL's sizes)
    for (int level = 1; level < tex.level_count(); ++level) {
        const int lw = tex.width(level), lh = tex.height(level);
        for (int y = 0; y < lh; ++y)
            for (int x = 0; x < lw; ++x) {
                const double expect = box_mean(t, w, double(x) * w / lw, double(x + 1) * w / lw,
                                               double(y) * h / lh, double(y + 1) * h / lh);
                EXPECT_NEAR(tex.texel(level, x, y, 0), expect, 1e-5)
                    << level << " " << x << " " << y;
            }
    }
    // The coarsest level is the image mean.
    double mean = 0.0;
    for (float v : t) mean += v;
    EXPECT_NEAR(tex.texel(2, 0, 0, 0), mean / (w * h), 1e-5);
}

TEST(MipTexture, BilinearWrapsRepeatClampAndMirror) {
    // 4x1: values 0 1 2 3 at u = 1/8, 3/8, 5/8, 7/8.
    const std::vector<float> t = {0, 1, 2, 3};
    const MipTexture repeat(4, 1, 1, t, TextureWrap::Repeat);
    const MipTexture clamp(4, 1, 1, t, TextureWrap::Clamp);
    const MipTexture mirror(4, 1, 1, t, TextureWrap::Mirror);
    EXPECT_NEAR(repeat.bilinear(0, {0.375f, 0.5f}).x, 1.0f, 1e-6f);
    EXPECT_NEAR(repeat.bilinear(0, {1.0f, 0.5f}).x, 1.5f, 1e-6f);  // between 3 and 0
    EXPECT_NEAR(repeat.bilinear(0, {-0.625f, 0.5f}).x, 1.0f, 1e-6f);
    EXPECT_NEAR(clamp.bilinear(0, {1.0f, 0.5f}).x, 3.0f, 1e-6f);
    EXPECT_NEAR(clamp.bilinear(0, {-5.0f, 0.5f}).x, 0.0f, 1e-6f);
    EXPECT_NEAR(mirror.bilinear(0, {1.0f, 0.5f}).x, 3.0f, 1e-6f);    // 3 | 3
    EXPECT_NEAR(mirror.bilinear(0, {1.125f, 0.5f}).x, 3.0f, 1e-6f);  // the mirrored last texel
    EXPECT_NEAR(mirror.bilinear(0, {1.375f, 0.5f}).x, 2.0f, 1e-6f);
    // Far-out coordinates keep their fraction (1e6 + 3/8).
    EXPECT_NEAR(repeat.bilinear(0, {1e6f + 0.375f, 0.5f}).x, 1.0f, 1e-3f);
}

TEST(MipTexture, UAndVWrapApart) {
    // 4x4: texel (x, y) holds 10 y + x.
    std::vector<float> t(16);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) t[size_t(y * 4 + x)] = float(10 * y + x);
    const MipTexture repeat_clamp(4, 4, 1, t, {TextureWrap::Repeat, TextureWrap::Clamp});
    const MipTexture clamp_mirror(4, 4, 1, t, {TextureWrap::Clamp, TextureWrap::Mirror});
    // Past the far corner: u repeats to column 0, v clamps to row 3.
    EXPECT_NEAR(repeat_clamp.bilinear(0, {1.125f, 1.125f}).x, 30.0f, 1e-5f);
    // Before the near corner: u clamps to column 0, v mirrors to row 1.
    EXPECT_NEAR(clamp_mirror.bilinear(0, {-0.375f, -0.375f}).x, 10.0f, 1e-5f);
    // The anisotropic filter wraps its probes the same way: a footprint
    // straddling v = 1 reads rows 3 (clamped) only on the v-clamped texture.
    const glm::vec2 du(0.0f), dv(0.0f, 0.25f);
    EXPECT_NEAR(repeat_clamp.filtered({0.125f, 1.125f}, du, dv).x, 30.0f, 1e-4f);
    EXPECT_EQ(repeat_clamp.wrap(), (TextureWraps{TextureWrap::Repeat, TextureWrap::Clamp}));
    EXPECT_NE(repeat_clamp.wrap(), TextureWraps(TextureWrap::Repeat));
}

TEST(MipTexture, ConstantImageStaysConstantAtEveryLevelAndFootprint) {
    const MipTexture tex(13, 9, 3, std::vector<float>(13 * 9 * 3, 0.25f), TextureWrap::Repeat);
    for (float s : {1e-4f, 0.01f, 0.3f, 5.0f}) {
        const glm::vec3 v = tex.filtered({0.3f, 0.7f}, {s, 0.1f * s}, {0.05f * s, 0.02f * s});
        EXPECT_NEAR(v.x, 0.25f, 1e-6f);
        EXPECT_NEAR(v.z, 0.25f, 1e-6f);
    }
}

// A checkerboard seen at a grazing angle: the footprint is 64 texels along
// u and 1 along v. The exact box average over it is 1/2; the anisotropic
// filter's 16 probes at the level of a 4-texel width get within a few per
// cent, where one isotropic lookup at the footprint's width (level 6 of
// 256: the mean) would also be 1/2 but blur across v — and a lookup at the
// narrow width alone would alias (0 or 1).
TEST(MipTexture, AnisotropicLookupOfACheckerboardConvergesToTheFootprintMean) {
    const int n = 256;
    std::vector<float> t(size_t(n * n));
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) t[size_t(y * n + x)] = float((x / 2 + y / 2) % 2);
    const MipTexture tex(n, n, 1, t, TextureWrap::Repeat);
    double worst = 0.0;
    for (int i = 0; i < 50; ++i) {
        const glm::vec2 uv(0.013f * i, 0.37f + 0.0071f * i);
        const float v = tex.filtered(uv, {64.0f / n, 0.0f}, {0.0f, 1.0f / n}).x;
        worst = std::max(worst, std::abs(double(v) - 0.5));
    }
    EXPECT_LT(worst, 0.05);
    // A footprint of exactly one period of the checker (4 x 4 texels) in
    // both directions: the mean too.
    EXPECT_NEAR(tex.filtered({0.5f, 0.5f}, {4.0f / n, 0.0f}, {0.0f, 4.0f / n}).x, 0.5f, 0.02f);
}

TEST(MipTexture, RejectsBadShapes) {
    EXPECT_THROW(MipTexture(0, 4, 1, {}, TextureWrap::Repeat), std::exception);
    EXPECT_THROW(MipTexture(2, 2, 5, std::vector<float>(20), TextureWrap::Repeat), std::exception);
    EXPECT_THROW(MipTexture(2, 2, 1, std::vector<float>(3), TextureWrap::Repeat), std::exception);
}

}  // namespace
}  // namespace glintlab
