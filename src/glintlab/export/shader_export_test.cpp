// `glintlab export` (export/shader_export.h): every exported file compiles on
// its own (GLSL 4.50 and GLSL ES 3.00 with glslangValidator, HLSL with
// glslang's HLSL front end), carries no include or project macro, is made
// from the renderer's own glue, and the manifest lists files that exist with
// the sizes it states.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "glintlab/core/error.h"
#include "glintlab/core/image.h"
#include "glintlab/core/image_test_util.h"
#include "glintlab/core/shader_sources.h"
#include "glintlab/export/shader_export.h"
#include "glintlab/glints/registry.h"

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
        while (std::getline(lines, line)) {
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

// --env: kneiphof2025's prefiltered maps for a given environment, for hosts
// without compute shaders. A constant environment of radiance c: the
// prefiltered radiance is c at every texel and layer (the kernel's weights
// are normalised), to float rounding (1e-4 relative).
TEST(Export, Kneiphof2025EnvironmentMapsOfAConstantEnvironment) {
    testing::ScratchDir dir;
    const fs::path env = dir / "env.exr";
    write_image(Image(32, 16, glm::vec3(0.5f, 1.0f, 2.0f)), env);
    ExportOptions o;
    o.model = "kneiphof2025";
    o.language = ExportLanguage::GlslEs;
    o.out_dir = dir / "out";
    o.environment = env;
    export_model(o);
    const nlohmann::json j =
        nlohmann::json::parse(slurp(o.out_dir / "kneiphof2025.glsles.manifest.json"));
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
    }
}

}  // namespace
}  // namespace glintlab
