#include "glintlab/core/bloom.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "glintlab/core/bloom_blur.h"
#include "glintlab/core/error.h"

namespace glintlab {
namespace {

glm::dvec3 channel_sums(const Image& image) {
    glm::dvec3 sum(0.0);
    for (const glm::vec3& p : image.pixels) sum += glm::dvec3(p);
    return sum;
}

// Per-axis second moments about the centre pixel of an image holding one blurred point.
glm::dvec2 second_moments(const Image& image, int cx, int cy) {
    double total = 0.0, xx = 0.0, yy = 0.0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const double v = image.at(x, y).x;
            total += v;
            xx += v * double(x - cx) * double(x - cx);
            yy += v * double(y - cy) * double(y - cy);
        }
    }
    return {xx / total, yy / total};
}

void expect_error(const BloomSettings& s, const std::string& name, const std::string& range) {
    try {
        validate(s);
        ADD_FAILURE() << "no error for " << name;
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(range), std::string::npos) << e.what();
    }
}

TEST(Bloom, ValidatesParametersWithNameAndRange) {
    EXPECT_NO_THROW(validate(BloomSettings{}));
    EXPECT_NO_THROW(validate(BloomSettings{1.0f, 0.5f, 0.0f}));
    expect_error({1.5f, 8.0f, 1.0f}, "strength", "[0, 1]");
    expect_error({-0.1f, 8.0f, 1.0f}, "strength", "[0, 1]");
    expect_error({std::nanf(""), 8.0f, 1.0f}, "strength", "[0, 1]");
    expect_error({0.5f, 0.0f, 1.0f}, "radius_px", "> 0");
    expect_error({0.5f, INFINITY, 1.0f}, "radius_px", "> 0");
    expect_error({0.5f, 8.0f, -1.0f}, "threshold", ">= 0");
    EXPECT_THROW(apply_bloom(Image(4, 4), BloomSettings{2.0f, 8.0f, 1.0f}), Error);
}

TEST(Bloom, OffOrBelowThresholdLeavesImageBitExact) {
    Image image(20, 10);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = glm::vec3(0.9f * float(i % 7) / 6.0f, 0.5f, 0.1f);  // luminance < 1
    EXPECT_EQ(apply_bloom(image, BloomSettings{0.0f, 8.0f, 0.0f}).pixels, image.pixels);
    EXPECT_EQ(apply_bloom(image, BloomSettings{1.0f, 8.0f, 1.0f}).pixels, image.pixels);
}

TEST(Bloom, ExtractBrightSplitsLuminanceAtThresholdKeepingHue) {
    const glm::vec3 colour(4.0f, 2.0f, 1.0f);
    Image image(1, 1, colour);
    const float t = 1.5f;
    const glm::vec3 bright = extract_bright(image, t).at(0, 0);
    // Luminance of the bright part is Y - t; float rounding of a few operations: 1e-6 relative.
    EXPECT_NEAR(luminance(bright), luminance(colour) - t, 1e-6f * luminance(colour));
    EXPECT_NEAR(bright.x / bright.z, 4.0f, 1e-6f);
    EXPECT_NEAR(bright.y / bright.z, 2.0f, 1e-6f);
}

// A sampled Gaussian on the integer grid has variance sigma^2 up to exp(-2 pi^2 sigma^2)
// (Poisson summation, < 1e-8 for sigma >= 1); truncating at 4 sigma removes tail mass that
// carried about 1.1e-3 of the variance. So the measured variance is sigma^2 within 0.3%.
TEST(BloomBlur, GaussianHasRequestedVarianceAndIsIsotropic) {
    for (float sigma : {1.0f, 2.5f, 6.0f}) {
        Image image(81, 81);
        image.at(40, 40) = glm::vec3(1.0f);
        const glm::dvec2 m = second_moments(gaussian_blur_conserving(image, sigma), 40, 40);
        EXPECT_NEAR(m.x / (sigma * sigma), 1.0, 3e-3) << sigma;
        EXPECT_NEAR(m.y / (sigma * sigma), 1.0, 3e-3) << sigma;
    }
}

// The bloom kernel is the mean of Gaussians with sigma = r/4, r/2, r, 2r, so its variance
// per axis is r^2 (1/16 + 1/4 + 1 + 4) / 4 (same 0.3% truncation bound as above).
TEST(BloomBlur, KernelVarianceIsMeanOfOctaves) {
    const float r = 4.0f;
    Image image(81, 81);
    image.at(40, 40) = glm::vec3(1.0f);
    const glm::dvec2 m = second_moments(bloom_blur(image, r), 40, 40);
    const double want = r * r * (1.0 / 16 + 1.0 / 4 + 1.0 + 4.0) / 4.0;
    EXPECT_NEAR(m.x / want, 1.0, 3e-3);
    EXPECT_NEAR(m.y / want, 1.0, 3e-3);
}

// With scatter-normalised borders nothing leaves the frame, even when the kernel (up to
// 4 * 2r = 64 px) is wider than the image and the sources sit on corners and edges. Each
// output is a float sum of positive terms (<= 129 taps per pass, 2 passes, 4 octaves), whose
// relative rounding error is below about 300 * 2^-24 = 1.8e-5; the total inherits that bound.
TEST(Bloom, ConservesEnergyUpToRounding) {
    Image image(60, 45, glm::vec3(0.2f, 0.3f, 0.1f));
    image.at(0, 0) = glm::vec3(50.0f, 20.0f, 5.0f);
    image.at(59, 44) = glm::vec3(10.0f, 80.0f, 3.0f);
    image.at(30, 0) = glm::vec3(7.0f);
    image.at(0, 22) = glm::vec3(3.0f, 4.0f, 30.0f);
    image.at(31, 20) = glm::vec3(100.0f);
    const BloomSettings settings{0.8f, 8.0f, 1.0f};
    const Image out = apply_bloom(image, settings);
    const glm::dvec3 before = channel_sums(image), after = channel_sums(out);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(after[c] / before[c], 1.0, 2e-5) << c;
    // And the bloom really moved energy: the centre source lost strength * bright.
    const float bright_y = luminance(glm::vec3(100.0f)) - settings.threshold;
    EXPECT_LT(out.at(31, 20).x, 100.0f - 0.5f * settings.strength * bright_y);
    EXPECT_GT(out.at(40, 20).x, image.at(40, 20).x);
}

// Glare carries the colour of its source: around a single orange source on black the
// halo has the source's channel ratios (to float rounding, 1e-5 relative).
TEST(Bloom, HaloKeepsSourceHue) {
    Image image(41, 41);
    image.at(20, 20) = glm::vec3(40.0f, 20.0f, 10.0f);
    const Image out = apply_bloom(image, BloomSettings{0.5f, 3.0f, 1.0f});
    for (auto [x, y] : {std::pair{21, 20}, std::pair{25, 23}, std::pair{30, 35}}) {
        const glm::vec3 p = out.at(x, y);
        ASSERT_GT(p.z, 0.0f);
        EXPECT_NEAR(p.x / p.z, 4.0f, 4e-5f);
        EXPECT_NEAR(p.y / p.z, 2.0f, 2e-5f);
    }
}

}  // namespace
}  // namespace glintlab
