// Curved surfaces under glints through the CPU renderer (docs/MODELS.md,
// "Curved surfaces"). A sphere about 20 pixels across turns its normal by
// ~0.16 rad per pixel, against a lobe of α 0.05: the footprint's mixture of
// lobes is wider than one. The ground truth composing each facet with the
// sphere's normal at the facet's position and the smooth lobe widened by
// the footprint's normal covariance change the image mean alike.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "glintlab/core/image.h"
#include "glintlab/render/renderer.h"
#include "glintlab/scene/scene_loader.h"

namespace glintlab {
namespace {

Scene small_sphere(const char* model, const char* curvature) {
    nlohmann::json doc = {
        {"camera", {{"eye", {0.0, 1.27, 2.72}}, {"target", {0, 0.15, 0}}, {"fov_deg", 20}}},
        {"film", {{"width", 96}, {"height", 72}}},
        {"render", {{"integrator", "direct"}, {"spp", 1}, {"seed", 1}}},
        {"materials",
         {{{"name", "m"},
           {"type", "glint"},
           {"model", model},
           {"ndf", "ggx"},
           {"roughness", 0.05},
           {"log_density", 16},
           {"curvature", curvature}}}},
        {"shapes",
         {{{"type", "sphere"}, {"center", {0, 0.15, 0}}, {"radius", 0.15}, {"material", "m"}}}},
        {"lights",
         {{{"type", "directional"}, {"direction", {0.3, 0.8, 0.6}}, {"irradiance", 2.0}},
          {{"type", "point"}, {"position", {1.0, 1.5, 0.5}}, {"intensity", 1.0}}}}};
    // Silhouette footprints hold millions of facets: one part of each.
    if (std::string(model) == "explicit")
        doc["materials"][0]["explicit"] = {{"over_budget", "subsample"}};
    return parse_scene(doc, "test:curvature");
}

double mean(const Image& img) {
    double s = 0.0;
    for (const glm::vec3& p : img.pixels) s += double(p.x + p.y + p.z) / 3.0;
    return s / double(img.pixels.size());
}

TEST(CurvatureRender, TheTruthOnACurvedFootprintIsTheWidenedLobesMean) {
    const double truth =
        mean(render_scene(small_sphere("explicit", "footprint"), RenderOptions{0, true}));
    const double truth_flat =
        mean(render_scene(small_sphere("explicit", "none"), RenderOptions{0, true}));
    const double widened =
        mean(render_scene(small_sphere("smooth", "footprint"), RenderOptions{0, true}));
    const double one_normal =
        mean(render_scene(small_sphere("smooth", "none"), RenderOptions{0, true}));
    RecordProperty("explicit_footprint", std::to_string(truth));
    RecordProperty("explicit_none", std::to_string(truth_flat));
    RecordProperty("smooth_footprint", std::to_string(widened));
    RecordProperty("smooth_none", std::to_string(one_normal));
    // The same facets (one seed) composed with the curved surface or not:
    // the truth's change is the curvature's alone, and the widened lobe
    // changes by as much (measured −3.8 % and −3.7 %; the lobes' own
    // difference from the truth, γ's cone over a narrow lobe, cancels).
    const double truth_change = truth / truth_flat - 1.0;
    const double lobe_change = widened / one_normal - 1.0;
    RecordProperty("truth_change", std::to_string(truth_change));
    RecordProperty("lobe_change", std::to_string(lobe_change));
    EXPECT_LT(truth_change, -0.02);
    EXPECT_NEAR(lobe_change, truth_change, 0.015);
}

}  // namespace
}  // namespace glintlab
