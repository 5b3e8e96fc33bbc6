// A glint model's descriptor: everything the front ends need to know about a
// model, stated once in the model's own folder (<model>/<model>_descriptor.cpp)
// and listed in glints/model_list.cpp. The scene reader, `glintlab info`
// (text, --json, --markdown), `glintlab validate`, the viewer's model panel
// and the generated sections of docs/MODELS.md and docs/SCENE_FORMAT.md all
// loop over descriptors and name no model (docs/ADDING_A_MODEL.md).
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "glintlab/glints/glint_desc.h"

namespace glintlab {

class JsonObject;
struct GlintExportContext;
struct GlintLightingContext;
struct GpuModelHooks;
struct Scene;

// The paper a model implements (or, for `smooth` and `explicit`, the papers
// whose formulation it follows). `key` is the number the code's comments use
// (000..004, docs/MODELS.md), empty for papers outside that set.
struct GlintCitation {
    std::string key;
    std::string authors;
    int year = 0;
    std::string venue;
    std::string title;
};

enum class GlintParamType { Number, Integer, Bool, Enum };
const char* glint_param_type_name(GlintParamType type);  // "number", "integer", "bool", "enum"

// A parameter's value: Number → double, Integer → int, Bool → bool,
// Enum → the choice's name.
using GlintParamValue = std::variant<double, int, bool, std::string>;

// How a viewer edits a number: linearly, on a log scale, or by decades
// (10^k, integer k: for values whose every change costs a prefilter).
enum class GlintParamUi { Linear, Log, Decades };

// One row of a model's parameter table: the key of the model's JSON block,
// its type, range, unit and doc, and get/set on the GlintModelParams
// variant (the alternative of the model's params struct). The default is
// not restated: it is get() of the model's default-constructed params.
struct GlintParam {
    std::string key;
    GlintParamType type = GlintParamType::Number;
    // Number and Integer: the range; an open end excludes its bound itself
    // and only it ("(1, 4]").
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool min_open = false, max_open = false;
    // Number stored as float: values are range-checked as written (double),
    // and an open end also rejects values that round onto it in float.
    bool single_precision = false;
    std::vector<int> integer_values;   // Integer: if not empty, the only values allowed
    std::vector<std::string> choices;  // Enum: the allowed names
    std::string unit;                  // "" when dimensionless
    std::string doc;                   // one line
    GlintParamUi ui = GlintParamUi::Linear;
    std::function<GlintParamValue(const GlintModelParams&)> get;
    std::function<void(GlintModelParams&, const GlintParamValue&)> set;

    // "[0.5, 8]", "(1, 4]", ">= 0", "4 or 8", "kneiphof2025, wang2020_style", "true or false".
    std::string range_text() const;
    // Whether a value of this parameter's type lies in its range (and
    // choices); Number values are the JSON doubles.
    bool accepts(const GlintParamValue& value) const;
};

// Text for a value of any parameter ("0.025", "8", "true", "split_sum").
std::string glint_param_value_text(const GlintParamValue& value);

// A key of the model's block that the table does not cover (read by the
// model's check hook); documented with its descriptor. A list of RGB
// colours may expose its storage for the viewer's panel.
struct GlintExtraKey {
    std::string key;
    std::string doc;
    int max_colours = 0;  // > 0: an RGB colour list of up to this many entries
    std::function<int&(GlintModelParams&)> colour_count;
    std::function<glm::vec3*(GlintModelParams&)> colours;
};

// A model's validation suite: `glintlab validate NAME`. Only the name: the
// suites are research code (the glintlab_research library). The model's
// folder defines its runner there (`<model>_validation_suite()`, beside
// validate_<model>.cpp; validation_suites.h), so the runtime library does not
// depend on them.
struct GlintValidationSuite {
    std::string name;
};

// `glintlab export` of a model with a GPU back end (export/shader_export.h,
// docs/INTEGRATION.md): the sources the exporter flattens and the model's
// own part of the manifest, stated in the model's descriptor.
struct GlintModelExport {
    // The export's glue (an embedded .glsl path): the renderer's glue, or one
    // written for the export (wang2020 reads its tables from textures).
    std::string glue;
    // An option variant exported beside the default program ("": none): its
    // name (the file suffix) and glue (deliot2023's noise texture, 000 §6.3).
    std::string variant;
    std::string variant_glue;
    std::vector<std::string> compute;  // per-environment compute passes (embedded paths)
    // Flags the export defines (`#define NAME 1`) ahead of the glue. E.g.
    // GLINTLAB_GLINT_VIEW_DIFFERENTIALS: the glue reads the pixel's view
    // differentials (g_glint_view; chermain2020's geometric glint
    // anti-aliasing), which the exported main() computes and a host with its
    // own fragment stage passes (glint_set_view_derivatives).
    std::vector<std::string> defines;
    // Optional (model_export.h), defined beside the model
    // (<model>/<model>_export.cpp) and named with GLINTLAB_EXPORT_HOOK: the
    // exported material's resources (textures and the uniforms that go with
    // them) and the uniforms the host derives from its parameters.
    void (*material)(GlintExportContext& ctx) = nullptr;
};

struct GlintModelDescriptor {
    GlintModelId id = GlintModelId::Smooth;
    std::string_view name;
    std::string description;  // one line
    std::vector<GlintCitation> citations;
    std::vector<GlintLightType> lights;  // light types the model can shade
    bool cpu = true;                     // back ends
    bool gpu = false;
    // The GPU back end's hooks (gpu_model_hooks.h), defined beside the model
    // (<model>/<model>_gpu*.cpp) and set with set_gpu_hooks(); null for a
    // CPU-only model and in a build without OpenGL, where `gpu` still says
    // that the model has a GPU back end.
    const GpuModelHooks& (*gpu_hooks)() = nullptr;
    GlintModelParams (*default_params)() = nullptr;
    std::vector<GlintParam> params;
    std::vector<GlintExtraKey> extra_keys;
    // Optional: cross-parameter checks and keys outside the table, called
    // after the table is read (desc.params holds its values); errors name
    // the file and JSON path (JsonObject::error).
    void (*check)(JsonObject& block, GlintDesc& desc) = nullptr;
    // Optional: makes a material that is switched to this model (the viewer's
    // model switcher, switch_glint_model) one the model accepts, e.g. the NDF
    // and roughness its check requires. The scene reader never calls it: a
    // scene file with such a material is an error instead.
    void (*fit_material)(GlintDesc& desc) = nullptr;
    // Optional (glint_lighting.h): whether the model shades scene.lights[light]
    // itself at the camera's first hit, and that light's reflected radiance
    // towards ctx.wo. Null for models that are plain BRDFs (GlintBxdf) under
    // every light.
    bool (*shades_light)(const GlintDesc& desc, const Scene& scene, int light) = nullptr;
    glm::vec3 (*light_radiance)(const GlintLightingContext& ctx, int light) = nullptr;
    // Optional (facet_extent.h; `glintlab compare`): sets the model's own
    // facet-extent parameter to the explicit ground truth's reflection cone
    // of half-angle gamma (radians) and returns what it set, e.g.
    // "microfacet_roughness 0.000846", noting a clamp to the parameter's
    // range.
    std::string (*match_facet_cone)(GlintDesc& desc, double gamma_rad) = nullptr;
    // Optional: for a model whose facets' extent the method fixes (no
    // parameter), the explicit cone half-angle (radians) of the same extent.
    double (*facet_cone)(const GlintDesc& desc) = nullptr;
    // Which shared parameters may come from a texture (docs/MODELS.md,
    // "Textured parameters"): colour and base_albedo always; the density and
    // the roughness where the model evaluates them per hit. A model that
    // precomputes from them per material says why not (the loader's error
    // quotes it).
    bool textured_density = true, textured_roughness = true;
    std::string untextured_reason;
    // The renderers widen the model's α per hit by the footprint's normal
    // covariance from the surface's curvature (docs/MODELS.md, "Curved
    // surfaces"). False where α is fixed per material (textured_roughness
    // false), where a per-hit α builds a table per pixel (jakob2014), and
    // for `explicit`, which composes each facet with the curved surface.
    bool filters_curvature = true;
    // The material's model reads the correlation of the footprint's slopes
    // (GlintDesc::slope_correlation) as well as the widened α, i.e. shears
    // its target NDF by it; null: no, the correlation is dropped.
    std::function<bool(const GlintDesc&)> reads_slope_correlation;
    GlintValidationSuite validation;  // name empty: no suite
    // Set (set_export): `glintlab export` writes the model (its GPU back end).
    std::optional<GlintModelExport> shader_export;

    // A model with a GPU back end: set_gpu_hooks(GLINTLAB_GPU_HOOKS(foo_gpu_hooks)).
    void set_gpu_hooks(const GpuModelHooks& (*hooks)()) {
        gpu = true;
        gpu_hooks = hooks;
    }
    // A model `glintlab export` writes: set_export(glue,
    // GLINTLAB_EXPORT_HOOK(foo_export_material)); returns the export for its
    // other fields (variant, compute passes).
    GlintModelExport& set_export(std::string glue,
                                 void (*material)(GlintExportContext& ctx) = nullptr) {
        shader_export = GlintModelExport{};
        shader_export->glue = std::move(glue);
        shader_export->material = material;
        return *shader_export;
    }

    bool shades(GlintLightType type) const;
    const GlintParam* find_param(std::string_view key) const;
    GlintParamValue default_value(const GlintParam& param) const {
        return param.get(default_params());
    }
};

// Compatibility name used by code that predates descriptors.
using GlintModelInfo = GlintModelDescriptor;

// The head of every descriptor: its id, name, one-line description, the
// light types it can shade and default_params (a default-constructed P).
template <class P>
GlintModelDescriptor make_glint_model_descriptor(GlintModelId id, std::string_view name,
                                                 std::string description,
                                                 std::vector<GlintLightType> lights) {
    GlintModelDescriptor d;
    d.id = id;
    d.name = name;
    d.description = std::move(description);
    d.lights = std::move(lights);
    d.default_params = [] { return GlintModelParams(P{}); };
    return d;
}

// The argument of set_gpu_hooks: the model's hooks function where the OpenGL
// renderer is built (GLINTLAB_WITH_GL), null elsewhere (the hooks' sources
// are not compiled there).
#if GLINTLAB_WITH_GL
#define GLINTLAB_GPU_HOOKS(hooks_function) (&(hooks_function))
#else
#define GLINTLAB_GPU_HOOKS(hooks_function) nullptr
#endif

// The hook of GlintModelExport::material: the model's function, null in the
// lean fuzzing build (GLINTLAB_NO_MODEL_EXPORT), which compiles the
// descriptors without the export code.
#ifndef GLINTLAB_NO_MODEL_EXPORT
#define GLINTLAB_EXPORT_HOOK(hook_function) (&(hook_function))
#else
#define GLINTLAB_EXPORT_HOOK(hook_function) nullptr
#endif

// The lighting hooks of a model that shades some lights itself
// (glint_lighting.h): its functions, except in the lean fuzzing build
// (GLINTLAB_NO_MODEL_LIGHTING), which compiles the descriptors without the
// models. There they are one shared pair that aborts (fuzz/
// no_model_lighting.cpp): loading a scene never shades, but the scene reader
// asks whether a model has the hooks, so they must not be null.
#ifndef GLINTLAB_NO_MODEL_LIGHTING
#define GLINTLAB_SHADES_LIGHT_HOOK(hook_function) (&(hook_function))
#define GLINTLAB_LIGHT_RADIANCE_HOOK(hook_function) (&(hook_function))
#else
bool shades_light_outside_this_build(const GlintDesc& desc, const Scene& scene, int light);
glm::vec3 light_radiance_outside_this_build(const GlintLightingContext& ctx, int light);
#define GLINTLAB_SHADES_LIGHT_HOOK(hook_function) (&shades_light_outside_this_build)
#define GLINTLAB_LIGHT_RADIANCE_HOOK(hook_function) (&light_radiance_outside_this_build)
#endif

// Table rows from a member of the model's params struct P.
namespace glint_param {

template <class P, class T>
GlintParam number(std::string key, T P::*member, double min, double max, std::string unit,
                  std::string doc, GlintParamUi ui = GlintParamUi::Linear) {
    static_assert(std::is_floating_point_v<T>);
    GlintParam p;
    p.key = std::move(key);
    p.type = GlintParamType::Number;
    p.min = min, p.max = max;
    p.single_precision = std::is_same_v<T, float>;
    p.unit = std::move(unit);
    p.doc = std::move(doc);
    p.ui = ui;
    p.get = [member](const GlintModelParams& v) {
        return GlintParamValue(static_cast<double>(std::get<P>(v).*member));
    };
    p.set = [member](GlintModelParams& v, const GlintParamValue& x) {
        std::get<P>(v).*member = static_cast<T>(std::get<double>(x));
    };
    return p;
}

template <class P>
GlintParam integer(std::string key, int P::*member, int min, int max, std::string unit,
                   std::string doc, std::vector<int> values = {}) {
    GlintParam p;
    p.key = std::move(key);
    p.type = GlintParamType::Integer;
    p.min = min, p.max = max;
    p.integer_values = std::move(values);
    p.unit = std::move(unit);
    p.doc = std::move(doc);
    p.get = [member](const GlintModelParams& v) { return GlintParamValue(std::get<P>(v).*member); };
    p.set = [member](GlintModelParams& v, const GlintParamValue& x) {
        std::get<P>(v).*member = std::get<int>(x);
    };
    return p;
}

template <class P>
GlintParam boolean(std::string key, bool P::*member, std::string doc) {
    GlintParam p;
    p.key = std::move(key);
    p.type = GlintParamType::Bool;
    p.doc = std::move(doc);
    p.get = [member](const GlintModelParams& v) { return GlintParamValue(std::get<P>(v).*member); };
    p.set = [member](GlintModelParams& v, const GlintParamValue& x) {
        std::get<P>(v).*member = std::get<bool>(x);
    };
    return p;
}

// An enum over names: each choice is (name, member value).
template <class P, class T>
GlintParam choice(std::string key, T P::*member, std::vector<std::pair<std::string, T>> values,
                  std::string doc) {
    GlintParam p;
    p.key = std::move(key);
    p.type = GlintParamType::Enum;
    for (const auto& [name, _] : values) p.choices.push_back(name);
    p.doc = std::move(doc);
    p.get = [member, values](const GlintModelParams& v) {
        const T x = std::get<P>(v).*member;
        for (const auto& [name, value] : values)
            if (value == x) return GlintParamValue(name);
        return GlintParamValue(std::string());
    };
    p.set = [member, values](GlintModelParams& v, const GlintParamValue& x) {
        for (const auto& [name, value] : values)
            if (name == std::get<std::string>(x)) std::get<P>(v).*member = value;
    };
    return p;
}

// R of 000 Eq. 4 (p = R D(h)/D(n)), shared by the models that count facets
// on an angular grid (zirr2016, deliot2023, kneiphof2025's point-light path).
// R in (0, 1] (000 §3); 1e-4 stands for the open end: below it the angular
// cells h.xy / R are finer than fp32 resolves near the normal.
template <class P>
GlintParam microfacet_roughness(float P::*member, std::string doc) {
    return number("microfacet_roughness", member, 1e-4, 1.0, "", std::move(doc), GlintParamUi::Log);
}

}  // namespace glint_param

}  // namespace glintlab
