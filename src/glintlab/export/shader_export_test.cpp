// `glintlab export` (export/shader_export.h): every exported file compiles on
// its own (GLSL 4.50 and GLSL ES 3.00 with glslangValidator, HLSL with
// glslang's HLSL front end), carries no include or project macro, is made
// from the renderer's own glue, and the manifest lists files that exist with
// the sizes it states.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "glintlab/core/error.h"
#include "glintlab/core/image.h"
#include "glintlab/core/image_test_util.h"
#include "glintlab/core/shader_sources.h"
#include "glintlab/export/shader_export.h"
#include "glintlab/glints/glint_bxdf.h"
#include "glintlab/glints/glint_desc.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_prefilter.h"
#include "glintlab/glints/registry.h"
#include "glintlab/scene/environment.h"

namespace glintlab {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

// glslangValidator on one exported file: exit status and log.
std::pair<int, std::string> validate(const fs::path& file, ExportLanguage lang, bool compute) {
    const std::string stage = compute ? "comp" : "frag";
    // glslangValidator takes the stage from -S; GLSL files are copied to a
    // name with the stage's extension for older versions' sake.
    std::string cmd;
    if (lang == ExportLanguage::Hlsl) {
        cmd = fmt::format("{} -D -V -e main -S {} -o {} {}", GLSLANG_VALIDATOR, stage,
                          (file.string() + ".spv"), file.string());
    } else {
        cmd = fmt::format("{} -l -S {} {}", GLSLANG_VALIDATOR, stage, file.string());
    }
    const fs::path log = file.string() + ".log";
    const int status = std::system((cmd + " > " + log.string() + " 2>&1").c_str());
    return {status, slurp(log)};
}

// An HLSL file speaks HLSL: its header comment names no GLSL type, sampler
// or built-in, and its registers fit Direct3D 11's slots (16 samplers, 128
// shader resources, 8 UAVs of a pixel or compute stage), each used once per
// class, each SamplerState named after its texture.
void expect_hlsl_terms_and_registers(const std::string& name, const std::string& text) {
    std::string comment;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line) && line.rfind("//", 0) == 0;)
        comment += line + "\n";
    static const std::regex glsl_words(
        R"(\b(vec[234]|ivec[234]|uvec[234]|mat[234]|sampler2D\w*|sampler3D|samplerCube\w*|)"
        R"(dFdx\w*|dFdy\w*|textureLod|textureGrad|texelFetch|textureSize|gl_\w+|texture unit)\b)");
    std::smatch m;
    EXPECT_FALSE(std::regex_search(comment, m, glsl_words)) << name << ": " << m.str();
    static const std::regex reg(R"((\w+) : register\(([tsu])(\d+)\))");
    std::map<char, std::set<int>> used;
    std::set<std::string> textures;
    std::vector<std::string> samplers;
    for (std::sregex_iterator it(text.begin(), text.end(), reg), end; it != end; ++it) {
        const char kind = (*it)[2].str()[0];
        const int slot = std::stoi((*it)[3].str());
        EXPECT_TRUE(used[kind].insert(slot).second) << name << ": " << kind << slot << " twice";
        EXPECT_LT(slot, kind == 's' ? 16 : kind == 'u' ? 8 : 128) << name << ": " << (*it)[0];
        if (kind == 't') textures.insert((*it)[1]);
        if (kind == 's') samplers.push_back((*it)[1]);
    }
    for (const std::string& s : samplers) {
        const bool paired = s.size() > 9 && s.front() == '_' && s.ends_with("_sampler") &&
                            textures.contains(s.substr(1, s.size() - 9));
        EXPECT_TRUE(paired) << name << ": " << s << " samples no texture";
    }
}

struct Case {
    std::string model;
    ExportLanguage lang;
};

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
    return info.param.model + "_" + export_language_name(info.param.lang);
}

std::vector<Case> all_cases() {
    std::vector<Case> out;
    for (const std::string& m : exportable_models())
        for (ExportLanguage l :
             {ExportLanguage::Glsl, ExportLanguage::GlslEs, ExportLanguage::Hlsl})
            out.push_back({m, l});
    return out;
}

class ExportEach : public ::testing::TestWithParam<Case> {};

TEST_P(ExportEach, EveryFileCompilesStandaloneAndTheManifestMatches) {
    const Case& c = GetParam();
    testing::ScratchDir dir;
    ExportOptions o;
    o.model = c.model;
    o.language = c.lang;
    o.out_dir = dir / "out";
    // The resources do not depend on the language: built and checked once
    // (GLSL 4.50), the other languages check their shaders only (wang2020's
    // tables take seconds to build).
    o.resources = c.lang == ExportLanguage::Glsl;
    const std::vector<ExportedFile> files = export_model(o);
    ASSERT_FALSE(files.empty());
    EXPECT_EQ(files.back().kind, "manifest");

    int shaders = 0;
    for (const ExportedFile& f : files) {
        const fs::path path = o.out_dir / f.name;
        ASSERT_TRUE(fs::exists(path)) << f.name;
        EXPECT_EQ(fs::file_size(path), f.bytes) << f.name;
        if (f.kind != "fragment_shader" && f.kind != "compute_shader") continue;
        ++shaders;
        const std::string text = slurp(path);
        // Flattened and free of project macros: nothing for the host to resolve.
        EXPECT_EQ(text.find("#include"), std::string::npos) << f.name;
        EXPECT_EQ(text.find("INOUT("), std::string::npos) << f.name;
        for (const char* macro : {"#ifdef", "#ifndef", "#line", "#define GLINTLAB"})
            EXPECT_EQ(text.find(macro), std::string::npos) << f.name << ": " << macro;
        if (f.kind == "fragment_shader") {
            // The header names the paper and the version it came from.
            const GlintModelDescriptor* d = find_glint_model(c.model);
            ASSERT_NE(d, nullptr);
            for (const GlintCitation& cit : d->citations)
                EXPECT_NE(text.find(std::to_string(cit.year)), std::string::npos) << f.name;
            EXPECT_NE(text.find(std::string("glintlab ") + GLINTLAB_VERSION), std::string::npos);
        }
        if (c.lang == ExportLanguage::Hlsl) expect_hlsl_terms_and_registers(f.name, text);
        const auto [status, log] = validate(path, c.lang, f.kind == "compute_shader");
        EXPECT_EQ(status, 0) << f.name << ":\n" << log;
    }
    EXPECT_GE(shaders, 1);

    // The manifest: every file it lists exists with its size, and every
    // resource's size is its texel count times its format's bytes.
    const nlohmann::json j = nlohmann::json::parse(slurp(o.out_dir / files.back().name));
    EXPECT_EQ(j.at("model"), c.model);
    EXPECT_EQ(j.at("language"), export_language_name(c.lang));
    EXPECT_EQ(j.at("files").size() + 1, files.size());
    for (const auto& f : j.at("files")) {
        const fs::path p = o.out_dir / f.at("file").get<std::string>();
        ASSERT_TRUE(fs::exists(p)) << p;
        EXPECT_EQ(fs::file_size(p), f.at("bytes").get<uint64_t>()) << p;
    }
    for (const auto& r : j.at("resources")) {
        const std::string format = r.at("format");
        const uint64_t channels = format == "R32F"                          ? 1
                                  : format == "RG32F" || format == "RG32UI" ? 2
                                  : format == "RGB32F"                      ? 3
                                                                            : 4;
        const uint64_t layers = r.contains("layers") ? r.at("layers").get<uint64_t>() : 1;
        const uint64_t expected =
            r.at("width").get<uint64_t>() * r.at("height").get<uint64_t>() * layers * channels * 4;
        EXPECT_EQ(fs::file_size(o.out_dir / r.at("file").get<std::string>()), expected)
            << r.at("file");
        EXPECT_TRUE(r.contains("uniform") && r.contains("filter") && r.contains("wrap") &&
                    r.contains("meaning"))
            << r.dump();
    }
    if (!o.resources) {
        EXPECT_TRUE(j.at("resources").empty());
    }
    // Shaders per language: GLSL ES has no compute stage.
    for (const auto& p : j.at("compute_passes"))
        EXPECT_NE(c.lang, ExportLanguage::GlslEs) << p.dump();
}

INSTANTIATE_TEST_SUITE_P(Models, ExportEach, ::testing::ValuesIn(all_cases()), case_name);

// Generated from the renderer's sources, not a copy: every code line of the
// model's glue (the renderer's own glints/**/*_gpu.glsl) is in the export.
TEST(Export, FragmentHoldsTheRenderersGlueVerbatim) {
    for (const char* glue : {"glintlab/glints/deliot2023/deliot2023_gpu.glsl",
                             "glintlab/glints/chermain2020/chermain2020_gpu.glsl"}) {
        std::string text;
        for (const ShaderSource& s : shader_sources())
            if (s.path == glue) text = std::string(s.text);
        ASSERT_FALSE(text.empty()) << glue;
        const GlintModelId id = std::string(glue).find("deliot") != std::string::npos
                                    ? GlintModelId::Deliot2023
                                    : GlintModelId::Chermain2020;
        const std::string out = export_fragment_glsl(id, 0, ExportLanguage::Glsl);
        std::istringstream lines(text);
        std::string line;
        int checked = 0;
        // The default export defines no option macro: an `#ifdef OPTION`
        // branch (e.g. deliot2023's stochastic_grid) is left out and its
        // #else branch kept; the include guard (#ifndef) stays active; any
        // other #if is not checked. Every other code line must be there.
        std::vector<int> active;  // per open conditional: 1 kept, 0 left out, -1 unknown
        const auto all_active = [&] {
            return std::all_of(active.begin(), active.end(), [](int a) { return a == 1; });
        };
        while (std::getline(lines, line)) {
            if (line.rfind("#ifndef", 0) == 0) {
                active.push_back(1);
                continue;
            }
            if (line.rfind("#if", 0) == 0) {
                active.push_back(line.rfind("#ifdef GLINTLAB_", 0) == 0 ? 0 : -1);
                continue;
            }
            if (line.rfind("#else", 0) == 0 && !active.empty()) {
                if (active.back() >= 0) active.back() = 1 - active.back();
                continue;
            }
            if (line.rfind("#endif", 0) == 0 && !active.empty()) {
                active.pop_back();
                continue;
            }
            if (!all_active()) continue;
            if (line.empty() || line[0] == '#' || line.find("//") == 0) continue;
            if (line.find("INOUT(") != std::string::npos) continue;
            EXPECT_NE(out.find(line), std::string::npos) << glue << ": " << line;
            ++checked;
        }
        EXPECT_GE(checked, 5) << glue;
    }
}

TEST(Export, GlslEsHasNoDesktopOnlySpelling) {
    const std::string es =
        export_fragment_glsl(GlintModelId::Deliot2023, 1, ExportLanguage::GlslEs);
    EXPECT_EQ(es.rfind("#version 300 es", 0), 0u);
    EXPECT_EQ(es.find("dFdxFine"), std::string::npos);
    EXPECT_EQ(es.find("layout(binding"), std::string::npos);
    EXPECT_NE(es.find("uniform sampler2D u_deliot2023_noise"), std::string::npos);
}

TEST(Export, BadRequestsAreClearErrors) {
    testing::ScratchDir dir;
    ExportOptions o;
    o.out_dir = dir / "out";
    o.model = "nope";
    try {
        export_model(o);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("deliot2023"), std::string::npos) << e.what();
    }
    o.model = "jakob2014";  // CPU only
    try {
        export_model(o);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("jakob2014"), std::string::npos) << e.what();
    }
    try {
        parse_export_language("glsl330");
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("glsles"), std::string::npos) << e.what();
    }
}

// Exports kneiphof2025 (GLSL ES) with the maps of `env` into `out_dir`;
// returns the options used and the manifest.
std::pair<ExportOptions, nlohmann::json> export_kneiphof2025_with_env(const fs::path& out_dir,
                                                                      const fs::path& env) {
    ExportOptions o;
    o.model = "kneiphof2025";
    o.language = ExportLanguage::GlslEs;
    o.out_dir = out_dir;
    o.environment = env;
    export_model(o);
    return {o, nlohmann::json::parse(slurp(o.out_dir / "kneiphof2025.glsles.manifest.json"))};
}

// --env: kneiphof2025's prefiltered maps for a given environment, for hosts
// without compute shaders. A constant environment of radiance c: the
// prefiltered radiance is c at every texel and layer (the kernel's weights
// are normalised), to float rounding (1e-4 relative).
TEST(Export, Kneiphof2025EnvironmentMapsOfAConstantEnvironment) {
    testing::ScratchDir dir;
    const fs::path env = dir / "env.exr";
    write_image(Image(32, 16, glm::vec3(0.5f, 1.0f, 2.0f)), env);
    const auto [o, j] = export_kneiphof2025_with_env(dir / "out", env);
    std::set<std::string> uniforms;
    for (const auto& r : j.at("resources")) uniforms.insert(r.at("uniform").get<std::string>());
    for (const char* u : {"kneiphof2025_dfg_lut", "kneiphof2025_radiance_layers",
                          "kneiphof2025_weights_layers_a", "kneiphof2025_weights_layers_b"})
        EXPECT_TRUE(uniforms.contains(u)) << u;
    const std::string rad = slurp(o.out_dir / "kneiphof2025.env_radiance.f32");
    ASSERT_EQ(rad.size() % 16, 0u);
    const float* t = reinterpret_cast<const float*>(rad.data());
    const size_t texels = rad.size() / 16;
    ASSERT_GT(texels, 0u);
    for (size_t i = 0; i < texels; i += 97) {
        EXPECT_NEAR(t[4 * i + 0], 0.5f, 1e-4f * 0.5f) << i;
        EXPECT_NEAR(t[4 * i + 1], 1.0f, 1e-4f) << i;
        EXPECT_NEAR(t[4 * i + 2], 2.0f, 2e-4f) << i;
        EXPECT_EQ(t[4 * i + 3], 0.0f) << i;  // no source: the sources channel is 0
    }
    // No source: the derived uniforms say none.
    bool counted = false;
    for (const auto& u : j.at("derived_uniforms")) {
        if (u.at("uniform") == "u_kneiphof2025_source_count") {
            EXPECT_EQ(u.at("value"), 0);
            counted = true;
        }
    }
    EXPECT_TRUE(counted);
}

// The "lobe_sun" smooth term (the default) reads the environment's bright
// sources from the radiance array's alpha and the u_kneiphof2025_source*
// uniforms: the export carries both, those of the renderer's prefilter
// (kneiphof2025_gpu.cpp uploads the same). A map of radiance 0.2 with a
// small sun: 2 x 2 texels of (5000, 4000, 3000) centred on theta = 45 deg,
// u = 0.75 of the map's frame.
TEST(Export, Kneiphof2025EnvironmentMapsCarryTheSources) {
    constexpr double kPi = 3.14159265358979323846;
    testing::ScratchDir dir;
    const fs::path env = dir / "sun.exr";
    Image sky(128, 64, glm::vec3(0.2f));
    for (int y = 15; y <= 16; ++y)
        for (int x = 95; x <= 96; ++x) sky.at(x, y) = glm::vec3(5000.0f, 4000.0f, 3000.0f);
    write_image(sky, env);
    const auto [o, j] = export_kneiphof2025_with_env(dir / "out", env);
    std::map<std::string, nlohmann::json> derived;
    for (const auto& u : j.at("derived_uniforms")) derived[u.at("uniform")] = u.at("value");
    EXPECT_EQ(derived.at("u_kneiphof2025_smooth"), 2);  // KNEIPHOF2025_SMOOTH_LOBE_SUN

    // The renderer's prefilter of the same map (default K and black level).
    const Kneiphof2025Environment pre(EnvironmentMap(read_image(env), 1.0f, 0.0f),
                                      Kneiphof2025PrefilterOptions{});
    const Kneiphof2025Sources& src = pre.sources();
    const size_t n = src.directions.size();
    ASSERT_EQ(n, size_t(Kneiphof2025Sources::kSamples));
    EXPECT_EQ(derived.at("u_kneiphof2025_source_count"), n);
    auto expect_vec3 = [](const nlohmann::json& v, glm::vec3 want, const std::string& what) {
        ASSERT_EQ(v.size(), 3u) << what;
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(v[c].get<double>(), want[c], 1e-6 * (1.0 + std::abs(want[c]))) << what;
    };
    ASSERT_EQ(derived.at("u_kneiphof2025_source_direction").size(), n);
    ASSERT_EQ(derived.at("u_kneiphof2025_source_power").size(), n);
    ASSERT_EQ(derived.at("u_kneiphof2025_source_radius").size(), n);
    expect_vec3(derived.at("u_kneiphof2025_sources_color"), src.color, "color");
    glm::dvec3 power(0.0);
    for (size_t k = 0; k < n; ++k) {
        const std::string at = "source " + std::to_string(k);
        expect_vec3(derived.at("u_kneiphof2025_source_direction")[k], src.map_directions[k], at);
        expect_vec3(derived.at("u_kneiphof2025_source_power")[k], src.powers[k], at);
        EXPECT_NEAR(derived.at("u_kneiphof2025_source_radius")[k].get<double>(), src.radii[k], 1e-7)
            << at;
        // ... and they lie in the sun of the map: direction (sin 45, cos 45, 0)
        // (u = 0.5 + atan2(x, -z) / 2 pi), within its 2 x 2 texels of 2.8 deg
        // (3.4 deg from the centre to a corner) and the half source texel
        // (1.4 deg) the bilinear resampling to 256 x 128 spreads it by.
        const glm::dvec3 centre(std::sin(kPi / 4.0), std::cos(kPi / 4.0), 0.0);
        EXPECT_GT(glm::dot(glm::dvec3(src.map_directions[k]), centre), std::cos(5.0 * kPi / 180.0))
            << at;
        EXPECT_GT(src.radii[k], 0.0f) << at;
        EXPECT_LT(src.radii[k], 0.02f) << at;
        power += glm::dvec3(src.powers[k]);
    }
    // The power above the sky: 4 texels' solid angle times (5000 - 0.2), to
    // the resampling to 256 x 128 (the prefilter's base level).
    const double texel = (2.0 * kPi / 128.0) * (kPi / 64.0) * std::sin(kPi / 4.0);
    EXPECT_NEAR(power.x, 4.0 * texel * 4999.8, 0.2 * 4.0 * texel * 4999.8);

    // The radiance's alpha is the sources channel of every layer.
    nlohmann::json info;
    for (const auto& r : j.at("resources"))
        if (r.at("uniform") == "kneiphof2025_radiance_layers") info = r;
    const int w = info.at("width"), h = info.at("height"), layers = info.at("layers");
    const std::string rad = slurp(o.out_dir / "kneiphof2025.env_radiance.f32");
    ASSERT_EQ(rad.size(), size_t(w) * size_t(h) * size_t(layers) * 16u);
    ASSERT_EQ(pre.source_mips().size(), size_t(layers));
    const float* t = reinterpret_cast<const float*>(rad.data());
    float base_max = 0.0f;
    size_t mismatches = 0;
    for (int i = 0; i < layers; ++i) {
        const Kneiphof2025Level& l = pre.source_mips()[size_t(i)];
        ASSERT_EQ(l.width, w);
        ASSERT_EQ(l.height, h);
        for (size_t p = 0; p < size_t(w) * size_t(h); ++p) {
            const float a = t[(size_t(i) * size_t(w) * size_t(h) + p) * 4 + 3];
            mismatches += a != l.data[p];
            if (i == 0) base_max = std::max(base_max, a);
        }
    }
    EXPECT_EQ(mismatches, 0u);
    EXPECT_GT(base_max, 1000.0f);  // the sun's luminance above the sky (~4140) at layer 0
}

// --scene / --material: the resources and values of a scene material. Two
// wang2020 materials with the same (small, fast) tables resolution: "plain"
// keeps the default alpha and seed (ln N 14: wang2020's range ends at 19.4),
// "sparkle" changes alpha, density and seed.
// Each manifest records its material's values, and the tables built for the
// default glint values differ from those of "sparkle" (other DPF lobe,
// other particles): the export does not fall back to the defaults.
constexpr const char* kMaterialsScene = R"({
  "film": {"width": 16, "height": 16},
  "camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "fov_deg": 45},
  "materials": [
    {"name": "plain", "type": "glint", "model": "wang2020", "ndf": "beckmann", "log_density": 14,
     "wang2020": {"dpf_theta": 8, "dpf_phi": 16, "depth": 6}},
    {"name": "sparkle", "type": "glint", "model": "wang2020", "ndf": "beckmann",
     "roughness": 0.25, "log_density": 12, "seed": 7,
     "fresnel": {"type": "schlick", "f0": [0.9, 0.8, 0.7]},
     "wang2020": {"dpf_theta": 8, "dpf_phi": 16, "depth": 6, "gamma_deg": 4}},
    {"name": "paint", "type": "diffuse"},
    {"name": "shiny", "type": "glint", "model": "kneiphof2025", "ndf": "ggx"}
  ],
  "shapes": [{"name": "s", "type": "sphere", "radius": 1.0, "material": "sparkle"}],
  "lights": [{"type": "point", "position": [2, 2, 3], "intensity": 20}]
})";

TEST(Export, Wang2020SceneMaterialTablesAndValues) {
    testing::ScratchDir dir;
    const fs::path scene = dir / "materials.json";
    { std::ofstream(scene) << kMaterialsScene; }
    auto run = [&](const std::string& material) {
        ExportOptions o;
        o.model = "wang2020";
        o.out_dir = dir / material;
        o.scene = scene;
        o.material = material;
        export_model(o);
        return nlohmann::json::parse(slurp(o.out_dir / "wang2020.glsl.manifest.json"));
    };
    const nlohmann::json plain = run("plain"), sparkle = run("sparkle");
    EXPECT_EQ(sparkle.at("material").at("name"), "sparkle");
    const auto& u = sparkle.at("material").at("uniforms");
    EXPECT_FLOAT_EQ(u.at("u_glint_alpha")[0].get<float>(), 0.25f);
    EXPECT_FLOAT_EQ(u.at("u_glint_log_density").get<float>(), 12.0f);
    EXPECT_EQ(u.at("u_glint_seed").get<uint32_t>(), 7u);
    EXPECT_FLOAT_EQ(plain.at("material").at("uniforms").at("u_glint_alpha")[0].get<float>(), 0.3f);
    // Parameter values: the material's, next to the descriptor's default.
    for (const auto& p : sparkle.at("parameters")) {
        if (p.at("key") == "gamma_deg") {
            EXPECT_DOUBLE_EQ(p.at("value").get<double>(), 4.0);
            EXPECT_DOUBLE_EQ(p.at("default").get<double>(), 1.0);
        }
        if (p.at("key") == "dpf_theta") {
            EXPECT_EQ(p.at("value").get<int>(), 8);
        }
    }
    // The tables' uniforms follow the material (cos gamma of 4 degrees).
    nlohmann::json tables;
    for (const auto& r : sparkle.at("resources"))
        if (r.contains("uniforms")) tables = r.at("uniforms");
    ASSERT_FALSE(tables.is_null());
    EXPECT_EQ(tables.at("u_wang2020_seed").get<uint32_t>(), 7u);
    EXPECT_NEAR(tables.at("u_wang2020_cos_gamma").get<double>(), std::cos(4.0 * M_PI / 180.0),
                1e-12);
    EXPECT_EQ(tables.at("u_wang2020_dpf_res")[0].get<int>(), 8);
    // The prefiltered table integrates the material's Fresnel: its values
    // are the tables' too (a host must not shade them with another).
    EXPECT_EQ(tables.at("u_fresnel_mode").get<int>(), 1);
    EXPECT_FLOAT_EQ(tables.at("u_fresnel_f0")[2].get<float>(), 0.7f);
    for (const char* t : {"wang2020.dpf.f32", "wang2020.nodes.u32"}) {
        const std::string a = slurp(dir / "plain" / t), b = slurp(dir / "sparkle" / t);
        EXPECT_FALSE(a.empty()) << t;
        EXPECT_NE(a, b) << t << " is the same for both materials";
    }
}

// Bad --scene/--material requests name the file, the material and the problem.
TEST(Export, SceneMaterialErrorsNameFileAndMaterial) {
    testing::ScratchDir dir;
    const fs::path scene = dir / "materials.json";
    { std::ofstream(scene) << kMaterialsScene; }
    auto error = [&](const std::string& model, const std::string& material, bool with_scene) {
        ExportOptions o;
        o.model = model;
        o.out_dir = dir / "out";
        o.resources = false;
        if (with_scene) o.scene = scene;
        o.material = material;
        try {
            export_model(o);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    std::string e = error("wang2020", "nope", true);
    EXPECT_NE(e.find("materials.json"), std::string::npos) << e;
    EXPECT_NE(e.find("\"nope\""), std::string::npos) << e;
    EXPECT_NE(e.find("sparkle"), std::string::npos) << e;  // lists what exists
    e = error("wang2020", "paint", true);
    EXPECT_NE(e.find("\"paint\""), std::string::npos) << e;
    EXPECT_NE(e.find("not a glint material"), std::string::npos) << e;
    e = error("wang2020", "shiny", true);
    EXPECT_NE(e.find("uses model \"kneiphof2025\""), std::string::npos) << e;
    EXPECT_NE(e.find("materials.json"), std::string::npos) << e;
    e = error("deliot2023", "", true);
    EXPECT_NE(e.find("no glint material of model \"deliot2023\""), std::string::npos) << e;
    e = error("wang2020", "sparkle", false);
    EXPECT_NE(e.find("needs --scene"), std::string::npos) << e;
}

// D3D's y runs down the image, OpenGL's up: the exported HLSL (SPIRV-Cross
// maps dFdyFine to ddy_fine) computes duvdy = -ddy_fine(uv), the mirror of
// the GLSL footprint's. Every model's footprint NDF depends on duvdy only
// through sign-free forms (the J J^T ellipse of deliot2023, zirr2016 and
// chermain2020 — products of two duvdy components —, |det J|, and
// wang2020's AABB |duvdx| + |duvdy|), so negating duvdy must give the same
// D_P to the bit (IEEE negation is exact, (-a)(-b) = ab exactly). Checked
// on the shared shader functions through the CPU renderer's GlintBxdf over
// 64 half vectors (wang2020 needs its tables; its AABB uses abs() only).
TEST(Export, FootprintNdfIgnoresTheSignOfDuvdy) {
    for (GlintModelId id : {GlintModelId::Smooth, GlintModelId::Deliot2023, GlintModelId::Zirr2016,
                            GlintModelId::Chermain2020, GlintModelId::Kneiphof2025}) {
        GlintDesc g;
        switch_glint_model(g, id);
        g.log_density = 12.0f;
        GlintBxdf up, down;
        up.desc = down.desc = &g;
        up.has_footprint = down.has_footprint = true;
        up.footprint.uv = glm::vec2(0.3f, 0.7f);
        up.footprint.duvdx = glm::vec2(0.004f, 0.001f);
        up.footprint.duvdy = glm::vec2(-0.0015f, 0.003f);
        down.footprint = up.footprint;
        down.footprint.duvdy = -up.footprint.duvdy;
        int nonzero = 0;
        const glm::vec3 wo = glm::normalize(glm::vec3(0.2f, -0.3f, 0.9f));
        for (int i = 0; i < 64; ++i) {
            // Half vectors within ~0.35 rad of the normal (where glints are).
            const float a = 0.35f * static_cast<float>(i % 8) / 8.0f;
            const float phi = 6.2831853f * static_cast<float>(i / 8) / 8.0f;
            const glm::vec3 h(std::sin(a) * std::cos(phi), std::sin(a) * std::sin(phi),
                              std::cos(a));
            const glm::vec3 wi = glm::reflect(-wo, h);
            if (wi.z <= 0.0f) continue;
            const float du = up.footprint_ndf(wo, wi, h), dd = down.footprint_ndf(wo, wi, h);
            EXPECT_EQ(du, dd) << glint_model(id).name << " h " << i;
            nonzero += du > 0.0f;
        }
        EXPECT_GT(nonzero, 0) << glint_model(id).name;  // the check saw glints
    }
}

}  // namespace
}  // namespace glintlab
