// `glintlab compare` end to end on a tiny scene: the files, the JSON keys,
// the models that cannot shade a light listed with the reason, bad options.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "glintlab/core/image.h"

namespace {

struct RunResult {
    int status;
    std::string output;
};

RunResult run(const std::string& args) {
    const std::string cmd = std::string(GLINTLAB_CLI_PATH) + " " + args;
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return {-1, "popen failed"};
    std::string out;
    std::array<char, 4096> buf;
    size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) out.append(buf.data(), n);
    const int raw = pclose(pipe);
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw), out};
}

// 24 x 24, ln density 12 (a few hundred facets per pixel: explicit is cheap
// and lit), a point and a sphere light: zirr2016 shades no sphere light.
const char* kScene = R"({
  "film": {"width": 24, "height": 24},
  "camera": {"eye": [0, 0, 3.2], "target": [0, 0, 0], "fov_deg": 45},
  "render": {"integrator": "direct", "spp": 2, "seed": 1},
  "materials": [{"name": "glitter", "type": "glint", "model": "explicit", "ndf": "ggx",
                 "roughness": 0.3, "log_density": 12, "fresnel": {"type": "none"}}],
  "shapes": [{"type": "sphere", "radius": 1, "material": "glitter"}],
  "lights": [{"type": "point", "position": [2, 2, 3], "intensity": 8},
             {"type": "sphere", "center": [-2, 1, 2], "radius": 0.3, "radiance": 10}]
})";

std::filesystem::path temp_dir() {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("glintlab_compare_cli_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

TEST(CompareCli, WritesTheFilesAndTheJsonTable) {
    const auto dir = temp_dir();
    const auto scene = dir / "tiny.json";
    std::ofstream(scene) << kScene;
    const auto out = dir / "out";
    const RunResult r = run("compare " + scene.string() +
                            " --models smooth,zirr2016,kneiphof2025 --realizations 2 --frames 2 "
                            "--flicker-paths 3 --truth-realizations 3 --json -o " +
                            out.string() + " 2>/dev/null");
    ASSERT_EQ(r.status, 0) << r.output;
    const nlohmann::json j = nlohmann::json::parse(r.output);  // stdout is the JSON alone
    for (const char* key :
         {"scene", "material", "lights", "width", "height", "spp", "realizations", "frames",
          "flicker_paths", "orbit_deg", "blur_sigma_px", "mask_pixels", "models"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j["width"], 24);
    EXPECT_EQ(j["realizations"], 2);
    EXPECT_EQ(j["truth_realizations"], 3);  // the explicit rows' own seeds
    EXPECT_EQ(j["flicker_paths"], 3);
    EXPECT_GT(j["mask_pixels"].get<int>(), 100);  // the sphere fills ~40 % of 576 pixels
    std::map<std::string, nlohmann::json> rows;
    for (const nlohmann::json& m : j["models"]) rows[m["model"]] = m;
    ASSERT_EQ(rows.size(), 4u);  // explicit (truth), smooth, zirr2016, kneiphof2025
    EXPECT_TRUE(rows["explicit"]["reference"].get<bool>());
    EXPECT_FALSE(rows["zirr2016"]["compared"].get<bool>());
    EXPECT_NE(rows["zirr2016"]["reason"].get<std::string>().find("sphere"), std::string::npos);
    for (const char* model : {"smooth", "kneiphof2025"}) {
        const nlohmann::json& m = rows[model];
        ASSERT_TRUE(m["compared"].get<bool>()) << model;
        for (const char* key :
             {"mean_rel_err", "mean_rel_err_se", "blurred_rel_rmse", "variance_ratio",
              "wasserstein", "flicker", "flicker_se", "flicker_ratio", "flicker_ratio_se",
              "seconds", "nan_count", "inf_count", "negative_count", "truth", "backend"})
            EXPECT_TRUE(m.contains(key)) << model << " " << key;
        EXPECT_EQ(m["nan_count"], 0) << model;
        EXPECT_EQ(m["negative_count"], 0) << model;
        // The error is finite and not absurd (a model off by 2x would be a
        // defect the suite reports; this test checks the plumbing).
        EXPECT_LT(std::abs(m["mean_rel_err"].get<double>()), 1.0) << model;
    }
    // smooth has no sparkle: its per-pixel variance over realizations (only
    // the pixel-position jitter of 2 spp) is far below explicit's, whose
    // facets change with the seed.
    EXPECT_LT(rows["smooth"]["variance_ratio"].get<double>(), 0.5);
    for (const char* f :
         {"grid.png", "metrics.json", "metrics.csv", "explicit.png", "explicit.exr", "smooth.png",
          "smooth_diff.png", "smooth_diff_blur.png", "kneiphof2025.png"})
        EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
    EXPECT_FALSE(std::filesystem::exists(out / "zirr2016.png"));
    // The difference images carry their colour legend (bar and labels) under
    // the enlarged image: 24 px wide, enlarged 6x to 144 x 144, + 22 rows.
    const glintlab::Image diff = glintlab::read_image(out / "smooth_diff.png");
    EXPECT_EQ(diff.width, 144);
    EXPECT_EQ(diff.height, 144 + 22);
    std::ifstream csv(out / "metrics.csv");
    std::string header;
    std::getline(csv, header);
    EXPECT_EQ(
        header.rfind(
            "model,compared,reference,backend,truth,facet_extent,mean_luminance,mean_rel_err,", 0),
        0u);
    std::filesystem::remove_all(dir);
}

TEST(CompareCli, BadOptionsNameTheOption) {
    const auto dir = temp_dir();
    const auto scene = dir / "tiny.json";
    std::ofstream(scene) << kScene;
    const std::string base = "compare " + scene.string() + " -o " + (dir / "o").string() + " ";
    RunResult r = run(base + "--models smooth,nosuch 2>&1");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("--models: unknown model \"nosuch\""), std::string::npos) << r.output;
    r = run(base + "--material nosuch 2>&1");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("--material nosuch"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("glitter"), std::string::npos) << r.output;
    r = run(base + "--realizations 1 2>&1");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("realizations"), std::string::npos) << r.output;
    r = run(base + "--truth-realizations 1 2>&1");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("truth-realizations"), std::string::npos) << r.output;
    r = run(base + "--flicker-paths 0 2>&1");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find("flicker-paths"), std::string::npos) << r.output;
    r = run(base + "--res 0x4 2>&1");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.output.find("--res"), std::string::npos) << r.output;
    std::filesystem::remove_all(dir);
}

}  // namespace
