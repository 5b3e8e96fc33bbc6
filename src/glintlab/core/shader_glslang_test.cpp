// Every shared .glsl file must be valid GLSL 4.50 on its own (with its
// includes), so C++-only constructs cannot creep into shared shading code.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "glintlab/core/shader_assembly.h"
#include "glintlab/core/shader_sources.h"

namespace glintlab {
namespace {

struct ValidatorResult {
    int status;
    std::string log;
};

ValidatorResult run_glslang(const std::string& text, const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("glintlab_glslang_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto src = dir / (name + ".frag");
    const auto log = dir / (name + ".log");
    std::ofstream(src) << text;
    const std::string cmd = std::string(GLSLANG_VALIDATOR) + " -S frag " + src.string() + " > " +
                            log.string() + " 2>&1";
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

TEST(ShaderGlslang, EverySharedFileCompilesAsGlsl450) {
    ASSERT_FALSE(shader_sources().empty());
    for (const ShaderSource& source : shader_sources()) {
        AssembledShader shader = assemble_shader(source.path);
        shader.text += "\nvoid main() {}\n";
        const ValidatorResult r = run_glslang(shader.text, safe_name(source.path));
        EXPECT_EQ(r.status, 0) << source.path << ":\n" << map_shader_log(shader, r.log);
    }
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
