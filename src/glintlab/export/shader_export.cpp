#include "glintlab/export/shader_export.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "glintlab/core/error.h"
#include "glintlab/core/image.h"
#include "glintlab/core/shader_assembly.h"
#include "glintlab/core/shader_sources.h"
#include "glintlab/glints/chermain2020/dictionary.h"
#include "glintlab/glints/deliot2023/deliot2023.h"
#include "glintlab/glints/glint_model_descriptor.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_params.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_prefilter.h"
#include "glintlab/glints/registry.h"
#include "glintlab/glints/wang2020/wang2020_model.h"
#include "glintlab/glints/wang2020/wang2020_shading.h"
#include "glintlab/scene/environment.h"

#ifndef GLINTLAB_GIT_COMMIT
#define GLINTLAB_GIT_COMMIT "unknown"
#endif

namespace glintlab {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kEntry = "glintlab/export/glint_export.frag.glsl";

// The models with a GPU back end (glints/gpu_model_hooks.h lists them for
// the renderer; this table adds, per model, the glue variants and passes
// exported). `glue` is the renderer's own glue file; `variant_glue` the
// renderer's option variant (deliot2023's noise texture, 000 §6.3).
struct ExportModel {
    GlintModelId id;
    const char* glue;
    const char* variant;  // nullptr: no variant
    const char* variant_glue;
    std::vector<const char*> compute;  // per-environment passes (embedded paths)
};

const std::vector<ExportModel>& export_table() {
    static const std::vector<ExportModel> table = {
        {GlintModelId::Smooth, "glintlab/glints/smooth_gpu.glsl", nullptr, nullptr, {}},
        {GlintModelId::Deliot2023,
         "glintlab/glints/deliot2023/deliot2023_gpu.glsl",
         "noise_texture",
         "glintlab/glints/deliot2023/deliot2023_noise_texture_gpu.glsl",
         {}},
        {GlintModelId::Zirr2016,
         "glintlab/glints/zirr2016/zirr2016_gpu.glsl",
         nullptr,
         nullptr,
         {}},
        {GlintModelId::Chermain2020,
         "glintlab/glints/chermain2020/chermain2020_gpu.glsl",
         nullptr,
         nullptr,
         {}},
        {GlintModelId::Kneiphof2025,
         "glintlab/glints/kneiphof2025/kneiphof2025_gpu.glsl",
         nullptr,
         nullptr,
         {"glintlab/glints/kneiphof2025/kneiphof2025_prefilter_base.comp.glsl",
          "glintlab/glints/kneiphof2025/kneiphof2025_prefilter_partition.comp.glsl",
          "glintlab/glints/kneiphof2025/kneiphof2025_prefilter_reduce.comp.glsl",
          "glintlab/glints/kneiphof2025/kneiphof2025_prefilter_filter.comp.glsl"}},
        // The renderer's glue reads the tables from SSBOs (wang2020_gpu.glsl);
        // the export reads them from textures in every language (GLSL ES 3.00
        // has no storage buffers), the rest of the glue is shared
        // (wang2020_glue_common.glsl).
        {GlintModelId::Wang2020,
         "glintlab/glints/wang2020/wang2020_export_textures.glsl",
         nullptr,
         nullptr,
         {}},
    };
    return table;
}

const ExportModel* find_export_model(GlintModelId id) {
    for (const ExportModel& m : export_table())
        if (m.id == id) return &m;
    return nullptr;
}

// ---- Flattening ------------------------------------------------------------

bool starts_with(std::string_view s, std::string_view p) {
    return s.substr(0, p.size()) == p;
}

std::string trim(std::string_view s) {
    size_t a = 0, b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
    return std::string(s.substr(a, b - a));
}

// Resolves the project's preprocessor use in assembled text so that the
// exported file needs no macro from its host: drops `#line` directives and
// include guards, evaluates `#ifdef`/`#ifndef`/`#else`/`#endif` over the
// GLINTLAB_* flags (GLINTLAB_GLSL defined, GLINTLAB_CPP not, the glue's own
// `#define GLINTLAB_... 1`), and expands INOUT(T)/OUT(T) (core/glsl.h).
// Other `#define NAME VALUE` lines (model constants) stay. Any other
// conditional is an error, so nothing is silently mis-evaluated.
std::string resolve_preprocessor(const std::string& text) {
    std::set<std::string> defined = {"GLINTLAB_GLSL"};
    struct Cond {
        bool guard;   // an include guard: #endif dropped silently
        bool active;  // this branch is emitted
        bool parent_active;
    };
    std::vector<Cond> stack;
    auto active = [&] { return stack.empty() || stack.back().active; };
    std::istringstream in(text);
    std::string line, out;
    while (std::getline(in, line)) {
        const std::string t = trim(line);
        if (starts_with(t, "#line ")) continue;
        if (starts_with(t, "#ifndef ") || starts_with(t, "#ifdef ")) {
            const bool negate = starts_with(t, "#ifndef ");
            const std::string name = trim(t.substr(negate ? 8 : 7));
            const bool guard = negate && starts_with(name, "GLINTLAB_") && name.size() > 5 &&
                               name.substr(name.size() - 5) == "_GLSL";
            const bool is_defined = defined.contains(name);
            if (!guard && !starts_with(name, "GLINTLAB_"))
                fail("export: unexpected conditional \"{}\" in the shader sources", t);
            const bool cond = guard ? true : (negate ? !is_defined : is_defined);
            stack.push_back({guard, active() && cond, active()});
            continue;
        }
        if (starts_with(t, "#else")) {
            if (stack.empty()) fail("export: #else without #if in the shader sources");
            Cond& c = stack.back();
            c.active = c.parent_active && !c.active;
            continue;
        }
        if (starts_with(t, "#endif")) {
            if (stack.empty()) fail("export: #endif without #if in the shader sources");
            stack.pop_back();
            continue;
        }
        if (starts_with(t, "#if") || starts_with(t, "#elif") || starts_with(t, "#undef"))
            fail("export: unsupported directive \"{}\" in the shader sources", t);
        if (!active()) continue;
        if (starts_with(t, "#define ")) {
            std::istringstream d(t.substr(8));
            std::string name, value;
            d >> name >> value;
            if (starts_with(name, "GLINTLAB_")) {
                if (!(value.empty() || value == "1") || name.find('(') != std::string::npos)
                    fail("export: unexpected macro \"{}\" in the shader sources", t);
                // Guards define their own name: already handled by the stack.
                defined.insert(name);
                continue;
            }
        }
        out += line;
        out += '\n';
    }
    if (!stack.empty()) fail("export: unterminated #if in the shader sources");
    static const std::regex inout(R"(\bINOUT\(([^()]*)\))");
    static const std::regex outp(R"(\bOUT\(([^()]*)\))");
    out = std::regex_replace(out, inout, "inout $1");
    out = std::regex_replace(out, outp, "out $1");
    // Collapse runs of blank lines left by removed directives.
    static const std::regex blanks("\n{3,}");
    return std::regex_replace(out, blanks, "\n\n");
}

// GLSL ES 3.00 spellings of the 4.50 text: no float suffix, no fine
// derivatives, no binding qualifiers (the manifest gives the unit).
std::string to_glsl_es(std::string text) {
    static const std::regex suffix(
        R"((^|[^A-Za-z0-9_.])((\d+\.\d*|\.\d+|\d+)([eE][+-]?\d+)?)[fF]\b)");
    text = std::regex_replace(text, suffix, "$1$2");
    static const std::regex fine(R"(\bdF(dx|dy)Fine\b)");
    text = std::regex_replace(text, fine, "dF$1");
    static const std::regex binding(R"(layout\s*\(\s*binding\s*=\s*\d+\s*\)\s*uniform)");
    text = std::regex_replace(text, binding, "uniform");
    // ldexp is GLSL ES 3.10: exact through exp2 for the integer exponents used.
    static const std::regex ldexp(R"(\bldexp\()");
    if (std::regex_search(text, ldexp))
        text = "float glint_ldexp(float x, int e) { return x * exp2(float(e)); }\n" +
               std::regex_replace(text, ldexp, "glint_ldexp(");
    return text;
}

// ---- Header ----------------------------------------------------------------

std::string comment_block(const std::string& text) {
    std::string out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) out += line.empty() ? "//\n" : "// " + line + "\n";
    return out;
}

std::string citations_text(const GlintModelDescriptor& d) {
    std::string out;
    for (const GlintCitation& c : d.citations)
        out += fmt::format("  {}, \"{}\", {} {}.\n", c.authors, c.title, c.venue, c.year);
    return out;
}

std::string parameter_rows(const GlintModelDescriptor& d, const std::string& shader) {
    std::string out;
    for (const GlintParam& p : d.params) {
        const std::string uniform = fmt::format("u_{}_{}", d.name, p.key);
        const bool is_uniform =
            p.type != GlintParamType::Enum && shader.find(" " + uniform + ";") != std::string::npos;
        out += fmt::format(
            "  {:<28} {} {}{}, default {}: {}\n", is_uniform ? uniform : fmt::format("({})", p.key),
            glint_param_type_name(p.type), p.range_text(), p.unit.empty() ? "" : " " + p.unit,
            glint_param_value_text(d.default_value(p)), p.doc);
    }
    return out;
}

std::string header(const GlintModelDescriptor& d, ExportLanguage lang, const std::string& glue,
                   const std::string& shader) {
    std::string h = fmt::format(
        "glintlab export: glint model \"{}\" ({}), {}.\n"
        "Generated by glintlab {} (commit {}) from the renderer's own sources\n"
        "({} and glintlab/export/glint_export.frag.glsl, flattened): do not edit,\n"
        "re-export. Integration guide: docs/INTEGRATION.md of glintlab.\n\n"
        "Citation:\n{}\n",
        d.name, d.description,
        lang == ExportLanguage::Glsl     ? "GLSL 4.50 fragment shader"
        : lang == ExportLanguage::GlslEs ? "GLSL ES 3.00 fragment shader (WebGL2)"
                                         : "HLSL Shader Model 5.0 pixel shader",
        GLINTLAB_VERSION, GLINTLAB_GIT_COMMIT, glue, citations_text(d));
    h +=
        "Contract (all vectors world space unless said; angles radians; radiance linear,\n"
        "not sRGB; the host writes o_radiance to a float or linear target and tone maps):\n"
        "  inputs  v_position (world position), v_normal (shading normal), v_uv (uv of the\n"
        "          glint pattern: log_density is ln(microfacets per unit uv area)),\n"
        "          v_dpdu (world dp/du, the tangent of the anisotropic frame)\n"
        "  output  o_radiance: rgb radiance towards u_eye, a = 1\n"
        "  Footprint glint_footprint(vec2 uv): the pixel footprint, uv and its derivatives\n"
        "          per pixel (x right, y DOWN the image: -dFdy in OpenGL window space). Call\n"
        "          in uniform control flow (derivatives are undefined in divergent code).\n"
        "  vec3 glint_eval(vec3 wo, vec3 wi, Footprint fp): f(wo, wi) cos(wi) of the glint\n"
        "          material in the local frame (z = normal, x = tangent along dp/du).\n"
        "  vec3 glint_shade(vec3 p, vec3 n, vec3 dpdu, Footprint fp): radiance at p from\n"
        "          the lights below (no shadows).\n"
        "Uniforms of every model (glintlab scene format, docs/SCENE_FORMAT.md):\n"
        "  u_eye                     vec3 camera position\n"
        "  u_glint_ndf               int 0 Beckmann, 1 GGX (the smooth limit's NDF)\n"
        "  u_glint_alpha             vec2 (alpha_x, alpha_y) in (0, 1]: scene \"roughness\"\n"
        "  u_glint_log_density       float ln(microfacets per unit uv area), scene "
        "\"log_density\"\n"
        "  u_glint_seed              uint pattern seed\n"
        "  u_glint_color             vec3 tint, u_glint_base_albedo vec3 diffuse base (0: none)\n"
        "  u_fresnel_mode            int 0 none, 1 Schlick (u_fresnel_f0), 2 conductor\n"
        "                            (u_fresnel_eta, u_fresnel_k), 3 dielectric (u_fresnel_eta.x)\n"
        "  u_glint_g2                int masking: 0 Smith height-correlated, 1 V-cavity\n"
        "                            (chermain2020 uses 1, every other model 0)\n"
        "  u_directional_count       int <= GLINT_MAX_LIGHTS; u_directional_direction[i]\n"
        "                            (towards the light, unit), u_directional_irradiance[i]\n"
        "  u_point_count             int <= GLINT_MAX_LIGHTS; u_point_position[i],\n"
        "                            u_point_intensity[i] (W/sr per channel)\n";
    h += "  u_environment_on          bool the model's own environment lighting (kneiphof2025,\n"
         "                            wang2020; ignored by the other models)\n";
    h += fmt::format(
        "Parameters of {} (uniform, type, range, default: meaning; a name in\n"
        "parentheses is host-side, see docs/INTEGRATION.md):\n{}",
        d.name, parameter_rows(d, shader));
    return comment_block(h);
}

// ---- Files -----------------------------------------------------------------

void write_file(const fs::path& path, std::string_view bytes) {
    std::ofstream f(path, std::ios::binary);
    f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    f.close();
    if (!f) fail("export: cannot write \"{}\"", path.string());
}

std::string read_file(const fs::path& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) fail("export: cannot read \"{}\"", path.string());
    return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

// Float32 values as raw little-endian bytes (the host's byte order is checked).
std::string float_bytes(const std::vector<float>& v) {
    static_assert(sizeof(float) == 4);
    const uint32_t probe = 1;
    if (*reinterpret_cast<const unsigned char*>(&probe) != 1)
        fail("export: raw resources are little-endian; this host is big-endian");
    return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(float));
}

std::string quote_arg(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// Runs `command`, returning its combined output; throws naming the step.
void run_tool(const std::string& command, const std::string& what, const fs::path& log) {
    const int status = std::system((command + " > " + quote_arg(log.string()) + " 2>&1").c_str());
    if (status != 0) {
        std::string out;
        if (fs::exists(log)) out = read_file(log);
        fail("export: {} failed (exit status {}): {}\n{}", what, status, command, out);
    }
}

// GLSL 4.50 -> SPIR-V (glslang, OpenGL semantics: loose uniforms allowed)
// -> HLSL SM 5.0 (SPIRV-Cross).
std::string glsl_to_hlsl(const ExportOptions& o, const std::string& glsl, const std::string& stage,
                         const std::string& name) {
    const fs::path tmp = fs::temp_directory_path() /
                         fmt::format("glintlab_export_{}_{}", static_cast<long>(::getpid()), name);
    fs::create_directories(tmp);
    const fs::path src = tmp / ("shader." + stage);
    const fs::path spv = tmp / "shader.spv";
    const fs::path hlsl = tmp / "shader.hlsl";
    write_file(src, glsl);
    run_tool(fmt::format("{} -G --aml --amb -S {} -o {} {}", quote_arg(o.glslang_validator), stage,
                         quote_arg(spv.string()), quote_arg(src.string())),
             fmt::format("glslangValidator (GLSL -> SPIR-V) of {}", name), tmp / "glslang.log");
    run_tool(fmt::format("{} {} --hlsl --shader-model 50 --output {}", quote_arg(o.spirv_cross),
                         quote_arg(spv.string()), quote_arg(hlsl.string())),
             fmt::format("spirv-cross (SPIR-V -> HLSL) of {}", name), tmp / "spirv_cross.log");
    std::string out = read_file(hlsl);
    fs::remove_all(tmp);
    return out;
}

const char* lang_ext(ExportLanguage l) {
    return l == ExportLanguage::Hlsl ? "hlsl" : "glsl";
}

struct Manifest {
    nlohmann::json shaders = nlohmann::json::array();
    nlohmann::json resources = nlohmann::json::array();
    nlohmann::json passes = nlohmann::json::array();
};

}  // namespace

const char* export_language_name(ExportLanguage lang) {
    switch (lang) {
        case ExportLanguage::Glsl:
            return "glsl";
        case ExportLanguage::GlslEs:
            return "glsles";
        case ExportLanguage::Hlsl:
            return "hlsl";
    }
    return "?";
}

ExportLanguage parse_export_language(std::string_view name) {
    for (ExportLanguage l : {ExportLanguage::Glsl, ExportLanguage::GlslEs, ExportLanguage::Hlsl})
        if (name == export_language_name(l)) return l;
    fail("export: --lang \"{}\" is not a language (allowed: glsl, glsles, hlsl)", name);
}

std::vector<std::string> exportable_models() {
    std::vector<std::string> out;
    for (const GlintModelDescriptor& d : glint_models())
        if (find_export_model(d.id)) out.emplace_back(d.name);
    return out;
}

std::string export_fragment_glsl(GlintModelId model, unsigned program_options,
                                 ExportLanguage language) {
    const ExportModel* m = find_export_model(model);
    if (!m) fail("export: model \"{}\" has no exportable GPU back end", glint_model(model).name);
    const std::string glue = (program_options & 1u) && m->variant_glue ? m->variant_glue : m->glue;
    const std::string root =
        fmt::format("#include \"{}\"\n#include \"{}\"\n", glue, std::string(kEntry));
    const AssembledShader a = assemble_shader(root, true, "\n");
    std::string body = resolve_preprocessor(a.text);
    std::string prelude;
    if (language == ExportLanguage::GlslEs) {
        body = to_glsl_es(body);
        prelude =
            "#version 300 es\n"
            "precision highp float;\n"
            "precision highp int;\n"
            "precision highp sampler2D;\n"
            "precision highp sampler2DArray;\n";
    } else {
        prelude = "#version 450 core\n";
    }
    return prelude + header(glint_model(model), language, glue, body) + body;
}

std::vector<ExportedFile> export_model(const ExportOptions& o) {
    const GlintModelDescriptor* d = find_glint_model(o.model);
    if (!d)
        fail("export: unknown model \"{}\" (models with a GPU back end: {})", o.model,
             fmt::join(exportable_models(), ", "));
    const ExportModel* m = find_export_model(d->id);
    if (!m)
        fail("export: model \"{}\" has no exportable GPU back end (exportable: {})", o.model,
             fmt::join(exportable_models(), ", "));
    std::error_code ec;
    fs::create_directories(o.out_dir, ec);
    if (ec || !fs::is_directory(o.out_dir))
        fail("export: cannot create output directory \"{}\": {}", o.out_dir.string(), ec.message());

    const std::string model(d->name);
    const std::string lang = export_language_name(o.language);
    std::vector<ExportedFile> files;
    Manifest man;
    auto add = [&](const std::string& name, const std::string& kind, std::string_view bytes) {
        write_file(o.out_dir / name, bytes);
        files.push_back({name, kind, bytes.size()});
    };

    // Fragment stages: the default program, and the option variant.
    for (unsigned variant = 0; variant < (m->variant ? 2u : 1u); ++variant) {
        const std::string suffix = variant ? std::string("_") + m->variant : "";
        const std::string name =
            fmt::format("{}{}.{}.frag.{}", model, suffix, lang, lang_ext(o.language));
        const ExportLanguage glsl_lang =
            o.language == ExportLanguage::Hlsl ? ExportLanguage::Glsl : o.language;
        std::string text = export_fragment_glsl(d->id, variant, glsl_lang);
        if (o.language == ExportLanguage::Hlsl) {
            const std::string glsl = text;
            text = header(*d, o.language, variant ? m->variant_glue : m->glue, glsl) +
                   "// Entry point: main (pixel stage). Uniform names are those of the GLSL\n"
                   "// export (global uniforms, SPIRV-Cross's $Globals constant buffer).\n" +
                   glsl_to_hlsl(o, glsl, "frag", model + suffix);
        }
        add(name, "fragment_shader", text);
        man.shaders.push_back({{"file", name},
                               {"stage", "fragment"},
                               {"entry", "main"},
                               {"variant", variant ? m->variant : "default"}});
    }

    // Compute passes (per environment): not in GLSL ES 3.00.
    if (!m->compute.empty() && o.language != ExportLanguage::GlslEs) {
        for (const char* path : m->compute) {
            std::string stem = fs::path(path).filename().string();
            stem = stem.substr(0, stem.find(".comp.glsl"));
            const std::string name = fmt::format("{}.{}.comp.{}", stem, lang, lang_ext(o.language));
            const AssembledShader a =
                assemble_shader(fmt::format("#include \"{}\"\n", path), true, "\n");
            const std::string body = resolve_preprocessor(a.text);
            std::string text =
                "#version 450 core\n" +
                comment_block(fmt::format(
                    "glintlab export: {} compute pass of {} (per environment; see\n"
                    "docs/INTEGRATION.md). Generated by glintlab {} (commit {}) from {}.\n",
                    stem, model, GLINTLAB_VERSION, GLINTLAB_GIT_COMMIT, path)) +
                body;
            if (o.language == ExportLanguage::Hlsl) text = glsl_to_hlsl(o, text, "comp", stem);
            add(name, "compute_shader", text);
            man.passes.push_back({{"file", name}, {"stage", "compute"}, {"source", path}});
        }
    }

    // Resources.
    auto resource = [&](const std::string& key, const std::vector<float>& values,
                        nlohmann::json info) {
        const bool uint = info.value("format", "") == "RG32UI";  // uint32 bit patterns
        const std::string name = fmt::format("{}.{}.{}", model, key, uint ? "u32" : "f32");
        add(name, "texture", float_bytes(values));
        info["file"] = name;
        info["bytes"] = values.size() * sizeof(float);
        info["encoding"] =
            "raw little-endian float32, row-major, first row at texture coordinate "
            "t = 0 (upload as is), channels interleaved";
        man.resources.push_back(info);
    };
    if (d->id == GlintModelId::Deliot2023) {
        std::vector<float> pairs;
        for (const glm::vec2& v : deliot2023_noise_table()) {
            pairs.push_back(v.x);
            pairs.push_back(v.y);
        }
        resource("noise", pairs,
                 {{"uniform", "u_deliot2023_noise"},
                  {"binding", 5},
                  {"used_by", "noise_texture variant"},
                  {"format", "RG32F"},
                  {"width", 64},
                  {"height", 64},
                  {"filter", "nearest"},
                  {"wrap", "repeat"},
                  {"mipmaps", false},
                  {"meaning",
                   "the two uniforms of each gated-Gaussian evaluation (000 6.3), indexed by "
                   "cell hash % 4096 (texelFetch)"}});
    }
    if (d->id == GlintModelId::Chermain2020) {
        const Dictionary& dict = default_dictionary();
        resource("dictionary", dict.values,
                 {{"uniform", "chermain2020_dictionary"},
                  {"format", "R32F"},
                  {"width", dict.params.table_size},
                  {"height", dict.params.n_dists * dict.params.n_levels},
                  {"filter", "nearest"},
                  {"wrap", "clamp_to_edge"},
                  {"mipmaps", false},
                  {"meaning",
                   "004 4.4-4.5 dictionary of 1D marginal distributions: row dist * n_levels + "
                   "level, one texel per table sample (texelFetch)"},
                  {"uniforms",
                   {{"u_chermain2020_dict_shape",
                     {dict.params.n_levels, dict.params.n_dists, dict.params.table_size}},
                    {"u_chermain2020_dict_range", {dict.params.alpha_dict, dict.slope_max}}}}});
    }
    if (d->id == GlintModelId::Kneiphof2025) {
        constexpr int n = Kneiphof2025DfgLut::kSize;
        std::vector<float> rgba(static_cast<size_t>(n) * n * 4, 0.0f);
        const Kneiphof2025DfgLut& lut = Kneiphof2025DfgLut::get();
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const glm::vec3 v = lut.lookup((static_cast<float>(i) + 0.5f) / n,
                                               (static_cast<float>(j) + 0.5f) / n);
                float* t = &rgba[(static_cast<size_t>(j) * n + i) * 4];
                t[0] = v.x;
                t[1] = v.y;
                t[2] = v.z;
            }
        resource("dfg", rgba,
                 {{"uniform", "kneiphof2025_dfg_lut"},
                  {"format", "RGBA32F"},
                  {"width", n},
                  {"height", n},
                  {"filter", "linear"},
                  {"wrap", "clamp_to_edge"},
                  {"mipmaps", false},
                  {"meaning",
                   "(A, B, E_D / D_H, 0) of isotropic GGX at (cos_o, sqrt(alpha)) texel centres "
                   "(003 Eq. 11, 21)"}});
        if (!o.environment.empty()) {
            const Image image = read_image(o.environment);
            const EnvironmentMap env(image, 1.0f, 0.0f);
            Kneiphof2025PrefilterOptions po;  // the renderer's defaults (K = 8)
            const Kneiphof2025Environment pre(env, po);
            const int layers = static_cast<int>(pre.mips().size());
            const int w = pre.mips()[0].width, h = pre.mips()[0].height;
            const int channels = pre.channels();
            std::vector<float> rad, wa, wb;
            for (const Kneiphof2025Level& l : pre.mips()) {
                // The data's rows run from v = 0 (zenith) down; a texture's
                // row 0 is t = 0, the same v: no flip.
                for (int p = 0; p < l.width * l.height; ++p) {
                    const float* src = &l.data[static_cast<size_t>(p) * channels];
                    for (int c = 0; c < 4; ++c) {
                        rad.push_back(c < 3 ? src[c] : 1.0f);
                        wa.push_back(3 + c < channels ? src[3 + c] : 0.0f);
                        wb.push_back(7 + c < channels ? src[7 + c] : 0.0f);
                    }
                }
            }
            const nlohmann::json common = {{"format", "RGBA32F"},
                                           {"target", "2D_ARRAY"},
                                           {"width", w},
                                           {"height", h},
                                           {"layers", layers},
                                           {"filter", "linear"},
                                           {"wrap", "repeat_s_clamp_t"},
                                           {"mipmaps", false},
                                           {"environment", o.environment.string()}};
            nlohmann::json r = common;
            r["uniform"] = "kneiphof2025_radiance_layers";
            r["meaning"] =
                "prefiltered radiance (003 Eq. 11), layer i: sqrt(alpha) = i / "
                "(layers - 1), lat-long, v = 0 at the zenith";
            resource("env_radiance", rad, r);
            r = common;
            r["uniform"] = "kneiphof2025_weights_layers_a";
            r["meaning"] = "prefiltered fuzzy indicators w^(1..4) (003 Eq. 19-21)";
            resource("env_weights_a", wa, r);
            r = common;
            r["uniform"] = "kneiphof2025_weights_layers_b";
            r["meaning"] = "prefiltered fuzzy indicators w^(5..8) (003 Eq. 19-21)";
            resource("env_weights_b", wb, r);
            const auto& L = pre.radiance_levels();
            man.resources.back()["uniforms"] = {
                {"u_kneiphof2025_levels_a", {L[0], L[1], L[2], L[3]}},
                {"u_kneiphof2025_levels_b", {L[4], L[5], L[6], L[7]}},
                {"kneiphof2025_last_layer", static_cast<float>(layers - 1)},
                {"u_kneiphof2025_radiance_scale", 1.0f},
                {"levels_K", pre.levels()}};
        }
    }

    if (d->id == GlintModelId::Wang2020) {
        // The tables of the default wang2020 material (switch_glint_model:
        // the descriptor's defaults, isotropic Beckmann), under --env's
        // environment if given: the arrays the renderer uploads as SSBOs,
        // laid out in textures WANG2020_TABLE_WIDTH (4096) texels wide.
        GlintDesc g;
        switch_glint_model(g, GlintModelId::Wang2020);
        std::shared_ptr<const EnvironmentMap> env;
        if (!o.environment.empty())
            env = std::make_shared<EnvironmentMap>(read_image(o.environment), 1.0f, 0.0f);
        const auto model_tables = wang2020_model_for(g, env);
        constexpr size_t kWidth = 4096;  // WANG2020_TABLE_WIDTH
        auto table = [&](const std::string& key, std::vector<float> values, int channels,
                         const std::string& format, const std::string& uniform,
                         const std::string& meaning) {
            const size_t elements = values.size() / static_cast<size_t>(channels);
            const size_t rows = std::max<size_t>(1, (elements + kWidth - 1) / kWidth);
            values.resize(rows * kWidth * static_cast<size_t>(channels), 0.0f);
            resource(
                key, values,
                {{"uniform", uniform},
                 {"format", format},
                 {"width", kWidth},
                 {"height", rows},
                 {"elements", elements},
                 {"filter", "nearest"},
                 {"wrap", "clamp_to_edge"},
                 {"mipmaps", false},
                 {"meaning", meaning + "; element i at texel (i % 4096, i / 4096), texelFetch"}});
        };
        auto vec4s = [](const std::vector<glm::vec4>& v) {
            std::vector<float> out;
            for (const glm::vec4& e : v) out.insert(out.end(), {e.x, e.y, e.z, e.w});
            return out;
        };
        table("dpf", model_tables->dpf().values(), 1, "R32F", "u_wang2020_dpf_texture",
              "extracted DPF table P(i, o, gamma) (001 Eq. 6, 4.4)");
        table("prefilter",
              model_tables->prefiltered() ? vec4s(model_tables->prefiltered()->data())
                                          : std::vector<float>(4, 0.0f),
              4, "RGBA32F", "u_wang2020_prefilter_texture",
              "prefiltered environment tables (001 Eqs. 16-17; one zero texel without --env)");
        {
            // Quadtree nodes {first_child, count_mask} as uint32 pairs (RG32UI).
            std::vector<float> bits;
            for (const wang2020::QuadtreeNode& n : model_tables->quadtree().nodes()) {
                float a, b;
                std::memcpy(&a, &n.first_child, 4);
                std::memcpy(&b, &n.count_mask, 4);
                bits.push_back(a);
                bits.push_back(b);
            }
            table("nodes", bits, 2, "RG32UI", "u_wang2020_nodes_texture",
                  "particle quadtree nodes {first_child, count_mask} as uint32 (001 4.4)");
            man.resources.back()["encoding"] =
                "raw little-endian uint32 pairs, row-major, first row at t = 0";
        }
        table("cone",
              model_tables->cone_average() ? vec4s(model_tables->cone_average()->data())
                                           : std::vector<float>(4, 0.0f),
              4, "RGBA32F", "u_wang2020_cone_texture",
              "cone-averaged environment L_gamma (micro per_particle mode; one zero texel "
              "otherwise)");
        const wang2020::DpfResolution& dr = model_tables->dpf().resolution();
        std::array<int, 4> pres{1, 1, 1, 1};
        if (model_tables->prefiltered()) {
            const wang2020::PrefilterResolution& pr = model_tables->prefiltered()->resolution();
            pres = {pr.theta_n, pr.phi_n, pr.theta_o, pr.phi_o};
        }
        const std::array<int, 2> cres =
            model_tables->cone_average()
                ? std::array<int, 2>{model_tables->cone_average()->width(),
                                     model_tables->cone_average()->height()}
                : std::array<int, 2>{1, 1};
        man.resources.back()["uniforms"] = {
            {"u_wang2020_dpf_res", {dr.theta_i, dr.theta_o, dr.phi}},
            {"u_wang2020_prefilter_res", pres},
            {"u_wang2020_depth", model_tables->quadtree().depth()},
            {"u_wang2020_seed", model_tables->material().seed},
            {"u_wang2020_particles", static_cast<double>(model_tables->quadtree().particles())},
            {"u_wang2020_sigma", static_cast<double>(model_tables->sigma_o())},
            {"u_wang2020_micro",
             model_tables->material().micro == wang2020::MicroMode::PerParticle ? 1 : 0},
            {"u_wang2020_cone_res", cres},
            {"u_wang2020_cos_gamma",
             std::cos(model_tables->material().gamma_deg * 3.14159265358979323846 / 180.0)},
            {"u_glint_alpha", {g.alpha_x, g.alpha_y}},
            {"u_glint_log_density", g.log_density},
            {"u_glint_seed", g.seed}};
        man.resources.back()["note"] =
            "the tables are those of the default wang2020 material (uniforms above): a "
            "material with another alpha, density, seed or parameters needs its own tables";
    }

    // Uniforms the host derives from parameters (the renderer's GPU hooks
    // compute them in C++), at the defaults, with how to compute them.
    nlohmann::json derived = nlohmann::json::array();
    if (d->id == GlintModelId::Kneiphof2025) {
        const Kneiphof2025Params k;
        derived = {{{"uniform", "u_kneiphof2025_wang2020_style"},
                    {"value", k.variant == Kneiphof2025Params::Variant::Wang2020Style},
                    {"from", "variant == \"wang2020_style\""}},
                   {{"uniform", "u_kneiphof2025_conditional"},
                    {"value", k.conditional_gaussian},
                    {"from", "gaussian == \"conditional\""}},
                   {{"uniform", "u_kneiphof2025_gamma_solid_angle"},
                    {"value", 2.0 * 3.14159265358979323846 *
                                  (1.0 - std::cos(k.gamma_deg * 3.14159265358979323846 / 180.0))},
                    {"from", "2 pi (1 - cos(gamma_deg))"}},
                   {{"uniform", "u_kneiphof2025_smooth"},
                    {"value", kneiphof2025_smooth_mode(k)},
                    {"from", "smooth: \"split_sum\" -> 0, \"lobe\" -> 1 (KNEIPHOF2025_SMOOTH_*)"}},
                   {{"uniform", "u_kneiphof2025_f0"},
                    {"value", {1.0, 1.0, 1.0}},
                    {"from",
                     "Schlick F0 of the material's Fresnel: none -> 1, schlick -> f0, conductor / "
                     "dielectric -> their Fresnel at normal incidence"}},
                   {{"uniform", "u_kneiphof2025_radiance_scale"},
                    {"value", 1.0},
                    {"from", "current environment scale / the scale the maps were prefiltered at"}},
                   {{"uniform", "kneiphof2025_env_rotation"},
                    {"value", 0.0},
                    {"from", "environment rotation about +y, radians"}},
                   {{"uniform", "black_level"},
                    {"value", k.black_level},
                    {"from",
                     "not a uniform: the prefilter's black level (the --env maps use the "
                     "default)"}}};
    }

    nlohmann::json j;
    j["derived_uniforms"] = derived;
    j["glintlab_version"] = GLINTLAB_VERSION;
    j["glintlab_commit"] = GLINTLAB_GIT_COMMIT;
    j["model"] = model;
    j["language"] = lang;
    j["citations"] = nlohmann::json::array();
    for (const GlintCitation& c : d->citations)
        j["citations"].push_back(
            {{"authors", c.authors}, {"year", c.year}, {"venue", c.venue}, {"title", c.title}});
    j["shaders"] = man.shaders;
    j["compute_passes"] = man.passes;
    j["resources"] = man.resources;
    nlohmann::json params = nlohmann::json::array();
    for (const GlintParam& p : d->params) {
        nlohmann::json q = {{"key", p.key},
                            {"type", glint_param_type_name(p.type)},
                            {"range", p.range_text()},
                            {"unit", p.unit},
                            {"doc", p.doc}};
        const GlintParamValue v = d->default_value(p);
        std::visit([&](const auto& x) { q["default"] = x; }, v);
        const std::string uniform = fmt::format("u_{}_{}", model, p.key);
        // An enum's uniform (if any) holds a code the host derives: host-side.
        if (p.type != GlintParamType::Enum)
            for (const ExportedFile& f : files)
                if (f.kind == "fragment_shader" &&
                    read_file(o.out_dir / f.name).find(uniform) != std::string::npos) {
                    q["uniform"] = uniform;
                    break;
                }
        params.push_back(q);
    }
    j["parameters"] = params;
    nlohmann::json listed = nlohmann::json::array();
    for (const ExportedFile& f : files)
        listed.push_back({{"file", f.name}, {"kind", f.kind}, {"bytes", f.bytes}});
    j["files"] = listed;
    const std::string manifest = fmt::format("{}.{}.manifest.json", model, lang);
    add(manifest, "manifest", j.dump(2) + "\n");
    return files;
}

}  // namespace glintlab
