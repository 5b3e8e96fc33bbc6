// End-to-end checks of the `glintlab` executable: bad input gives a clear
// message and a non-zero exit status, never a crash; a render writes files.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "glintlab/core/image.h"
#include "glintlab/glints/model_docs.h"
#include "glintlab/glints/registry.h"

namespace {

using namespace glintlab;

struct RunResult {
    int status;
    std::string output;
};

RunResult run_cli(const std::string& args) {
    const std::string cmd = std::string(GLINTLAB_CLI_PATH) + " " + args + " 2>&1";
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return {-1, "popen failed"};
    std::string out;
    std::array<char, 4096> buf;
    size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) out.append(buf.data(), n);
    const int raw = pclose(pipe);
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw), out};
}

std::filesystem::path temp_dir() {
    const auto dir =
        std::filesystem::temp_directory_path() / ("glintlab_cli_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

std::filesystem::path write_file(const std::string& name, const std::string& text) {
    const auto p = temp_dir() / name;
    std::ofstream(p) << text;
    return p;
}

const char* kSmallScene = R"({
  "film": {"width": 24, "height": 16},
  "camera": {"eye": [0, 1, 4], "target": [0, 0.5, 0], "fov_deg": 40},
  "render": {"integrator": "path", "spp": 2},
  "materials": [{"name": "m", "type": "glint", "model": "smooth", "roughness": 0.3}],
  "shapes": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5, "material": "m"}],
  "lights": [{"type": "environment", "radiance": 0.5}, {"type": "point", "position": [1, 3, 2], "intensity": 5}]
})";

TEST(Cli, RenderWritesExrAndPng) {
    const auto scene = write_file("small.json", kSmallScene);
    const auto out = temp_dir() / "small.exr";
    const RunResult r = run_cli("render " + scene.string() + " -o " + out.string() + " --quiet");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(out));
    EXPECT_TRUE(std::filesystem::exists(temp_dir() / "small.png"));
    EXPECT_EQ(r.output, "");  // --quiet prints nothing
}

TEST(Cli, BadInputGivesClearErrors) {
    const auto scene = write_file("ok.json", kSmallScene);
    const auto bad_key =
        write_file("bad_key.json", R"({"camera": {"eye": [0,0,1]}, "cameras": 1})");
    const auto bad_json = write_file("bad_json.json", "{ not json");
    const auto bad_model = write_file(
        "bad_model.json",
        R"({"camera": {}, "materials": [{"name": "m", "type": "glint", "model": "nope"}]})");
    struct Case {
        std::string args;
        std::vector<std::string> expected;
    };
    const std::vector<Case> cases = {
        {"render /nonexistent/scene.json", {"scene.json"}},
        {"render " + bad_key.string(), {"bad_key.json", "/cameras", "unknown key"}},
        {"render " + bad_json.string(), {"bad_json.json", "invalid JSON"}},
        {"render " + bad_model.string(), {"bad_model.json", "/materials/0/model", "smooth"}},
        {"render " + scene.string() + " --res 0x5", {"--res", "[1, 16384]"}},
        {"render " + scene.string() + " --res banana", {"--res", "WxH"}},
        {"render " + scene.string() + " --spp 0", {"--spp"}},
        {"render " + scene.string() + " --integrator bdpt", {"--integrator"}},
        // The output's parent is a regular file, so no directory can be made there.
        {"render " + scene.string() + " -o " + scene.string() + "/y.exr --quiet",
         {"cannot create the output directory"}},
        {"frobnicate", {"frobnicate"}},
        {"validate no_such_suite", {"no_such_suite"}},
        {"validate compare --scenes no_such_scene", {"no_such_scene", "sphere_city"}},
        // Lists are comma- or space-separated, as compare's --models.
        {"validate compare --scenes sphere_city,no_such_scene",
         {"unknown scene \"no_such_scene\""}},
        {"validate counting --scenes sphere_city", {"--scenes", "compare"}},
        {"validate counting --models deliot2023", {"--models", "robustness", "compare"}},
        {"export nope", {"\"nope\"", "deliot2023"}},
        {"export jakob2014", {"jakob2014", "exportable"}},
        {"export deliot2023 --lang glsl330", {"--lang", "glsles"}},
        {"export deliot2023 -o " + scene.string() + "/sub", {"cannot create output directory"}},
    };
    for (const Case& c : cases) {
        const RunResult r = run_cli(c.args);
        EXPECT_NE(r.status, 0) << c.args << "\n" << r.output;
        EXPECT_LT(r.status, 128) << "crashed: " << c.args << "\n" << r.output;
        for (const std::string& e : c.expected)
            EXPECT_NE(r.output.find(e), std::string::npos)
                << c.args << ": expected \"" << e << "\" in:\n"
                << r.output;
    }
}

TEST(Cli, ExportWritesTheShaderAndManifest) {
    const auto dir = temp_dir() / "export";
    const RunResult r = run_cli("export smooth --lang glsles -o " + dir.string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "smooth.glsles.frag.glsl"));
    EXPECT_TRUE(std::filesystem::exists(dir / "smooth.glsles.manifest.json"));
    EXPECT_NE(r.output.find("smooth.glsles.frag.glsl"), std::string::npos) << r.output;
}

TEST(Cli, ValidateCountingJsonFollowsTheContract) {
    const RunResult r = run_cli("validate counting --json");
    ASSERT_EQ(r.status, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_EQ(j.at("suite"), "counting");
    ASSERT_TRUE(j.at("checks").is_array());
    for (const auto& c : j.at("checks")) {
        EXPECT_TRUE(c.contains("name") && c.contains("value") && c.contains("limit") &&
                    c.contains("pass"))
            << c;
        EXPECT_TRUE(c.at("pass").get<bool>()) << c;
    }
}

TEST(Cli, BenchJsonListsMinMaxPerSceneAndModel) {
    const RunResult r =
        run_cli("bench --scene PLANE_25 SPHERE --model smooth --res 16x12 --frames 1 --json");
    ASSERT_EQ(r.status, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    ASSERT_EQ(j.at("results").size(), 2u);
    for (const auto& row : j.at("results")) {
        EXPECT_EQ(row.at("model"), "smooth");
        EXPECT_GT(row.at("min_ms").get<double>(), 0.0);
        EXPECT_GE(row.at("max_ms").get<double>(), row.at("min_ms").get<double>());
        EXPECT_EQ(row.at("ms_per_density").size(), j.at("log_densities").size());
    }
    const RunResult bad = run_cli("bench --scene NOPE --frames 1");
    EXPECT_NE(bad.status, 0);
    EXPECT_NE(bad.output.find("unknown scene \"NOPE\""), std::string::npos) << bad.output;
    const RunResult bad_model = run_cli("bench --model nope --frames 1");
    EXPECT_NE(bad_model.output.find("unknown model \"nope\""), std::string::npos)
        << bad_model.output;
}

TEST(Cli, InfoListsModelsAndHelpWorks) {
    const RunResult info = run_cli("info");
    EXPECT_EQ(info.status, 0);
    EXPECT_NE(info.output.find("smooth"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find("not log_density, roughness, base_albedo: its quadtree"),
              std::string::npos)
        << info.output;
    const RunResult help = run_cli("render --help");
    EXPECT_EQ(help.status, 0);
    EXPECT_NE(help.output.find("--spp"), std::string::npos) << help.output;
}

TEST(Cli, InfoJsonAndMarkdownComeFromTheDescriptors) {
    const RunResult r = run_cli("info --json");
    ASSERT_EQ(r.status, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_EQ(j.at("version"), GLINTLAB_VERSION);
    EXPECT_TRUE(j.at("features").contains("cpu renderer"));
    ASSERT_EQ(j.at("models").size(), glint_models().size());
    for (size_t i = 0; i < glint_models().size(); ++i)
        EXPECT_EQ(j.at("models")[i], glint_model_to_json(glint_models()[i]));
    const RunResult md = run_cli("info --markdown parameters");
    ASSERT_EQ(md.status, 0) << md.output;
    EXPECT_EQ(md.output, model_doc_markdown("parameters"));
    EXPECT_NE(run_cli("info --markdown nope").status, 0);
}

TEST(Cli, ValidateListsEveryModelSuiteAndCounting) {
    const RunResult help = run_cli("validate --help");
    for (const GlintModelDescriptor& m : glint_models()) {
        if (m.validation.name.empty()) continue;
        EXPECT_NE(help.output.find(m.validation.name), std::string::npos) << help.output;
    }
    EXPECT_NE(help.output.find("counting"), std::string::npos) << help.output;
}

}  // namespace

// -o: the extension decides which file the path names (README "Output files"):
// X.png writes the preview there and X.exr beside it (never X.png.exr), a
// directory (trailing slash) gets <scene stem>.exr/.png, an unknown extension
// is refused before rendering.
TEST(Cli, OutputExtensionDecidesTheFormat) {
    namespace fs = std::filesystem;
    const auto scene = write_file("paths.json", kSmallScene);
    const fs::path dir = temp_dir() / "paths";
    fs::remove_all(dir);
    RunResult r = run_cli("render " + scene.string() + " -o " + (dir / "a.png").string() + " -q");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir / "a.png"));
    EXPECT_TRUE(fs::exists(dir / "a.exr"));
    EXPECT_FALSE(fs::exists(dir / "a.png.exr"));
    EXPECT_FALSE(fs::exists(dir / "a.png.png"));
    r = run_cli("render " + scene.string() + " -o " + (dir / "b.exr").string() + " -q");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir / "b.exr"));
    EXPECT_TRUE(fs::exists(dir / "b.png"));
    r = run_cli("render " + scene.string() + " -o " + (dir / "sub").string() + "/ -q");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir / "sub" / "paths.exr"));
    EXPECT_TRUE(fs::exists(dir / "sub" / "paths.png"));
    EXPECT_FALSE(fs::exists(dir / "sub" / ".exr"));
    // An existing directory without the slash is a directory too.
    r = run_cli("render " + scene.string() + " -o " + dir.string() + " -q");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir / "paths.exr"));
    r = run_cli("render " + scene.string() + " -o " + (dir / "c.jpg").string() + " -q");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find(".jpg"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(".exr"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "c.exr"));
}

// Options are validated before anything renders or is written: a NaN exposure
// used to write the EXR and then fail; an overflowing --res reported "0x1".
TEST(Cli, OptionsAreValidatedBeforeRendering) {
    namespace fs = std::filesystem;
    const auto scene = write_file("opts.json", kSmallScene);
    const fs::path out = temp_dir() / "opts" / "x.exr";
    fs::remove_all(out.parent_path());
    RunResult r = run_cli("render " + scene.string() + " -o " + out.string() + " --exposure nan");
    EXPECT_NE(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("--exposure"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
    r = run_cli("render " + scene.string() + " -o " + out.string() + " --exposure inf");
    EXPECT_NE(r.status, 0) << r.output;
    EXPECT_FALSE(fs::exists(out));
    r = run_cli("render " + scene.string() + " -o " + out.string() + " --res 99999999999x1");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("99999999999x1"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("[1, 16384]"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("got 0x1"), std::string::npos) << r.output;
    r = run_cli("render " + scene.string() + " -o " + out.string() + " --res 8x-3");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("8x-3"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
}

// render --model / --set: the edits change the image, a bad pointer fails
// before anything is written and names the pointer, and --set takes one
// value per occurrence (the scene path after it is not swallowed).
TEST(Cli, ModelAndSetEditTheSceneBeforeLoading) {
    namespace fs = std::filesystem;
    const auto scene = write_file("edits.json", kSmallScene);
    const fs::path dir = temp_dir() / "edits";
    fs::remove_all(dir);
    // deliot2023 shades point and directional lights only: the environment
    // light is replaced by a second point light in the same command.
    const std::string point =
        R"('/lights/0={"type": "point", "position": [-2, 3, 2], "intensity": 5}')";
    RunResult r =
        run_cli("render -q --model deliot2023 --set /materials/0/log_density=12 --set " + point +
                " --set /film/width=16 " + scene.string() + " -o " + (dir / "a.exr").string());
    ASSERT_EQ(r.status, 0) << r.output;
    const Image a = read_image(dir / "a.exr");
    EXPECT_EQ(a.width, 16);
    r = run_cli("render -q --set " + point + " --set /film/width=16 " + scene.string() + " -o " +
                (dir / "b.exr").string());
    ASSERT_EQ(r.status, 0) << r.output;
    const Image b = read_image(dir / "b.exr");
    double diff = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) diff += std::abs(a.pixels[i].x - b.pixels[i].x);
    EXPECT_GT(diff, 0.0);  // deliot2023 at ln N = 12 sparkles; smooth does not
    r = run_cli("render -q --set /materials/3/x=1 " + scene.string() + " -o " +
                (dir / "c.exr").string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("/materials/3/x"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "c.exr"));
    r = run_cli("render -q --model nosuch " + scene.string() + " -o " + (dir / "d.exr").string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("nosuch"), std::string::npos) << r.output;
}

// A render estimated above the memory limit fails before allocating, naming
// the film and the estimate (a 16384² film needs ~19 GiB; here a tiny limit).
TEST(Cli, MemoryLimitRefusesTooBigRenders) {
    namespace fs = std::filesystem;
    const auto scene = write_file("mem.json", kSmallScene);
    const fs::path out = temp_dir() / "mem" / "x.exr";
    fs::remove_all(out.parent_path());
    RunResult r =
        run_cli("render " + scene.string() + " -o " + out.string() + " --memory-limit 1K");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("film 24x16"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("memory limit of 1.0 KiB"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
    r = run_cli("render " + scene.string() + " -o " + out.string() + " --memory-limit lots");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("--memory-limit"), std::string::npos) << r.output;
    // An empty size was taken as "no limit given".
    r = run_cli("render " + scene.string() + " -o " + out.string() + " --memory-limit ''");
    EXPECT_NE(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("--memory-limit"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
    // NaN passed CLI::Range (every comparison with NaN is false).
    for (const char* option : {"--exposure nan", "--exposure inf"}) {
        r = run_cli("render " + scene.string() + " -o " + out.string() + " " + option);
        EXPECT_NE(r.status, 0) << option << r.output;
        EXPECT_NE(r.output.find("not a finite number in [-20"), std::string::npos) << r.output;
    }
    ::setenv("GLINTLAB_MEMORY_LIMIT", "2K", 1);
    r = run_cli("render " + scene.string() + " -o " + out.string() + " -q");
    ::unsetenv("GLINTLAB_MEMORY_LIMIT");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("GLINTLAB_MEMORY_LIMIT"), std::string::npos) << r.output;
    r = run_cli("render " + scene.string() + " -o " + out.string() + " -q --memory-limit 1G");
    EXPECT_EQ(r.status, 0) << r.output;
}

// --no-cache is accepted (the tests run with GLINTLAB_NO_CACHE=1 anyway;
// the cache itself is tested in disk_cache_test.cpp / wang2020_cache_test.cpp).
TEST(Cli, NoCacheFlagIsAccepted) {
    const auto scene = write_file("nocache.json", kSmallScene);
    const auto out = temp_dir() / "nocache.exr";
    const RunResult r =
        run_cli("render " + scene.string() + " -o " + out.string() + " -q --no-cache");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(out));
}
