// Scene integration of wang2020: the parameter block is read strictly and the
// material constraints name the key and range.
#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "glintlab/core/error.h"
#include "glintlab/core/image.h"
#include "glintlab/glints/model_params.h"
#include "glintlab/glints/registry.h"
#include "glintlab/glints/wang2020/wang2020_model.h"
#include "glintlab/glints/wang2020/wang2020_quadtree.h"
#include "glintlab/glints/wang2020/wang2020_shading.h"
#include "glintlab/loader/scene_loader.h"
#include "glintlab/render/renderer.h"
#include "glintlab/scene/environment.h"

namespace glintlab {
namespace {

nlohmann::json scene_with(const nlohmann::json& material) {
    return {{"film", {{"width", 8}, {"height", 8}}},
            {"camera", {{"eye", {0, 0, 3}}, {"target", {0, 0, 0}}, {"fov_deg", 45}}},
            {"materials", {material}},
            {"shapes", {{{"name", "s"}, {"type", "sphere"}, {"radius", 1.0}, {"material", "g"}}}},
            {"lights", {{{"type", "point"}, {"position", {1, 1, 2}}, {"intensity", 1.0}}}}};
}

nlohmann::json glint_material(nlohmann::json block) {
    return {
        {"name", "g"},      {"type", "glint"},   {"model", "wang2020"},         {"ndf", "beckmann"},
        {"roughness", 0.4}, {"log_density", 12}, {"wang2020", std::move(block)}};
}

std::string error_of(const nlohmann::json& doc) {
    try {
        parse_scene(doc, "test.json");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(Wang2020Model, ReadsItsBlockAndRejectsBadInput) {
    const Scene ok =
        parse_scene(scene_with(glint_material({{"gamma_deg", 3}, {"depth", 9}})), "test.json");
    const auto& p = std::get<Wang2020Params>(ok.materials[0].glint.params);
    EXPECT_DOUBLE_EQ(p.gamma_deg, 3.0);
    EXPECT_EQ(p.depth, 9);
    EXPECT_EQ(p.dpf_theta, 90);         // Table 2 default
    EXPECT_TRUE(p.micro_per_particle);  // defaults, not as published
    EXPECT_TRUE(p.prefilter_mis);
    const Scene pub = parse_scene(
        scene_with(glint_material({{"micro", "as_published"}, {"prefilter", "as_published"}})),
        "test.json");
    EXPECT_FALSE(std::get<Wang2020Params>(pub.materials[0].glint.params).micro_per_particle);
    EXPECT_FALSE(std::get<Wang2020Params>(pub.materials[0].glint.params).prefilter_mis);
    EXPECT_NE(error_of(scene_with(glint_material({{"micro", "per_pixel"}}))).find("micro"),
              std::string::npos);
    EXPECT_NE(error_of(scene_with(glint_material({{"prefilter", 3}}))).find("prefilter"),
              std::string::npos);
    ASSERT_NE(find_glint_model("wang2020"), nullptr);
    EXPECT_FALSE(find_glint_model("wang2020")->shades(GlintLightType::Sphere));

    EXPECT_NE(error_of(scene_with(glint_material({{"gamma_deg", 0.5}}))).find("gamma_deg"),
              std::string::npos);
    EXPECT_NE(error_of(scene_with(glint_material({{"depth", 20}}))).find("depth"),
              std::string::npos);
    EXPECT_NE(error_of(scene_with(glint_material({{"unknown_key", 1}}))).find("unknown_key"),
              std::string::npos);
    nlohmann::json ggx = glint_material(nlohmann::json::object());
    ggx["ndf"] = "ggx";
    EXPECT_NE(error_of(scene_with(ggx)).find("Beckmann"), std::string::npos);
    nlohmann::json dense = glint_material(nlohmann::json::object());
    dense["log_density"] = 25;
    EXPECT_NE(error_of(scene_with(dense)).find("log_density"), std::string::npos);
}

// Regression: `glintlab validate robustness --models wang2020` never finished:
// its roughness-0.02 material had depth 1 at log_density 19.4, and the micro
// and meso scales enumerate the particles of each quadtree leaf the
// footprint cuts (N / 4^depth = 6.7e7 there). The scene reader bounds the
// particles per leaf (4096) and the quadtree's nodes (1.25e8), naming `depth`,
// the density and the allowed depths.
TEST(Wang2020Model, DepthIsBoundedByParticlesPerLeafAndNodes) {
    nlohmann::json mat = glint_material({{"depth", 7}});
    mat["log_density"] = 19.4;
    const std::string shallow = error_of(scene_with(mat));
    EXPECT_NE(shallow.find("/materials/0/wang2020/depth"), std::string::npos) << shallow;
    EXPECT_NE(shallow.find("depth 7 at log_density 19.4"), std::string::npos) << shallow;
    EXPECT_NE(shallow.find("particles per quadtree leaf"), std::string::npos) << shallow;
    EXPECT_NE(shallow.find("use depth 8 or more"), std::string::npos) << shallow;
    EXPECT_NE(shallow.find("depth 8..13"), std::string::npos) << shallow;
    mat["wang2020"]["depth"] = 8;  // the smallest allowed: N / 4^8 <= 4096
    EXPECT_EQ(error_of(scene_with(mat)), "");
    mat["wang2020"]["depth"] = 13;  // the largest within the node bound
    EXPECT_EQ(error_of(scene_with(mat)), "");
    mat["wang2020"]["depth"] = 14;
    const std::string deep = error_of(scene_with(mat));
    EXPECT_NE(deep.find("/materials/0/wang2020/depth"), std::string::npos) << deep;
    EXPECT_NE(deep.find("use depth 13 or less"), std::string::npos) << deep;
    // The default depth (11, §6) passes at every density of the range.
    for (double ld : {0.0, 10.0, 19.4}) {
        nlohmann::json d = glint_material(nlohmann::json::object());
        d["log_density"] = ld;
        EXPECT_EQ(error_of(scene_with(d)), "") << ld;
    }
    // At low density every depth passes (depth 1 at ln N 9: 8103 / 4 particles).
    mat["log_density"] = 9;
    mat["wang2020"]["depth"] = 1;
    EXPECT_EQ(error_of(scene_with(mat)), "");
    // The bounds themselves, and the constructor's own check (tables built
    // outside the scene reader).
    EXPECT_EQ(wang2020::min_quadtree_depth(1), 1);
    EXPECT_EQ(wang2020::max_quadtree_depth(1), 16);
    EXPECT_EQ(wang2020::min_quadtree_depth(0x0FFFFFFFu), 8);
    EXPECT_EQ(wang2020::max_quadtree_depth(0x0FFFFFFFu), 13);
    EXPECT_THROW(wang2020::ParticleQuadtree(0x0FFFFFFFu, 7, 1), Error);
    // The viewer's model switch fits the depth into the allowed range.
    GlintDesc g;
    g.log_density = 19.4f;
    switch_glint_model(g, GlintModelId::Wang2020);
    std::get<Wang2020Params>(g.params).depth = 2;
    glint_model(GlintModelId::Wang2020).fit_material(g);
    EXPECT_EQ(std::get<Wang2020Params>(g.params).depth, 8);
}

// The table cache is bounded: the seed is part of its key, and a sweep over
// seeds (compare's realizations) used to keep every seed's tables until the
// process ran out of memory (`validate compare`: 24 GB). A material used
// again while among the 4 most recent ones is a cache hit (the same tables);
// one that 4 others have displaced is freed once no render holds it.
TEST(Wang2020Model, TableCacheKeepsOnlyRecentMaterials) {
    GlintDesc g;
    g.log_density = 9.0f;
    switch_glint_model(g, GlintModelId::Wang2020);
    auto with_seed = [&](uint32_t seed) {
        GlintDesc d = g;
        d.seed = seed;
        return wang2020_model_for(d, nullptr);
    };
    std::weak_ptr<const wang2020::Wang2020Model> first = with_seed(1001);
    ASSERT_FALSE(first.expired());  // the cache holds it
    with_seed(1002);
    EXPECT_EQ(with_seed(1001).get(), first.lock().get());  // a hit, not a rebuild
    {
        const auto held = with_seed(1001);  // a render in progress keeps its tables
        for (uint32_t s = 2000; s < 2010; ++s) with_seed(s);
        EXPECT_FALSE(first.expired());
        EXPECT_EQ(held.get(), first.lock().get());
    }
    EXPECT_TRUE(first.expired()) << "10 later seeds must have evicted the first";
}

// The tables never depend on the seed (only the quadtree does): another
// seed of a cached material shares its DPF and prefiltered tables, and
// shades exactly as a model built from scratch with that seed. Without the
// sharing every realization of a compare row rebuilt the tables.
TEST(Wang2020Model, SeedsOfOneMaterialShareItsTables) {
    Image sky(16, 8, glm::vec3(0.3f, 0.4f, 0.6f));
    sky.at(5, 2) = glm::vec3(400.0f);  // a small sun: MIS sampling matters
    const auto env = std::make_shared<const EnvironmentMap>(sky, 1.0f, 0.0f);
    GlintDesc g;
    g.log_density = 9.0f;
    switch_glint_model(g, GlintModelId::Wang2020);
    auto& p = std::get<Wang2020Params>(g.params);
    p.dpf_theta = 12, p.dpf_phi = 24, p.prefilter_samples = 8;
    auto model = [&](uint32_t seed, float alpha) {
        GlintDesc d = g;
        d.seed = seed, d.alpha_x = d.alpha_y = alpha;
        return wang2020_model_for(d, env);
    };
    const auto a = model(3001, 0.3f);
    const auto b = model(3002, 0.3f);
    ASSERT_NE(a->prefiltered(), nullptr);
    EXPECT_EQ(a->prefiltered(), b->prefiltered());
    EXPECT_EQ(&a->dpf(), &b->dpf());
    EXPECT_EQ(b->material().seed, 3002u);
    // Displace every model of this material (4 others), then build seed
    // 3002 again from scratch.
    for (float alpha : {0.31f, 0.32f, 0.33f, 0.34f}) model(3001, alpha);
    const auto fresh = model(3002, 0.3f);
    ASSERT_NE(fresh->prefiltered(), b->prefiltered()) << "expected a rebuild";
    wang2020::UvBox box{glm::dvec2(0.40), glm::dvec2(0.41), glm::dvec2(0.405)};
    int differs_from_a = 0;
    for (int k = 0; k < 64; ++k) {
        const double t = 0.1 * k;
        const glm::dvec3 n = glm::normalize(glm::dvec3(std::sin(t), 0.3 * std::cos(t), 1.0));
        const glm::dvec3 o = glm::normalize(glm::dvec3(0.2, std::cos(0.7 * t), 0.8));
        box.lo = glm::dvec2(0.01 * k, 0.3), box.hi = box.lo + glm::dvec2(0.03);
        box.centre = 0.5 * (box.lo + box.hi);
        const glm::dvec3 lb = b->environment_radiance(box, n, o);
        const glm::dvec3 lf = fresh->environment_radiance(box, n, o);
        EXPECT_EQ(lb, lf) << k;
        differs_from_a += a->environment_radiance(box, n, o) != lb;
    }
    EXPECT_GT(differs_from_a, 0) << "the seeds' particles must differ";
}

// Four materials lit by an environment and by another light: a light other
// than the environment is served by the material's environment model, so
// the cache holds four models and alternating calls are hits. With one
// entry per (material, map or none) the eight entries thrashed the 4-model
// cache: `validate robustness` rebuilt a quadtree per evaluation.
TEST(Wang2020Model, OtherLightsShareTheEnvironmentModel) {
    const auto env =
        std::make_shared<const EnvironmentMap>(Image(16, 8, glm::vec3(0.5f)), 1.0f, 0.0f);
    GlintDesc g;
    g.log_density = 9.0f;
    switch_glint_model(g, GlintModelId::Wang2020);
    auto& p = std::get<Wang2020Params>(g.params);
    p.dpf_theta = 8, p.dpf_phi = 16, p.prefilter_samples = 1;
    std::vector<GlintDesc> materials;
    for (const float alpha : {0.2f, 0.4f, 0.6f, 0.8f}) {
        GlintDesc d = g;
        d.alpha_x = d.alpha_y = alpha;
        materials.push_back(d);
    }
    std::vector<const wang2020::Wang2020Model*> first;
    for (const GlintDesc& d : materials) first.push_back(wang2020_model_for(d, env).get());
    for (int round = 0; round < 3; ++round)
        for (size_t i = 0; i < materials.size(); ++i) {
            EXPECT_EQ(wang2020_model_for(materials[i], nullptr).get(), first[i]) << i;
            EXPECT_EQ(wang2020_model_for(materials[i], env).get(), first[i]) << i;
        }
}

// The §4.4 blurs in renders: with directional occlusion off (visibility 1,
// δ = 1) and "glint_blur": "as_published" the pass is G3 * rgb, a normalised
// kernel, so the image mean is unchanged while the sphere stays clear of the
// borders (clamped edges are the only place a normalised blur moves energy),
// and neighbouring pixels differ less (the 3-tap Gaussian removes part of
// the pixel-scale variance). With "glint_blur": "none" the pass is
// rgb · δ = rgb: the image is the unblurred one (up to float rounding: the
// deferred term is averaged and added apart).
TEST(Wang2020Model, RenderBlursTheGlintLayerAndKeepsItsEnergy) {
    nlohmann::json block = {{"dpf_theta", 12},
                            {"dpf_phi", 24},
                            {"prefilter_samples", 16},
                            {"directional_occlusion", false},
                            {"glint_blur", "as_published"}};
    nlohmann::json doc = scene_with(glint_material(block));
    doc["film"] = {{"width", 40}, {"height", 40}};
    doc["camera"]["fov_deg"] = 60;
    doc["lights"] = {{{"type", "environment"}, {"radiance", {0.5, 0.7, 1.0}}}};
    RenderOptions opt;
    opt.quiet = true;
    const Image blurred = render_scene(parse_scene(doc, "blur.json"), opt);
    doc["materials"][0]["wang2020"]["blur"] = false;
    const Image sharp = render_scene(parse_scene(doc, "sharp.json"), opt);
    double mean_b = 0.0, mean_s = 0.0, tv_b = 0.0, tv_s = 0.0;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) {
            mean_b += blurred.at(x, y).z, mean_s += sharp.at(x, y).z;
            if (x > 0) {
                tv_b += std::abs(blurred.at(x, y).z - blurred.at(x - 1, y).z);
                tv_s += std::abs(sharp.at(x, y).z - sharp.at(x - 1, y).z);
            }
        }
    ASSERT_GT(mean_s, 0.0);
    EXPECT_NEAR(mean_b / mean_s, 1.0, 1e-4);
    EXPECT_LT(tv_b, 0.9 * tv_s) << tv_b << " vs " << tv_s;
    EXPECT_NE(error_of(scene_with(glint_material({{"blur", 3}}))).find("blur"), std::string::npos);
    EXPECT_NE(error_of(scene_with(glint_material({{"glint_blur", "gaussian"}}))).find("glint_blur"),
              std::string::npos);
    doc["materials"][0]["wang2020"]["blur"] = true;
    doc["materials"][0]["wang2020"]["glint_blur"] = "none";
    const Image occlusion_only = render_scene(parse_scene(doc, "occlusion_only.json"), opt);
    for (size_t i = 0; i < sharp.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(occlusion_only.pixels[i][c], sharp.pixels[i][c],
                        1e-5f * (1.0f + sharp.pixels[i][c]))
                << i;
}

// One §4.4 post-process runs per image: two wang2020 materials of a scene
// whose "glint_blur" resolve to different kernels are refused with both
// names; "auto" (default) is the 3-tap blur with one sample per pixel only.
TEST(Wang2020Model, MaterialsMustAgreeOnTheGlintBlur) {
    nlohmann::json doc = scene_with(glint_material({{"dpf_theta", 12}, {"dpf_phi", 24}}));
    nlohmann::json second = doc["materials"][0];
    second["name"] = "second_glitter";
    second["wang2020"]["glint_blur"] = "as_published";
    doc["materials"].push_back(second);
    nlohmann::json shape = doc["shapes"][0];
    shape["name"] = "s2";
    shape["material"] = "second_glitter";
    doc["shapes"].push_back(shape);
    const Scene scene = parse_scene(doc, "two.json");
    EXPECT_EQ(wang2020_glint_blur_taps(scene, true), 3);  // auto = as_published here
    try {
        wang2020_glint_blur_taps(scene, false);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("glint_blur"), std::string::npos) << what;
        EXPECT_NE(what.find("second_glitter"), std::string::npos) << what;
    }
    // Agreeing materials, and "blur": false on the odd one, are fine.
    doc["materials"][1]["wang2020"]["blur"] = false;
    EXPECT_EQ(wang2020_glint_blur_taps(parse_scene(doc, "two_ok.json"), false), 1);
    EXPECT_EQ(wang2020_glint_blur_taps(parse_scene(doc, "two_ok.json"), true), 3);
    doc["materials"][0]["wang2020"]["glint_blur"] = "none";
    EXPECT_EQ(wang2020_glint_blur_taps(parse_scene(doc, "one_none.json"), true), 1);
    doc["materials"][0]["wang2020"]["glint_blur"] = "as_published";
    EXPECT_EQ(wang2020_glint_blur_taps(parse_scene(doc, "one_published.json"), false), 3);
}

// Regression: roughness 0.02, the documented minimum, loaded (0.02f passed the
// loader's float check) and then failed at render time without file or path
// ("roughness 0.0199999996 outside [0.02, 1]"): the float is 4e-10 below the
// table's first entry. The documented bound is accepted end to end.
TEST(Wang2020Model, RoughnessAtTheDocumentedMinimumRenders) {
    nlohmann::json mat =
        glint_material({{"dpf_theta", 4}, {"dpf_phi", 8}, {"prefilter_samples", 1}, {"depth", 4}});
    mat["roughness"] = 0.02;
    nlohmann::json doc = scene_with(mat);
    doc["film"] = {{"width", 4}, {"height", 4}};
    RenderOptions opt;
    opt.quiet = true;
    const Image img = render_scene(parse_scene(doc, "min.json"), opt);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) EXPECT_TRUE(std::isfinite(img.at(x, y).x));
    mat["roughness"] = 0.0199;
    EXPECT_NE(error_of(scene_with(mat)).find("[0.02, 1]"), std::string::npos);
}

}  // namespace
}  // namespace glintlab
