// The GPU bloom of the viewer equals core/bloom.h apply_bloom (the filter of
// the PNG previews) up to float summation order.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <epoxy/gl.h>

#include "glintlab/core/bloom.h"
#include "glintlab/core/rng.h"
#include "glintlab/gl/gl_handles.h"
#include "glintlab/realtime/gpu_bloom.h"
#include "glintlab/realtime/gpu_test_util.h"

namespace glintlab {
namespace {

TEST(GpuBloom, EqualsTheCpuBloom) {
    GLINTLAB_REQUIRE_GL();
    // Dim noise plus a few very bright pixels, some near the borders (where
    // the scatter normalisation matters).
    const int w = 61, h = 47;
    Image image(w, h);
    Pcg32 rng(7, 1);
    for (glm::vec3& p : image.pixels)
        p = glm::vec3(rng.next_float(), rng.next_float(), rng.next_float()) * 0.5f;
    image.at(3, 4) = glm::vec3(40.0f, 30.0f, 20.0f);
    image.at(30, 20) = glm::vec3(5.0f, 9.0f, 2.0f);
    image.at(60, 46) = glm::vec3(100.0f);
    BloomSettings settings;
    settings.strength = 0.3f;
    settings.radius_px = 3.0f;
    settings.threshold = 1.0f;
    const Image expected = apply_bloom(image, settings);

    std::vector<float> rgba(static_cast<size_t>(w) * h * 4, 1.0f);
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) rgba[i * 4 + c] = image.pixels[i][c];
    gl::Texture texture = gl::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(texture.get(), 1, GL_RGBA32F, w, h);
    glTextureSubImage2D(texture.get(), 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, rgba.data());
    gl::GpuBloom bloom;
    const GLuint out = bloom.apply(texture.get(), w, h, settings);
    glGetTextureImage(out, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * sizeof(float)),
                      rgba.data());
    double max_error = 0.0, sum_in = 0.0, sum_out = 0.0;
    for (size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            max_error =
                std::max(max_error, std::abs(double(rgba[i * 4 + c]) - expected.pixels[i][c]));
            sum_in += image.pixels[i][c];
            sum_out += rgba[i * 4 + c];
        }
    // fp32 sums of <= 33 taps of values <= 100: rounding below 1e-4.
    EXPECT_LT(max_error, 1e-4);
    EXPECT_NEAR(sum_out / sum_in, 1.0, 1e-5);  // energy conserving
    EXPECT_EQ(bloom.apply(texture.get(), w, h, BloomSettings{}),
              texture.get());  // strength 0: identity
}

}  // namespace
}  // namespace glintlab
