// Walks every model descriptor (glint_model_descriptor.h): each parameter is
// readable from a scene file, range-checked at both ends with the documented
// error text, present in the viewer's panel model and in `info --json`; each
// model accepts its declared light types and rejects the others with the
// error naming the model, the light and the models that can shade it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "glintlab/core/error.h"
#include "glintlab/core/json_reader.h"
#include "glintlab/export/shader_export.h"
#include "glintlab/glints/glint_panel_model.h"
#include "glintlab/glints/model_docs.h"
#include "glintlab/glints/model_list.h"
#include "glintlab/glints/registry.h"
#include "glintlab/glints/validation_suites.h"
#include "glintlab/loader/scene_loader.h"
#if GLINTLAB_WITH_GL
#include "glintlab/glints/gpu_model_hooks.h"
#include "glintlab/realtime/glint_programs.h"
#endif

namespace glintlab {
namespace {

nlohmann::json light_json(GlintLightType type) {
    switch (type) {
        case GlintLightType::Point:
            return {{"type", "point"}, {"position", {0, 2, 2}}};
        case GlintLightType::Directional:
            return {{"type", "directional"}, {"direction", {0, 1, 1}}};
        case GlintLightType::Sphere:
            return {{"type", "sphere"}, {"center", {0, 2, 2}}, {"radius", 0.1}};
        case GlintLightType::Environment:
            return {{"type", "environment"}, {"radiance", 1.0}};
    }
    return {};
}

nlohmann::json scene_json(const nlohmann::json& material, GlintLightType light) {
    nlohmann::json s;
    s["camera"] = {{"eye", {0, 0, 5}}, {"target", {0, 0, 0}}};
    s["materials"] = nlohmann::json::array({material});
    s["shapes"] = nlohmann::json::array({{{"type", "quad"}, {"material", "m"}}});
    s["lights"] = nlohmann::json::array({light_json(light)});
    return s;
}

std::string error_of(const nlohmann::json& scene) {
    try {
        parse_scene(scene, "walk.json");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

// A glint material of `m` that its check hook accepts: the shared keys are
// chosen among a few candidates without naming models (some models need
// Beckmann, some GGX; log_density 10 suits every model's limits).
nlohmann::json base_material(const GlintModelDescriptor& m) {
    for (const char* ndf : {"beckmann", "ggx"}) {
        nlohmann::json mat = {{"name", "m"}, {"type", "glint"},  {"model", m.name},
                              {"ndf", ndf},  {"roughness", 0.3}, {"log_density", 10.0}};
        if (error_of(scene_json(mat, m.lights.front())).empty()) return mat;
    }
    ADD_FAILURE() << m.name << ": no base material loads";
    return {};
}

nlohmann::json to_json(const GlintParamValue& v) {
    if (const double* x = std::get_if<double>(&v)) return *x;
    if (const int* x = std::get_if<int>(&v)) return *x;
    if (const bool* x = std::get_if<bool>(&v)) return *x;
    return std::get<std::string>(v);
}

// An in-range value different from the default.
GlintParamValue other_value(const GlintParam& p, const GlintParamValue& def) {
    switch (p.type) {
        case GlintParamType::Number: {
            const double d = std::get<double>(def);
            return (d + p.max) / 2.0 != d ? (d + p.max) / 2.0 : (d + p.min) / 2.0;
        }
        case GlintParamType::Integer: {
            const int d = std::get<int>(def);
            for (int v : p.integer_values)
                if (v != d) return v;
            return d + 1 <= p.max ? d + 1 : d - 1;
        }
        case GlintParamType::Bool:
            return !std::get<bool>(def);
        case GlintParamType::Enum:
            for (const std::string& c : p.choices)
                if (c != std::get<std::string>(def)) return c;
    }
    return def;
}

// What get() returns after reading `v` (floats keep float precision).
GlintParamValue stored(const GlintParam& p, const GlintParamValue& v) {
    if (p.single_precision) return static_cast<double>(static_cast<float>(std::get<double>(v)));
    return v;
}

const GlintModelParams& params_of(const Scene& s) {
    return s.materials[0].glint.params;
}

TEST(ModelDescriptors, ListIsCompleteAndConsistent) {
    ASSERT_FALSE(glint_models().empty());
    for (size_t i = 0; i < glint_models().size(); ++i) {
        const GlintModelDescriptor& m = glint_models()[i];
        EXPECT_EQ(static_cast<size_t>(m.id), i) << m.name;
        EXPECT_FALSE(m.citations.empty()) << m.name;
        EXPECT_FALSE(m.lights.empty()) << m.name;
        EXPECT_TRUE(m.cpu) << m.name;
        EXPECT_EQ(m.shades_light == nullptr, m.light_radiance == nullptr) << m.name;
        for (const GlintParam& p : m.params) {
            // Defaults lie in the documented range (they are get() of the
            // model's default params, so the table cannot restate them wrongly).
            EXPECT_TRUE(p.accepts(m.default_value(p))) << m.name << "/" << p.key;
            EXPECT_FALSE(p.doc.empty()) << m.name << "/" << p.key;
        }
    }
}

// The list of models (model_list.h) drives the GlintModelId enum, the
// GlintModelParams variant and the descriptors: as many of each as list
// entries, entry i being id i, its params struct the variant's alternative i
// and its descriptor the i-th, with the entry's name.
#define GLINTLAB_CHECK_PARAMS(m, M)                                                             \
    static_assert(                                                                              \
        std::is_same_v<                                                                         \
            std::variant_alternative_t<static_cast<size_t>(GlintModelId::M), GlintModelParams>, \
            M##Params>);
GLINTLAB_GLINT_MODELS(GLINTLAB_CHECK_PARAMS)
#undef GLINTLAB_CHECK_PARAMS
static_assert(std::variant_size_v<GlintModelParams> == kGlintModelCount);
// The ids keep their values (a new model is appended to the list).
static_assert(static_cast<int>(GlintModelId::Smooth) == 0 &&
              static_cast<int>(GlintModelId::Deliot2023) == 1 &&
              static_cast<int>(GlintModelId::Zirr2016) == 2 &&
              static_cast<int>(GlintModelId::Chermain2020) == 3 &&
              static_cast<int>(GlintModelId::Explicit) == 4 &&
              static_cast<int>(GlintModelId::Jakob2014) == 5 &&
              static_cast<int>(GlintModelId::Kneiphof2025) == 6 &&
              static_cast<int>(GlintModelId::Wang2020) == 7);

TEST(ModelList, DrivesTheIdsTheParamsAndTheDescriptors) {
#define GLINTLAB_LIST_ENTRY(m, M) {#m, GlintModelId::M},
    const std::pair<std::string_view, GlintModelId> list[] = {
        GLINTLAB_GLINT_MODELS(GLINTLAB_LIST_ENTRY)};
#undef GLINTLAB_LIST_ENTRY
    ASSERT_EQ(std::size(list), static_cast<size_t>(kGlintModelCount));
    ASSERT_EQ(glint_models().size(), std::size(list));
    for (size_t i = 0; i < std::size(list); ++i) {
        const GlintModelDescriptor& m = glint_models()[i];
        EXPECT_EQ(m.name, list[i].first);
        EXPECT_EQ(m.id, list[i].second) << m.name;
        EXPECT_EQ(static_cast<size_t>(m.id), i) << m.name;
        // default_params is the alternative of the model's params struct.
        EXPECT_EQ(m.default_params().index(), i) << m.name;
        GlintDesc desc;
        switch_glint_model(desc, m.id);
        EXPECT_EQ(desc.params.index(), i) << m.name;
    }
}

// `glintlab export` writes the models whose descriptors state an export, and
// only models with a GPU back end: the exporter names no model.
TEST(ModelList, ExportableModelsAreTheDescriptorsWithAnExport) {
    std::vector<std::string> with_export;
    for (const GlintModelDescriptor& m : glint_models()) {
        if (!m.shader_export) continue;
        with_export.emplace_back(m.name);
        EXPECT_TRUE(m.gpu) << m.name;
        EXPECT_FALSE(m.shader_export->glue.empty()) << m.name;
        EXPECT_EQ(m.shader_export->variant.empty(), m.shader_export->variant_glue.empty())
            << m.name;
    }
    EXPECT_EQ(exportable_models(), with_export);
}

// A descriptor names its suite; the model's folder defines its runner in the
// research library (`<model>_validation_suite()`, model_list.h), which
// validation_suites() files under that name. Every named suite has a runner there, and
// every runner but the model-less `counting`, `robustness` and `compare`
// (all models) belongs to a model, so `glintlab validate` lists exactly the
// descriptors' suites plus those three.
TEST(ModelDescriptors, EveryValidationSuiteNameHasARunner) {
    const auto& suites = validation_suites();
    std::set<std::string> named;
    for (const GlintModelDescriptor& m : glint_models()) {
        if (m.validation.name.empty()) continue;
        named.insert(m.validation.name);
        EXPECT_EQ(suites.count(m.validation.name), 1u) << m.name;
    }
    EXPECT_GE(named.size(), 7u);  // every model but smooth has a suite
    for (const auto& [name, run] : suites) {
        EXPECT_TRUE(run != nullptr) << name;
        if (name != "counting" && name != "robustness" && name != "compare") {
            EXPECT_EQ(named.count(name), 1u) << name;
        }
    }
    EXPECT_THROW(run_validation_suite("no-such-suite", 1), Error);
}

#if GLINTLAB_WITH_GL
// A descriptor's "gpu" back end is the GPU renderer's (realtime/) support,
// through the hooks the descriptor names.
TEST(ModelDescriptors, GpuBackEndMatchesTheGpuRenderer) {
    for (const GlintModelDescriptor& m : glint_models()) {
        EXPECT_EQ(m.gpu, gl::gpu_supports_model(m.id)) << m.name;
        EXPECT_EQ(m.gpu, m.gpu_hooks != nullptr) << m.name;
        if (m.gpu_hooks != nullptr) {
            EXPECT_EQ(m.gpu_hooks().model, m.id) << m.name;
        }
    }
}

// `glintlab view --gpu-option`: a bare OPTION resolves among the GPU models
// of the scene's glint materials, MODEL.OPTION names the model; an option of
// no model of the scene is an error.
TEST(ModelDescriptors, GpuOptionsResolveAgainstTheScenesModels) {
    Scene scene;
    for (GlintModelId id : {GlintModelId::Deliot2023, GlintModelId::Kneiphof2025}) {
        MaterialDesc m;
        m.type = MaterialDesc::Type::Glint;
        m.glint.model_id = id;
        scene.materials.push_back(m);
    }
    const GpuModelOptionName bare = find_scene_gpu_option(scene, "dynamic_environment");
    EXPECT_EQ(bare.model, "kneiphof2025");
    EXPECT_EQ(bare.option, "dynamic_environment");
    const GpuModelOptionName named = find_scene_gpu_option(scene, "deliot2023.noise_texture");
    EXPECT_EQ(named.model, "deliot2023");
    EXPECT_EQ(named.option, "noise_texture");
    EXPECT_THROW(find_scene_gpu_option(scene, "split_sum_environment"), Error);  // smooth's
    EXPECT_THROW(find_scene_gpu_option(scene, "kneiphof2025.noise_texture"), Error);
    EXPECT_THROW(find_scene_gpu_option(scene, "no_such_option"), Error);
}
#endif

TEST(ModelDescriptors, EveryParameterReadsBackAndIsRangeChecked) {
    for (const GlintModelDescriptor& m : glint_models()) {
        const nlohmann::json base = base_material(m);
        const GlintLightType light = m.lights.front();
        const Scene defaults = parse_scene(scene_json(base, light), "walk.json");
        for (const GlintParam& p : m.params) {
            SCOPED_TRACE(fmt::format("{}/{}", m.name, p.key));
            EXPECT_EQ(p.get(params_of(defaults)), m.default_value(p));
            // A non-default in-range value reads back.
            const GlintParamValue v = other_value(p, m.default_value(p));
            ASSERT_NE(v, m.default_value(p));
            nlohmann::json mat = base;
            mat[std::string(m.name)][p.key] = to_json(v);
            const Scene s = parse_scene(scene_json(mat, light), "walk.json");
            EXPECT_EQ(p.get(params_of(s)), stored(p, v));
            // Out of range: the error names file, JSON path, key and range.
            std::vector<nlohmann::json> bad;
            if (p.type == GlintParamType::Number) {
                // The closed bounds themselves are accepted (documented
                // decimals, compared as written); the next double outside is not.
                for (double bound : {p.min, p.max}) {
                    mat[std::string(m.name)][p.key] = bound;
                    EXPECT_EQ(error_of(scene_json(mat, light)), "") << bound;
                }
                bad = {std::nextafter(p.min, -INFINITY), std::nextafter(p.max, INFINITY),
                       p.min - 1.0, p.max + 1.0, "text"};
            } else if (p.type == GlintParamType::Integer) {
                bad = {static_cast<int>(p.min) - 1, static_cast<int>(p.max) + 1, 1.5};
                for (int x = static_cast<int>(p.min); x <= static_cast<int>(p.max); ++x)
                    if (!p.accepts(x)) bad.push_back(x);
            } else if (p.type == GlintParamType::Bool) {
                bad = {3, "yes"};
            } else {
                bad = {"bogus", 1};
            }
            for (const nlohmann::json& b : bad) {
                mat[std::string(m.name)][p.key] = b;
                const std::string e = error_of(scene_json(mat, light));
                EXPECT_NE(e.find("walk.json"), std::string::npos) << b << ": " << e;
                EXPECT_NE(e.find(fmt::format("/materials/0/{}/{}", m.name, p.key)),
                          std::string::npos)
                    << b << ": " << e;
                if (p.type != GlintParamType::Bool && b.is_number()) {
                    EXPECT_NE(e.find(p.range_text()), std::string::npos) << b << ": " << e;
                }
            }
        }
    }
}

TEST(ModelDescriptors, EveryParameterIsInThePanelModelAndInfoJson) {
    for (const GlintModelDescriptor& m : glint_models()) {
        GlintDesc desc;
        desc.model_id = m.id;
        desc.params = m.default_params();
        std::vector<GlintPanelWidget> widgets = glint_panel_model(desc);
        const nlohmann::json j = glint_model_to_json(m);
        EXPECT_EQ(j.at("name"), m.name);
        ASSERT_EQ(widgets.size(), m.params.size()) << m.name;
        ASSERT_EQ(j.at("parameters").size(), m.params.size()) << m.name;
        for (size_t i = 0; i < m.params.size(); ++i) {
            const GlintParam& p = m.params[i];
            SCOPED_TRACE(fmt::format("{}/{}", m.name, p.key));
            const nlohmann::json& q = j.at("parameters")[i];
            EXPECT_EQ(q.at("key"), p.key);
            EXPECT_EQ(q.at("type"), glint_param_type_name(p.type));
            EXPECT_EQ(q.at("range"), p.range_text());
            EXPECT_EQ(q.at("default"), to_json(m.default_value(p)));
            GlintPanelWidget& w = widgets[i];
            EXPECT_EQ(w.key, p.key);
            EXPECT_EQ(w.type, p.type);
            EXPECT_EQ(w.value, m.default_value(p));
            // The setter writes through to the material's params.
            const GlintParamValue v = other_value(p, m.default_value(p));
            w.set(v);
            EXPECT_EQ(p.get(desc.params), stored(p, v));
            // Out-of-range numbers are clamped into the range.
            if (p.type == GlintParamType::Number) {
                w.set(p.max * 2.0 + 1.0);
                EXPECT_TRUE(p.accepts(p.get(desc.params)));
                EXPECT_EQ(p.get(desc.params), stored(p, p.max));
            }
        }
    }
}

// Which keys take a texture comes from the descriptor's flags: `info` and
// its JSON list them, with the reason for those a model refuses.
TEST(ModelDescriptors, TextureInputsFollowTheDescriptorsFlags) {
    for (const GlintModelDescriptor& m : glint_models()) {
        SCOPED_TRACE(m.name);
        const GlintTextureInputs t = glint_texture_inputs(m);
        EXPECT_EQ(t.keys.size() + t.refused.size(), 5u);
        const auto has = [&](const char* key) {
            return std::find(t.keys.begin(), t.keys.end(), key) != t.keys.end();
        };
        EXPECT_EQ(has("log_density"), m.textured_density);
        EXPECT_EQ(has("roughness"), m.textured_roughness);
        EXPECT_TRUE(has("color") && has("normal_map"));
        EXPECT_EQ(t.refused.empty(), t.reason.empty());
        const nlohmann::json j = glint_model_to_json(m);
        EXPECT_EQ(j.at("texture_inputs"), nlohmann::json(t.keys));
        EXPECT_EQ(j.contains("texture_refused"), !t.refused.empty());
    }
    const GlintTextureInputs wang = glint_texture_inputs(*find_glint_model("wang2020"));
    EXPECT_EQ(wang.keys, std::vector<std::string>({"color", "normal_map"}));
    EXPECT_NE(wang.reason.find("quadtree tables"), std::string::npos) << wang.reason;
    EXPECT_TRUE(glint_texture_inputs(*find_glint_model("deliot2023")).refused.empty());
}

// Colour lists outside the table: read from the scene file, exposed to the
// panel, rejected with more entries than allowed.
TEST(ModelDescriptors, ColourListsReadAndAppearInThePanel) {
    for (const GlintModelDescriptor& m : glint_models()) {
        for (const GlintExtraKey& k : m.extra_keys) {
            if (k.max_colours <= 0) continue;
            SCOPED_TRACE(fmt::format("{}/{}", m.name, k.key));
            nlohmann::json mat = base_material(m);
            mat[std::string(m.name)][k.key] = {{1.0, 0.0, 0.0}, {0.0, 0.5, 1.0}};
            Scene s = parse_scene(scene_json(mat, m.lights.front()), "walk.json");
            GlintDesc& desc = s.materials[0].glint;
            const std::vector<GlintPanelColours> lists = glint_panel_colours(desc);
            ASSERT_EQ(lists.size(), 1u);
            EXPECT_EQ(lists[0].key, k.key);
            EXPECT_EQ(*lists[0].count, 2);
            EXPECT_EQ(lists[0].colours[1], glm::vec3(0.0f, 0.5f, 1.0f));
            lists[0].colours[0] = glm::vec3(0.25f);  // the panel writes through
            EXPECT_EQ(k.colours(desc.params)[0], glm::vec3(0.25f));
            mat[std::string(m.name)][k.key] =
                nlohmann::json::array_t(static_cast<size_t>(k.max_colours) + 1, {0.5, 0.5, 0.5});
            EXPECT_NE(error_of(scene_json(mat, m.lights.front())).find(k.key), std::string::npos);
        }
    }
}

TEST(ModelDescriptors, DeclaredLightsAreAcceptedOthersRejectedNamingWhoCan) {
    for (const GlintModelDescriptor& m : glint_models()) {
        const nlohmann::json mat = base_material(m);
        for (GlintLightType t : kGlintLightTypes) {
            SCOPED_TRACE(fmt::format("{} under {}", m.name, glint_light_type_name(t)));
            const std::string e = error_of(scene_json(mat, t));
            if (m.shades(t)) {
                EXPECT_EQ(e, "");
                continue;
            }
            EXPECT_NE(e.find("walk.json: /lights/0"), std::string::npos) << e;
            EXPECT_NE(e.find(fmt::format("type \"{}\"", glint_light_type_name(t))),
                      std::string::npos)
                << e;
            EXPECT_NE(e.find(fmt::format("glint model \"{}\"", m.name)), std::string::npos) << e;
            EXPECT_NE(e.find("/materials/0"), std::string::npos) << e;
            const std::string who = glint_models_shading(t);
            EXPECT_FALSE(who.empty());
            EXPECT_NE(e.find("models that can: " + who), std::string::npos) << e;
        }
    }
}

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    std::stringstream b;
    b << in.rdbuf();
    return b.str();
}

// docs/MODELS.md and docs/SCENE_FORMAT.md hold sections generated from the
// descriptors; regenerate with
//   build/release/glintlab info --update-docs docs/MODELS.md docs/SCENE_FORMAT.md
// The viewer's model switcher (switch_glint_model): a material coming from
// any other model, with shared values outside what the target accepts
// (either NDF, roughness 0.001 and 1, ln density up to 60, a diffuse base under a
// dielectric coat), becomes a material that the scene reader accepts for
// the target model, with the model's default parameters.
TEST(ModelDescriptors, SwitchedMaterialsAreAcceptedByTheTargetModel) {
    for (const GlintModelDescriptor& m : glint_models()) {
        SCOPED_TRACE(std::string(m.name));
        for (NdfType ndf : {NdfType::Beckmann, NdfType::GGX})
            for (float alpha : {0.001f, 1.0f})
                for (float log_density : {0.0f, 10.0f, 25.0f, 60.0f})
                    for (float base : {0.0f, 0.5f}) {
                        GlintDesc g;
                        g.ndf = ndf;
                        g.alpha_x = g.alpha_y = alpha;
                        g.log_density = log_density;
                        g.base_albedo = glm::vec3(base);
                        switch_glint_model(g, m.id);
                        EXPECT_EQ(g.model_id, m.id);
                        EXPECT_EQ(g.params.index(), m.default_params().index());
                        const nlohmann::json mat = {
                            {"name", "m"},
                            {"type", "glint"},
                            {"model", m.name},
                            {"ndf", g.ndf == NdfType::GGX ? "ggx" : "beckmann"},
                            {"roughness", {g.alpha_x, g.alpha_y}},
                            {"log_density", g.log_density},
                            {"fresnel", {{"type", "dielectric"}, {"eta", 1.5}}},
                            {"base_albedo", g.base_albedo.x}};
                        const std::string error = error_of(scene_json(mat, m.lights.front()));
                        EXPECT_EQ(error, "")
                            << "ndf " << static_cast<int>(ndf) << " alpha " << alpha
                            << " ln density " << log_density << " base " << base;
                    }
    }
}

TEST(ModelDocs, GeneratedDocSectionsAreCurrent) {
    const std::string root = GLINTLAB_SOURCE_DIR;
    const std::pair<const char*, std::vector<const char*>> files[] = {
        {"docs/MODELS.md", {"models", "parameters", "citations"}},
        {"docs/SCENE_FORMAT.md", {"scene-format"}},
    };
    for (const auto& [file, sections] : files) {
        const std::string text = read_text(root + "/" + file);
        ASSERT_FALSE(text.empty()) << file;
        for (const char* s : sections)
            EXPECT_NE(
                text.find(fmt::format("<!-- BEGIN generated: glintlab info --markdown {} -->", s)),
                std::string::npos)
                << file << " lacks section " << s;
        EXPECT_EQ(update_generated_sections(text, file), text)
            << file << " is out of date: run `glintlab info --update-docs " << file << "`";
    }
    // Every model appears in the generated summary and parameter tables.
    for (const GlintModelDescriptor& m : glint_models()) {
        EXPECT_NE(model_doc_markdown("models").find(fmt::format("| `{}` |", m.name)),
                  std::string::npos);
        EXPECT_NE(model_doc_markdown("parameters").find(fmt::format("#### `{}`", m.name)),
                  std::string::npos);
    }
}

TEST(ModelDocs, UpdateReplacesOnlyTheGeneratedSections) {
    const std::string stale =
        "intro\n<!-- BEGIN generated: glintlab info --markdown scene-format -->\nold row\n"
        "<!-- END generated -->\noutro\n";
    const std::string fresh = update_generated_sections(stale, "x.md");
    EXPECT_EQ(fresh, "intro\n<!-- BEGIN generated: glintlab info --markdown scene-format -->\n" +
                         model_doc_markdown("scene-format") + "<!-- END generated -->\noutro\n");
    EXPECT_THROW(update_generated_sections(
                     "<!-- BEGIN generated: glintlab info --markdown nope -->\n<!-- END "
                     "generated -->\n",
                     "x.md"),
                 Error);
    EXPECT_THROW(update_generated_sections(
                     "<!-- BEGIN generated: glintlab info --markdown models -->\nno end\n", "x.md"),
                 Error);
}

}  // namespace
}  // namespace glintlab
