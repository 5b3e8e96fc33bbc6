// Every .glsl file must be valid GLSL 4.50 on its own (with its includes), so
// C++-only constructs cannot creep into shared shading code. Files named
// *.vert.glsl, *.frag.glsl, *.comp.glsl are whole shader stages (with their own
// main) and are validated as that stage; the others are libraries, validated
// as a fragment shader with an empty main. A stage file that needs defines or
// a glue file ahead of it gets them from kStagePrefixes (the forward pass:
// every model glue, glints/**/*_gpu.glsl, with and without each light kind).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "glintlab/core/shader_assembly.h"
#include "glintlab/core/shader_sources.h"

namespace glintlab {
namespace {

struct ValidatorResult {
    int status;
    std::string log;
};

// `stage`: glslangValidator's stage name (vert, frag, comp). -l links the
// stage, as a driver does: a called function without a body is an error.
ValidatorResult run_glslang(const std::string& text, const std::string& name,
                            const std::string& stage = "frag") {
    const auto dir =
        std::filesystem::temp_directory_path() / ("glintlab_glslang_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto src = dir / (name + "." + stage);
    const auto log = dir / (name + ".log");
    std::ofstream(src) << text;
    const std::string cmd = std::string(GLSLANG_VALIDATOR) + " -l -S " + stage + " " +
                            src.string() + " > " + log.string() + " 2>&1";
    const int status = std::system(cmd.c_str());
    std::ifstream in(log);
    std::string out((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return {status, out};
}

std::string safe_name(std::string_view path) {
    std::string s(path);
    for (char& c : s)
        if (c == '/' || c == '.') c = '_';
    return s;
}

bool ends_with(std::string_view s, std::string_view suffix) {
    return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

// The stage of a file named <name>.<stage>.glsl; empty for a library file.
std::string stage_of(std::string_view path) {
    for (const char* stage : {"vert", "frag", "comp"})
        if (ends_with(path, std::string(".") + stage + ".glsl")) return stage;
    return {};
}

// The model glue files of the forward pass (realtime/glint_programs.cpp).
std::vector<std::string> glue_files() {
    std::vector<std::string> out;
    for (const ShaderSource& s : shader_sources())
        if (ends_with(s.path, "_gpu.glsl")) out.emplace_back(s.path);
    return out;
}

// What realtime/forward_shaders.cpp puts ahead of forward.frag.glsl: the
// light counts and sample counts, then the glue of one model. Every glue with
// no lights and with every light kind (sphere and cone lights included: the
// glue's GLINTLAB_GLINT_SHADES_AREA_LIGHTS branches); with every light kind
// also the textured-material variant (GLINTLAB_MATERIAL_TEXTURES) and the
// normal-mapped one (GLINTLAB_NORMAL_MAP with it).
std::vector<std::string> forward_prefixes() {
    std::vector<std::string> out;
    for (const std::string& glue : glue_files())
        for (const int lights : {0, 1, 2, 3}) {
            const int points = lights > 0 ? 2 : 0, directionals = lights > 0 ? 1 : 0;
            const int environment = lights > 0 ? 1 : 0;
            out.push_back(fmt::format(
                "#define GLINTLAB_POINT_LIGHTS {}\n#define GLINTLAB_DIRECTIONAL_LIGHTS {}\n"
                "#define GLINTLAB_ENVIRONMENT {}\n#define GLINTLAB_ENV_SPECULAR_SAMPLES 4\n"
                "#define GLINTLAB_ENV_DIFFUSE_SAMPLES 4\n#define GLINTLAB_ENV_DEFENSIVE_SAMPLES 4\n"
                "#define GLINTLAB_ENV_SOURCE_SAMPLES 4\n"
                "{}#include \"{}\"\n",
                points, directionals, environment,
                lights == 2 ? "#define GLINTLAB_MATERIAL_TEXTURES 1\n"
                : lights == 3
                    ? "#define GLINTLAB_MATERIAL_TEXTURES 1\n#define GLINTLAB_NORMAL_MAP 1\n"
                    : "",
                glue));
        }
    return out;
}

// `glintlab export`'s fragment stage (export/shader_export.h): after any
// glue, with the per-pixel inputs' GLINTLAB_MATERIAL_TEXTURES as the
// exporter puts it ahead.
std::vector<std::string> export_prefixes() {
    std::vector<std::string> out;
    for (const std::string& glue : glue_files())
        out.push_back(fmt::format("#define GLINTLAB_MATERIAL_TEXTURES 1\n#include \"{}\"\n", glue));
    return out;
}

const std::map<std::string, std::vector<std::string>>& stage_prefixes() {
    static const std::map<std::string, std::vector<std::string>> table = {
        {"glintlab/realtime/shaders/forward.frag.glsl", forward_prefixes()},
        {"glintlab/export/glint_export.frag.glsl", export_prefixes()},
    };
    return table;
}

TEST(ShaderGlslang, EverySharedFileCompilesAsGlsl450) {
    ASSERT_FALSE(shader_sources().empty());
    int stage_files = 0;
    for (const ShaderSource& source : shader_sources()) {
        const std::string stage = stage_of(source.path);
        if (!stage.empty()) {
            ++stage_files;
            continue;
        }
        AssembledShader shader = assemble_shader(source.path);
        shader.text += "\nvoid main() {}\n";
        const ValidatorResult r = run_glslang(shader.text, safe_name(source.path));
        EXPECT_EQ(r.status, 0) << source.path << ":\n" << map_shader_log(shader, r.log);
    }
    // The forward, background, tonemap, shadow, bloom and model passes.
    EXPECT_GE(stage_files, 14);
}

TEST(ShaderGlslang, EveryStageFileCompilesAsItsStage) {
    int checked = 0;
    for (const ShaderSource& source : shader_sources()) {
        const std::string stage = stage_of(source.path);
        if (stage.empty()) continue;
        const auto it = stage_prefixes().find(std::string(source.path));
        const std::vector<std::string> prefixes =
            it != stage_prefixes().end() ? it->second : std::vector<std::string>{""};
        ASSERT_FALSE(prefixes.empty()) << source.path;
        for (size_t i = 0; i < prefixes.size(); ++i) {
            const std::string root = prefixes[i] + fmt::format("#include \"{}\"\n", source.path);
            const AssembledShader shader = assemble_shader(root, true);
            const ValidatorResult r =
                run_glslang(shader.text, safe_name(source.path) + std::to_string(i), stage);
            EXPECT_EQ(r.status, 0) << source.path << " (" << stage << ", prefix:\n"
                                   << prefixes[i] << "):\n"
                                   << map_shader_log(shader, r.log);
            ++checked;
        }
    }
    // Six model glues (smooth, deliot2023 and its noise texture, zirr2016,
    // chermain2020, kneiphof2025, wang2020) x 2 light sets for the forward pass.
    EXPECT_GE(glue_files().size(), 7u);
    EXPECT_GE(checked, 14 + 2 * 7 - 1);
}

TEST(ShaderGlslang, ForwardPassWithoutGlueIsRejected) {
    // Guards the prefix table and the linking: with lights, the forward pass
    // calls eval_bsdf, which needs a glue's glint_ndf (material.glsl only
    // declares it), so without a glue it must fail to link.
    const AssembledShader shader = assemble_shader(
        "#define GLINTLAB_POINT_LIGHTS 1\n#define GLINTLAB_DIRECTIONAL_LIGHTS 0\n"
        "#define GLINTLAB_ENVIRONMENT 0\n"
        "#include \"glintlab/realtime/shaders/forward.frag.glsl\"\n",
        true);
    const ValidatorResult r = run_glslang(shader.text, "forward_without_glue", "frag");
    EXPECT_NE(r.status, 0) << r.log;
    EXPECT_NE(r.log.find("glint_ndf"), std::string::npos) << r.log;
}

TEST(ShaderGlslang, CppOnlyConstructIsRejected) {
    // Guards the guard: a reference parameter is C++ and must fail glslang.
    AssembledShader shader =
        assemble_shader("float f(float& x) { return x; }\nvoid main() {}\n", true);
    const ValidatorResult r = run_glslang(shader.text, "reject_reference");
    EXPECT_NE(r.status, 0) << r.log;
}

TEST(ShaderAssembly, IncludesResolvedOnceWithLineDirectives) {
    const AssembledShader shader = assemble_shader(
        "#include \"glintlab/core/hash.glsl\"\n#include \"glintlab/core/hash.glsl\"\nfloat x;\n",
        true);
    ASSERT_EQ(shader.files.size(), 2u);
    EXPECT_EQ(shader.files[1], "glintlab/core/hash.glsl");
    EXPECT_NE(shader.text.find("#line 1 1"), std::string::npos);
    EXPECT_NE(shader.text.find("#line 2 0"), std::string::npos);
    EXPECT_EQ(shader.text.find("uint pcg_hash"), shader.text.rfind("uint pcg_hash"));
}

TEST(ShaderAssembly, LogLocationsMapToFiles) {
    AssembledShader shader;
    shader.files = {"<inline>", "glintlab/core/hash.glsl"};
    EXPECT_EQ(map_shader_log(shader, "ERROR: 1:17: 'x' : undeclared"),
              "ERROR: glintlab/core/hash.glsl:17: 'x' : undeclared");
    EXPECT_EQ(map_shader_log(shader, "0(3) : error C0000"), "<inline>:3 : error C0000");
}

TEST(ShaderAssembly, MissingIncludeIsAClearError) {
    try {
        assemble_shader("#include \"glintlab/nope.glsl\"\n", true);
        FAIL() << "expected an error";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("glintlab/nope.glsl"), std::string::npos);
    }
}

}  // namespace
}  // namespace glintlab
