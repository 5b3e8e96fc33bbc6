// examples/minimal_host (no glintlab library: only the files of `glintlab
// export`) against the OpenGL renderer on the same view, the PLANE_25 scene
// of 000 Table 1 (bench/table1.h) at 128 x 128, log_density 12.
//
// Tolerances: those of the CPU-vs-GPU tests (docs/VALIDATION.md "CPU vs
// GPU"; gpu_renderer_test.cpp GpuVsCpu), which bound two renderers of the
// same model whose footprints may differ slightly: mean luminance within 3%
// (5% for the gated models deliot2023 and zirr2016), 8x8 block means within
// 5% (10%), at most 1% of the pixels off by more than 0.02 + 10%. Here both
// sides run the same GLSL functions on the same driver with the same
// dFdxFine/dFdyFine footprint, so they are expected far inside these bounds
// (the differences are the order of floating-point operations in the light
// loop); the measured values are recorded as test properties.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <functional>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "glintlab/bench/table1.h"
#include "glintlab/core/image.h"
#include "glintlab/core/image_test_util.h"
#include "glintlab/export/shader_export.h"
#include "glintlab/loader/scene_loader.h"
#include "glintlab/realtime/gpu_renderer.h"
#include "glintlab/realtime/gpu_test_util.h"
#include "glintlab/realtime/image_compare.h"

namespace glintlab {
namespace {

// A PFM (little-endian, rows bottom to top) as an Image (rows top to bottom).
Image read_pfm(const std::filesystem::path& path) {
    std::ifstream f(path, std::ios::binary);
    std::string magic;
    int w = 0, h = 0;
    float scale = 0.0f;
    f >> magic >> w >> h >> scale;
    f.get();
    EXPECT_EQ(magic, "PF");
    EXPECT_LT(scale, 0.0f);  // little-endian
    Image image(w, h);
    std::vector<float> rgb(static_cast<size_t>(w) * h * 3);
    f.read(reinterpret_cast<char*>(rgb.data()), static_cast<std::streamsize>(rgb.size() * 4));
    EXPECT_TRUE(f.good()) << path;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float* p = &rgb[(static_cast<size_t>(h - 1 - y) * w + x) * 3];
            image.at(x, y) = glm::vec3(p[0], p[1], p[2]);
        }
    return image;
}

// Runs examples/minimal_host with `args`; its output (stdout and stderr)
// goes to `log` and comes back in `log_text`. Returns the exit status.
int run_minimal_host(const std::string& args, const std::filesystem::path& log,
                     std::string* log_text) {
    const std::string cmd =
        fmt::format("{} {} > {} 2>&1", GLINTLAB_MINIMAL_HOST_PATH, args, log.string());
    const int status = std::system(cmd.c_str());
    std::ifstream in(log);
    log_text->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return status;
}

// The agreement of the host's image with the renderer's, both scaled to the
// renderer's mean luminance 1: the view is lit dimly (the light is behind
// the camera: mean ~1e-3), and the scaling makes the absolute part (0.02)
// of the pixel tolerance relative to the image's level. `mean_b`: the
// renderer's mean before scaling.
ImageAgreement agreement_at_unit_mean(const Image& host, const Image& gpu, double* mean_b) {
    *mean_b = compare_images(host, gpu, 8, 0.02f, 0.1f).mean_b;
    Image host_n = host, gpu_n = gpu;
    const float k = *mean_b > 0.0 ? static_cast<float>(1.0 / *mean_b) : 1.0f;
    for (int y = 0; y < gpu.height; ++y)
        for (int x = 0; x < gpu.width; ++x) {
            host_n.at(x, y) *= k;
            gpu_n.at(x, y) *= k;
        }
    return compare_images(host_n, gpu_n, 8, 0.02f, 0.1f);
}

class MinimalHost : public ::testing::TestWithParam<std::string> {};

// The PLANE_25 scene of `model` as the test renders it: 000 Table 1's
// material; kneiphof2025 needs GGX and is also lit by a constant environment
// (radiance 0.5: its prefiltered maps are exact and equal on both sides, the
// CPU prefilter of the export and the renderer's GPU prefilter); wang2020's
// DPF table at 16 x 32 and quadtree depth 8 (its tables build in well under
// a second; the host and the renderer use the same tables).
nlohmann::json plane25_scene(const std::string& model) {
    nlohmann::json j = table1_scene_json("PLANE_25", model, 12.0f, 128, 128);
    if (model == "kneiphof2025") {
        j["materials"][0]["ndf"] = "ggx";
        j["lights"].push_back({{"type", "environment"}, {"radiance", 0.5}});
    }
    if (model == "wang2020")
        j["materials"][0]["wang2020"] = {{"dpf_theta", 16}, {"dpf_phi", 32}, {"depth", 8}};
    return j;
}

// The export of `exported`'s glint material (--scene) drawn by the minimal
// host (`host_args` after OUT.pfm) and the scene `rendered` drawn by the
// OpenGL renderer; nullopt (with the host's log as a failure) when the host
// fails. The export lands in dir/export, the host's image in `host_pfm`.
struct HostAndRenderer {
    Image host, gpu;
};
std::optional<HostAndRenderer> draw_both(const std::string& model, const nlohmann::json& exported,
                                         const nlohmann::json& rendered,
                                         const testing::ScratchDir& dir,
                                         const std::string& host_args) {
    const std::filesystem::path exported_file = dir / "exported.json";
    const std::filesystem::path rendered_file = dir / "plane_25.json";
    { std::ofstream(exported_file) << exported.dump(2); }
    { std::ofstream(rendered_file) << rendered.dump(2); }
    ExportOptions o;
    o.model = model;
    o.language = ExportLanguage::Glsl;
    o.out_dir = dir / "export";
    o.scene = exported_file;
    export_model(o);
    const std::filesystem::path pfm = dir / "host.pfm";
    std::string log_text;
    if (run_minimal_host(
            fmt::format("{} {} {} {}", o.out_dir.string(), model, pfm.string(), host_args),
            dir / "host.log", &log_text) != 0) {
        ADD_FAILURE() << log_text;
        return std::nullopt;
    }
    const Scene scene = parse_scene(rendered, rendered_file);
    GpuRenderer renderer(scene);
    renderer.render(scene);
    return HostAndRenderer{read_pfm(pfm), renderer.read_image()};
}

TEST_P(MinimalHost, MatchesTheRendererOnPlane25) {
    GLINTLAB_REQUIRE_GL();
    const std::string model = GetParam();
    testing::ScratchDir dir;
    // The host reads everything from the export of the scene's material
    // (--scene): its Fresnel, alpha, density, parameters and, for
    // kneiphof2025, the prefiltered maps of the scene's environment.
    const nlohmann::json scene_json = plane25_scene(model);
    std::optional<HostAndRenderer> both = draw_both(model, scene_json, scene_json, dir, "");
    ASSERT_TRUE(both);
    const Image& host = both->host;
    Image& gpu = both->gpu;
    ASSERT_EQ(host.width, gpu.width);
    ASSERT_EQ(host.height, gpu.height);
    if (model == "kneiphof2025") {
        // The renderer draws the environment behind the quad, the host only
        // the quad (cleared to 0). Background pixels — exactly 0 in the host,
        // where the lit quad is never 0 — must show the environment's
        // radiance 0.5 in the renderer's image; they are then left out.
        int background = 0;
        for (int y = 0; y < gpu.height; ++y)
            for (int x = 0; x < gpu.width; ++x)
                if (host.at(x, y) == glm::vec3(0.0f)) {
                    EXPECT_NEAR(gpu.at(x, y).y, 0.5f, 1e-3f) << x << ", " << y;
                    gpu.at(x, y) = glm::vec3(0.0f);
                    ++background;
                }
        EXPECT_GT(background, 0);
        EXPECT_LT(background, gpu.width * gpu.height / 2);  // the quad covers most of the view
    }

    double mean_b = 0.0;
    const ImageAgreement a = agreement_at_unit_mean(host, gpu, &mean_b);
    ASSERT_GT(mean_b, 1e-4);
    RecordProperty("mean_rel", std::to_string(a.mean_relative_error));
    RecordProperty("smoothed", std::to_string(a.smoothed_relative_l1));
    RecordProperty("mismatch", std::to_string(a.mismatch_fraction));
    const bool gated = model == "deliot2023" || model == "zirr2016";
    EXPECT_LT(a.mean_relative_error, gated ? 0.05 : 0.03);
    EXPECT_LT(a.smoothed_relative_l1, gated ? 0.10 : 0.05);
    EXPECT_LT(a.mismatch_fraction, 0.01);
}

// A PFM file (little-endian, rows from the bottom) of an RGB image whose
// rows `texel(x, y)` gives from the top.
void write_pfm_rgb(const std::filesystem::path& path, int w, int h,
                   const std::function<glm::vec3(int, int)>& texel) {
    std::vector<float> pfm(size_t(w) * size_t(h) * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::vec3 v = texel(x, y);
            for (int c = 0; c < 3; ++c)
                pfm[(size_t(h - 1 - y) * size_t(w) + size_t(x)) * 3 + c] = v[c];
        }
    std::ofstream f(path, std::ios::binary);
    f << "PF\n" << w << " " << h << "\n-1.0\n";
    f.write(reinterpret_cast<const char*>(pfm.data()),
            static_cast<std::streamsize>(pfm.size() * sizeof(float)));
}

struct InputLimits {
    double mean, smoothed, mismatch;
};

// A host feeding the export's per-pixel inputs (`host_inputs`: the
// minimal host's arguments after LOG_DENSITY) draws what the OpenGL
// renderer draws for `textured` (the same maps as the material's own),
// within `limits`; the host without the inputs draws another image.
void expect_inputs_match_the_renderer(const std::string& model, const nlohmann::json& textured,
                                      const testing::ScratchDir& dir,
                                      const std::string& host_inputs, InputLimits limits) {
    // The export takes numbers only: its material is the scene's untextured
    // one; the host then adds the maps as inputs.
    const nlohmann::json plain = plane25_scene(model);
    std::optional<HostAndRenderer> both =
        draw_both(model, plain, textured, dir, "128 128 12 " + host_inputs);
    ASSERT_TRUE(both);
    double mean_b = 0.0;
    const ImageAgreement a = agreement_at_unit_mean(both->host, both->gpu, &mean_b);
    ASSERT_GT(mean_b, 1e-4);
    ::testing::Test::RecordProperty(model + "_mean_rel", std::to_string(a.mean_relative_error));
    ::testing::Test::RecordProperty(model + "_smoothed", std::to_string(a.smoothed_relative_l1));
    EXPECT_LT(a.mean_relative_error, limits.mean);
    EXPECT_LT(a.smoothed_relative_l1, limits.smoothed);
    EXPECT_LT(a.mismatch_fraction, limits.mismatch);
    // The inputs matter: the host without them draws another image.
    std::string log_text;
    ASSERT_EQ(run_minimal_host(fmt::format("{} {} {} 128 128 12", (dir / "export").string(), model,
                                           (dir / "plain.pfm").string()),
                               dir / "plain.log", &log_text),
              0)
        << log_text;
    const ImageAgreement without =
        agreement_at_unit_mean(read_pfm(dir / "plain.pfm"), both->gpu, &mean_b);
    EXPECT_GT(without.smoothed_relative_l1, 2.0 * a.smoothed_relative_l1 + 0.02);
}

// The export's per-pixel inputs (docs/INTEGRATION.md "Per-pixel material
// inputs"): a host binding a density map through u_input_density draws what
// the OpenGL renderer draws with the same map as the material's textured
// log_density (the same mip chain of box means, the same footprint filter),
// within the same limits as above.
TEST(MinimalHostInputs, DensityMapMatchesTheRenderer) {
    GLINTLAB_REQUIRE_GL();
    for (const std::string model : {"deliot2023", "chermain2020"}) {
        SCOPED_TRACE(model);
        testing::ScratchDir dir;
        // ln N 9 to 13 in steps across u, a finer checker in v: 64 x 64, tiled.
        auto ln_n = [](int x, int y) { return 9.0f + float(x / 16) + ((y / 8) % 2 ? 0.5f : 0.0f); };
        Image map(64, 64);
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) map.at(x, y) = glm::vec3(ln_n(x, y));
        write_exr(map, dir / "density.exr");
        write_pfm_rgb(dir / "density.pfm", 64, 64,
                      [&](int x, int y) { return glm::vec3(ln_n(x, y)); });
        nlohmann::json scene_json = plane25_scene(model);
        scene_json["materials"][0]["log_density"] = {{"texture", "density.exr"}};
        const bool gated = model == "deliot2023";
        expect_inputs_match_the_renderer(model, scene_json, dir, (dir / "density.pfm").string(),
                                         {gated ? 0.05 : 0.03, gated ? 0.10 : 0.05, 0.01});
    }
}

// A normal map through the export's inputs: the host LEAN-maps it itself
// (slopes and bilinear-cell second moments, a box-mean mip chain; the recipe
// of docs/INTEGRATION.md) and draws what the OpenGL renderer draws with the
// same map as the material's normal_map. The same shader code on the same
// mip chains (glGenerateMipmap's box means on a power-of-two map are the
// renderer's levels): llvmpipe agrees to 1e-5 in the mean and 2e-4 in block
// means; the bounds leave room for another driver's mipmap rounding.
TEST(MinimalHostInputs, NormalMapMatchesTheRenderer) {
    GLINTLAB_REQUIRE_GL();
    for (const std::string model : {"smooth", "deliot2023", "chermain2020"}) {
        SCOPED_TRACE(model);
        testing::ScratchDir dir;
        // Bumps: ridges along u and v on a 64 x 64 map, tilts up to ~35°,
        // tiled 8 times.
        auto normal = [](int x, int y) {
            const float two_pi = 6.2831853f;
            const float u = (float(x) + 0.5f) / 64.0f, v = (float(y) + 0.5f) / 64.0f;
            return glm::normalize(glm::vec3(-0.7f * std::cos(two_pi * 2.0f * u),
                                            -1.05f * std::sin(two_pi * 3.0f * v), 1.0f));
        };
        Image map(64, 64);
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) map.at(x, y) = normal(x, y);
        write_exr(map, dir / "normals.exr");
        write_pfm_rgb(dir / "normals.pfm", 64, 64, normal);
        nlohmann::json scene_json = plane25_scene(model);
        scene_json["materials"][0]["normal_map"] = {{"texture", "normals.exr"},
                                                    {"encoding", "signed"}};
        expect_inputs_match_the_renderer(model, scene_json, dir,
                                         "- " + (dir / "normals.pfm").string(), {0.01, 0.02, 0.01});
    }
}

// chermain2020's geometric glint anti-aliasing in the export: the host's
// main() takes the view derivatives with dFdx/dFdy as the forward pass does
// and reads the running integrals of the export's one dictionary table;
// with the filter on (the widest
// kernel, 4, so that the plane's sweep, from the view's change alone, is
// well above the dictionary's sample spacing) it draws what the OpenGL
// renderer draws, within the normal-map test's bounds (the same shader code
// on the same driver), and the renderer's unfiltered image lies measurably
// further from it.
TEST(MinimalHostInputs, AntialiasedChermain2020MatchesTheRenderer) {
    GLINTLAB_REQUIRE_GL();
    testing::ScratchDir dir;
    nlohmann::json scene_json = plane25_scene("chermain2020");
    scene_json["materials"][0]["chermain2020"] = {{"antialiasing", "chermain2021"},
                                                  {"antialiasing_kernel", 4}};
    std::optional<HostAndRenderer> both =
        draw_both("chermain2020", scene_json, scene_json, dir, "");
    ASSERT_TRUE(both);
    // The manifest lists the one table (RGB32F, 3 floats a texel: the pairs
    // and the running integral) and the kernel the host sets.
    const nlohmann::json manifest =
        nlohmann::json::parse(std::ifstream(dir / "export" / "chermain2020.glsl.manifest.json"));
    int filters = 0;
    for (const auto& r : manifest.at("resources"))
        if (r.at("uniform") == "chermain2020_dictionary") {
            ++filters;
            EXPECT_EQ(r.at("format"), "RGB32F");
            EXPECT_EQ(std::filesystem::file_size(dir / "export" / r.at("file").get<std::string>()),
                      r.at("width").get<uint64_t>() * r.at("height").get<uint64_t>() * 12);
        }
    EXPECT_EQ(filters, 1);
    bool kernel = false;
    for (const auto& u : manifest.at("derived_uniforms"))
        kernel =
            kernel || (u.at("uniform") == "u_chermain2020_ggaa_kernel" && u.at("value") == 4.0);
    EXPECT_TRUE(kernel) << manifest.at("derived_uniforms").dump();
    double mean_b = 0.0;
    const ImageAgreement a = agreement_at_unit_mean(both->host, both->gpu, &mean_b);
    ASSERT_GT(mean_b, 1e-4);
    RecordProperty("mean_rel", std::to_string(a.mean_relative_error));
    RecordProperty("smoothed", std::to_string(a.smoothed_relative_l1));
    EXPECT_LT(a.mean_relative_error, 0.01);
    EXPECT_LT(a.smoothed_relative_l1, 0.02);
    EXPECT_LT(a.mismatch_fraction, 0.01);
    const nlohmann::json plain = plane25_scene("chermain2020");
    const Scene scene = parse_scene(plain, dir / "plain.json");
    GpuRenderer renderer(scene);
    renderer.render(scene);
    const ImageAgreement unfiltered =
        agreement_at_unit_mean(both->host, renderer.read_image(), &mean_b);
    RecordProperty("unfiltered_smoothed", std::to_string(unfiltered.smoothed_relative_l1));
    EXPECT_GT(unfiltered.smoothed_relative_l1, 2.0 * a.smoothed_relative_l1 + 0.005);
}

INSTANTIATE_TEST_SUITE_P(Models, MinimalHost,
                         ::testing::Values("deliot2023", "smooth", "zirr2016", "chermain2020",
                                           "wang2020", "kneiphof2025"));

}  // namespace
}  // namespace glintlab
