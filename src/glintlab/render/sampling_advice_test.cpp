#include "glintlab/render/sampling_advice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

namespace glintlab {
namespace {

Scene scene_with(GlintModelId model, bool environment, int spp) {
    Scene s;
    MaterialDesc m;
    m.name = "flakes";
    m.type = MaterialDesc::Type::Glint;
    m.glint.model_id = model;
    s.materials.push_back(m);
    // Built in place: a temporary Light variant makes GCC 12 with ASan warn
    // falsely -Wmaybe-uninitialized about EnvironmentLight's path.
    s.lights.emplace_back(std::in_place_type<PointLight>);
    if (environment) s.lights.emplace_back(std::in_place_type<EnvironmentLight>);
    s.render.spp = spp;
    return s;
}

// The threshold is where the measured 1.8/sqrt(spp) law crosses 25 %.
TEST(SamplingAdvice, Jakob2014UnderAnEnvironmentBelowTheThreshold) {
    const auto advice = sampling_advice(scene_with(GlintModelId::Jakob2014, true, 8));
    ASSERT_EQ(advice.size(), 1u);
    EXPECT_NE(advice[0].find("\"flakes\" (jakob2014)"), std::string::npos) << advice[0];
    EXPECT_NE(advice[0].find("at 8 spp"), std::string::npos) << advice[0];
    EXPECT_NE(advice[0].find("64 %"), std::string::npos) << advice[0];  // 1.8 / sqrt(8)
    EXPECT_NEAR(kJakob2014EnvironmentErrorAt1Spp / std::sqrt(kJakob2014EnvironmentMinSpp), 0.25,
                0.005);
}

TEST(SamplingAdvice, SilentWhereTheEstimatorConverges) {
    EXPECT_TRUE(sampling_advice(scene_with(GlintModelId::Jakob2014, true, 64)).empty());
    EXPECT_TRUE(sampling_advice(scene_with(GlintModelId::Jakob2014, false, 2)).empty());
    EXPECT_TRUE(sampling_advice(scene_with(GlintModelId::Explicit, true, 2)).empty());
}

}  // namespace
}  // namespace glintlab
