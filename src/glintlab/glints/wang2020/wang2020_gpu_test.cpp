// wang2020's post-process blurs on the GPU (wang2020_gpu_blur.h) equal the
// CPU's postprocess_glints (001 §4.4) up to float summation order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "glintlab/core/error.h"
#include "glintlab/core/rng.h"
#include "glintlab/glints/wang2020/wang2020_gpu_blur.h"
#include "glintlab/glints/wang2020/wang2020_postprocess.h"
#include "glintlab/realtime/gpu_test_util.h"

namespace glintlab {
namespace {

TEST(GpuWang2020Blur, EqualsTheCpuPostprocess) {
    GLINTLAB_REQUIRE_GL();
    // Sparse bright glints on noise, an occluded block (visibility 0) and
    // glints at the borders (the clamped edges).
    wang2020::GlintBuffer in{37, 23, {}};
    in.texels.resize(static_cast<size_t>(in.width) * in.height);
    Pcg32 rng(3, 8);
    for (glm::vec4& t : in.texels)
        t = glm::vec4(0.1f * rng.next_float(), 0.1f * rng.next_float(), 0.1f * rng.next_float(),
                      rng.next_float() < 0.9f ? 1.0f : 0.0f);
    for (int y = 5; y < 12; ++y)
        for (int x = 20; x < 30; ++x) in.texels[static_cast<size_t>(y) * in.width + x].w = 0.0f;
    for (const int k : {0, 36, 400, 850, 850 - 36})
        in.texels[static_cast<size_t>(k)] = glm::vec4(50.0f, 20.0f, 5.0f, 1.0f);
    gl::GpuWang2020Blur blur;
    for (const auto& [occlusion, glint] : {std::pair{9, 3}, std::pair{5, 7}}) {
        SCOPED_TRACE(occlusion);
        const wang2020::GlintBuffer cpu = wang2020::postprocess_glints(in, occlusion, glint);
        const wang2020::GlintBuffer gpu = blur.apply(in, occlusion, glint);
        double max_err = 0.0;
        for (size_t i = 0; i < cpu.texels.size(); ++i)
            for (int c = 0; c < 4; ++c)
                max_err = std::max(
                    max_err, static_cast<double>(std::abs(gpu.texels[i][c] - cpu.texels[i][c])) /
                                 (1e-3 + std::abs(cpu.texels[i][c])));
        EXPECT_LT(max_err, 1e-5);
        // The blur does something: the brightest glint spreads.
        EXPECT_LT(gpu.texels[400].x, 0.9f * 50.0f);
    }
    EXPECT_THROW(blur.apply(in, 4, 3), Error);
}

}  // namespace
}  // namespace glintlab
