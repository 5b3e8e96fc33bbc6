// kneiphof2025's GPU prefilter (glints/kneiphof2025/kneiphof2025_prefilter_gpu.h, 003 §5
// "dynamic IBL") against the CPU prefilter (kneiphof2025_prefilter.cpp) on a
// small synthetic map, and the renderer's dynamic mode against its static
// (CPU-prefiltered) mode. Skipped without an OpenGL 4.5 context.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <epoxy/gl.h>

#include "glintlab/gl/gl_handles.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_prefilter.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_prefilter_gpu.h"
#include "glintlab/loader/scene_loader.h"
#include "glintlab/realtime/gpu_renderer.h"
#include "glintlab/realtime/gpu_test_util.h"
#include "glintlab/realtime/image_compare.h"
#include "glintlab/scene/environment.h"
#include "glintlab/scene/environment_file.h"

namespace glintlab {
namespace {

// 128 x 64 lat-long map: a sky gradient, a dark ground, a small bright sun
// (4 x 3 texels, 2000x the sky) and a coloured patch: a dynamic range of
// ~1e5 that spreads texels over all K levels.
Image synthetic_map() {
    Image img(128, 64);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(img.height);
            glm::vec3 c = v < 0.5f ? glm::vec3(0.4f, 0.6f, 1.0f) * (1.5f - v)
                                   : glm::vec3(0.05f, 0.04f, 0.02f);
            if (x >= 40 && x < 44 && y >= 12 && y < 15) c = glm::vec3(2000.0f, 1800.0f, 1500.0f);
            if (x >= 90 && x < 100 && y >= 30 && y < 40) c = glm::vec3(3.0f, 0.5f, 0.2f);
            img.at(x, y) = c;
        }
    return img;
}

// Every channel of every layer: max |gpu - cpu| over the channel's largest
// CPU value in that layer (radiance channels) or absolute (weights, in
// [0, 1]), and the mean absolute error.
struct LayerError {
    double max_rel = 0.0, mean_abs = 0.0;
};

LayerError compare_layer(const Kneiphof2025Level& gpu, const Kneiphof2025Level& cpu, int channels) {
    LayerError e;
    const size_t n = static_cast<size_t>(cpu.width) * static_cast<size_t>(cpu.height);
    for (int c = 0; c < channels; ++c) {
        double scale = 0.0;
        for (size_t i = 0; i < n; ++i)
            scale = std::max(scale, std::abs(double(cpu.data[i * channels + c])));
        if (c >= 3) scale = 1.0;  // weights
        if (scale <= 0.0) continue;
        double sum = 0.0;
        for (size_t i = 0; i < n; ++i) {
            const double d =
                std::abs(double(gpu.data[i * channels + c]) - cpu.data[i * channels + c]);
            e.max_rel = std::max(e.max_rel, d / scale);
            sum += d / scale;
        }
        e.mean_abs = std::max(e.mean_abs, sum / static_cast<double>(n));
    }
    return e;
}

// A lat-long source texture as the renderer's (RGB32F, bilinear, u repeats,
// v clamps).
gl::Texture upload(const Image& img) {
    gl::Texture source = gl::make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(source.get(), 1, GL_RGB32F, img.width, img.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(source.get(), 0, 0, 0, img.width, img.height, GL_RGB, GL_FLOAT,
                        img.pixels.data());
    glTextureParameteri(source.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(source.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(source.get(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(source.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return source;
}

// compare_layer's measures split into the radiance (RGB, relative to the
// channel's largest CPU value in the layer) and the weights (absolute).
struct SplitError {
    LayerError radiance, weights;
};

SplitError compare_split(const Kneiphof2025Level& gpu, const Kneiphof2025Level& cpu, int K) {
    const size_t C = static_cast<size_t>(3 + K);
    const size_t n = static_cast<size_t>(cpu.width) * static_cast<size_t>(cpu.height);
    // Radiance alone: the GPU's weights replaced by the CPU's (no difference).
    Kneiphof2025Level g = gpu;
    for (size_t i = 0; i < n; ++i)
        for (size_t k = 3; k < C; ++k) g.data[i * C + k] = cpu.data[i * C + k];
    // Weights alone: the radiance zeroed in both (compare_layer skips a
    // radiance channel whose CPU values are all zero).
    Kneiphof2025Level gw = gpu, cw = cpu;
    for (size_t i = 0; i < n; ++i)
        for (size_t c = 0; c < 3; ++c) gw.data[i * C + c] = cw.data[i * C + c] = 0.0f;
    return {compare_layer(g, cpu, 3 + K), compare_layer(gw, cw, 3 + K)};
}

// The Blender studio lights (CC0), the maps of the validation suite.
const char* const kWorldDir = "/usr/share/blender/datafiles/studiolights/world/";

class GpuKneiphof2025Prefilter : public ::testing::TestWithParam<int> {};

TEST_P(GpuKneiphof2025Prefilter, EqualsTheCpuPrefilter) {
    GLINTLAB_REQUIRE_GL();
    const int K = GetParam();
    const Image img = synthetic_map();
    const float scale = 1.5f;
    const EnvironmentMap env(img, scale, 0.0f);
    Kneiphof2025PrefilterOptions o;
    o.levels = K;
    o.base_width = 64;  // 64 x 32, 7 layers, 64 kernel samples
    const Kneiphof2025Environment cpu(env, o);

    gl::Texture source = upload(img);
    gl::Kneiphof2025GpuPrefilter gpu(o);
    gpu.run(source.get(), img.width, img.height, scale);

    // Eq. 18: the same levels (same range, same function).
    for (int k = 0; k < 8; ++k)
        EXPECT_NEAR(gpu.radiance_levels()[k], cpu.radiance_levels()[k],
                    1e-6f * cpu.radiance_levels()[K - 1])
            << "level " << k;
    double worst_max = 0.0, worst_mean = 0.0;
    for (int layer = 0; layer < o.mip_count; ++layer) {
        const LayerError e =
            compare_layer(gpu.read_layer(layer), cpu.mips()[static_cast<size_t>(layer)], 3 + K);
        worst_max = std::max(worst_max, e.max_rel);
        worst_mean = std::max(worst_mean, e.mean_abs);
    }
    RecordProperty("max_rel", std::to_string(worst_max));
    RecordProperty("mean_abs", std::to_string(worst_mean));
    // Measured (llvmpipe, K = 4 and 8): max 6.1e-4 of a channel's range, mean
    // 2.3e-5. The GPU's trilinear pyramid lookups and atan / acos / sin of
    // the kernel directions round differently from the CPU's fp32 code; a
    // texel next to the 2000x sun moves by ~1e-7 of the sun per lookup, and
    // the kernel's 64 lookups add up. Limits ~3x and ~4x the measured values,
    // far below the levels' own spacing (a wrong LOD, kernel or partition
    // gives errors of 1e-2 to 1).
    EXPECT_LT(worst_max, 2e-3);
    EXPECT_LT(worst_mean, 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Levels, GpuKneiphof2025Prefilter, ::testing::Values(4, 8));

// The split-sum kernel integral itself (Eq. 11, 21: p(wi) ~ D(h) <n, wi>,
// n = v = r) of `base`'s radiance (3 + K channels a texel) around the
// direction of texel (x, y), summed over every base texel (its centre,
// solid angle): the value the 64-sample filtered importance sampling of the
// prefilters estimates. Out: RGB.
glm::vec3 kernel_integral(const Kneiphof2025Level& base, int K, float roughness, int x, int y) {
    const int W = base.width, H = base.height, C = 3 + K;
    const float pi = 3.14159265358979f;
    auto dir = [&](float u, float v) {
        const float theta = v * pi, phi = (u - 0.5f) * 2.0f * pi;
        return glm::vec3(std::sin(theta) * std::sin(phi), std::cos(theta),
                         -std::sin(theta) * std::cos(phi));
    };
    const glm::vec3 n = dir((x + 0.5f) / W, (y + 0.5f) / H);
    const double a2 = std::pow(std::max(roughness * roughness, 1e-4f), 2.0f);
    glm::dvec3 sum(0.0);
    double wsum = 0.0;
    for (int j = 0; j < H; ++j) {
        const double sa = std::sin((j + 0.5) * pi / H);
        for (int i = 0; i < W; ++i) {
            const glm::vec3 l = dir((i + 0.5f) / W, (j + 0.5f) / H);
            const float nl = glm::dot(n, l);
            if (nl <= 0.0f) continue;
            const glm::vec3 h = glm::normalize(n + l);
            const double c = glm::dot(n, h);
            const double d = a2 / (pi * std::pow(c * c * (a2 - 1.0) + 1.0, 2.0));
            const double w = d * nl * sa;
            const float* t = &base.data[(size_t(j) * W + i) * C];
            sum += w * glm::dvec3(t[0], t[1], t[2]);
            wsum += w;
        }
    }
    return glm::vec3(sum / wsum);
}

// Resolution::Reduced (the renderer's dynamic default): s_m = floor(min
// kernel LOD), at most 2. At 256 x 128 and 64 samples the smallest LODs of
// the layers sqrt(alpha) = 1/6 .. 1 are 0, 1.34, 2.51, 3.34, 3.98, 4.50; at
// 64 x 32 two less (texels 4 x 4 times larger), clamped at 0.
TEST(GpuKneiphof2025PrefilterReduced, ShiftsFollowTheKernelLods) {
    GLINTLAB_REQUIRE_GL();
    Kneiphof2025PrefilterOptions o;
    o.levels = 4;
    const gl::Kneiphof2025GpuPrefilter reduced(o,
                                               gl::Kneiphof2025GpuPrefilter::Resolution::Reduced);
    const gl::Kneiphof2025GpuPrefilter full(o);
    const int expected[7] = {0, 0, 1, 2, 2, 2, 2};
    for (int m = 0; m < 7; ++m) {
        EXPECT_EQ(reduced.filter_shift(m), expected[m]) << "layer " << m;
        EXPECT_EQ(full.filter_shift(m), 0) << "layer " << m;
    }
    o.base_width = 64;
    const gl::Kneiphof2025GpuPrefilter small(o, gl::Kneiphof2025GpuPrefilter::Resolution::Reduced);
    const int expected_small[7] = {0, 0, 0, 0, 1, 1, 2};
    for (int m = 0; m < 7; ++m) EXPECT_EQ(small.filter_shift(m), expected_small[m]) << m;
}

// The reduced layers against the CPU prefilter on the synthetic map of
// EqualsTheCpuPrefilter (64 x 32: layers 4-6 reduced, the 2000x sun patch
// the worst case of a bilinear reconstruction) and, at the default
// 256 x 128, on forest.exr and sunrise.exr (the map with the largest
// differences of the 8 studio lights, docs/BENCHMARKS.md).
// Measured (llvmpipe): see the limits' comments.
TEST_P(GpuKneiphof2025Prefilter, ReducedResolutionIsCloseToTheCpuPrefilter) {
    GLINTLAB_REQUIRE_GL();
    const int K = GetParam();
    Kneiphof2025PrefilterOptions o;
    o.levels = K;
    {
        const Image img = synthetic_map();
        const EnvironmentMap env(img, 1.5f, 0.0f);
        o.base_width = 64;
        const Kneiphof2025Environment cpu(env, o);
        const gl::Texture source = upload(img);
        gl::Kneiphof2025GpuPrefilter gpu(o, gl::Kneiphof2025GpuPrefilter::Resolution::Reduced);
        gpu.run(source.get(), img.width, img.height, 1.5f);
        double worst_max = 0.0, worst_mean = 0.0;
        for (int layer = 0; layer < o.mip_count; ++layer) {
            const LayerError e =
                compare_layer(gpu.read_layer(layer), cpu.mips()[static_cast<size_t>(layer)], 3 + K);
            std::printf("synthetic K=%d layer %d shift %d: max %.3g mean %.3g\n", K, layer,
                        gpu.filter_shift(layer), e.max_rel, e.mean_abs);
            worst_max = std::max(worst_max, e.max_rel);
            worst_mean = std::max(worst_mean, e.mean_abs);
        }
        RecordProperty("synthetic_max_rel", std::to_string(worst_max));
        RecordProperty("synthetic_mean_abs", std::to_string(worst_mean));
        // Measured (llvmpipe, K = 4 and 8): max 0.40, mean 0.045 (layer 6
        // on 16 x 8 texels, next to the 2000x sun); layers 1-3 (s = 0) as
        // EqualsTheCpuPrefilter. Limits 1.5x: they catch a wrong layer,
        // level or texel centre (errors of order 1), not the sun's slope
        // breaks.
        EXPECT_LT(worst_max, 0.6);
        EXPECT_LT(worst_mean, 0.07);
    }
    o.base_width = 256;
    for (const char* name : {"forest", "sunrise"}) {
        const std::filesystem::path path = std::string(kWorldDir) + name + ".exr";
        if (!std::filesystem::exists(path)) continue;
        const EnvironmentMap env(read_environment_image(path, 1.0f), 1.0f, 0.0f);
        const Kneiphof2025Environment cpu(env, o);
        const gl::Texture source = upload(env.image());
        gl::Kneiphof2025GpuPrefilter gpu(o, gl::Kneiphof2025GpuPrefilter::Resolution::Reduced);
        gpu.run(source.get(), env.image().width, env.image().height, 1.0f);
        gl::Kneiphof2025GpuPrefilter full(o);
        full.run(source.get(), env.image().width, env.image().height, 1.0f);
        for (int layer = 0; layer < o.mip_count; ++layer) {
            const Kneiphof2025Level reduced_layer = gpu.read_layer(layer);
            const SplitError e =
                compare_split(reduced_layer, cpu.mips()[static_cast<size_t>(layer)], K);
            if (K == 4 && layer > 0) {
                // Both GPU modes against the kernel integral (every 16th
                // texel): the reduced grid must not move the layer away from
                // what the prefilter estimates.
                const Kneiphof2025Level full_layer = full.read_layer(layer);
                const float rough = static_cast<float>(layer) / static_cast<float>(o.mip_count - 1);
                std::vector<std::pair<glm::vec3, size_t>> refs;
                double scale = 0.0, full_mean = 0.0, reduced_mean = 0.0;
                for (int y = 8; y < 128; y += 16)
                    for (int x = 8; x < 256; x += 16) {
                        const glm::vec3 ref = kernel_integral(cpu.mips()[0], K, rough, x, y);
                        refs.push_back(
                            {ref, static_cast<size_t>(y) * 256 + static_cast<size_t>(x)});
                        scale = std::max(scale, double(std::max({ref.x, ref.y, ref.z})));
                    }
                for (const auto& [ref, i] : refs)
                    for (int ch = 0; ch < 3; ++ch) {
                        full_mean += std::abs(full_layer.data[i * 7 + ch] - ref[ch]);
                        reduced_mean += std::abs(reduced_layer.data[i * 7 + ch] - ref[ch]);
                    }
                full_mean /= 3.0 * static_cast<double>(refs.size()) * scale;
                reduced_mean /= 3.0 * static_cast<double>(refs.size()) * scale;
                std::printf("%s layer %d vs kernel integral: full %.3g reduced %.3g\n", name, layer,
                            full_mean, reduced_mean);
                // Measured: reduced / full 0.85 - 1.23 (sunrise layer 2:
                // 9.6e-4 vs 7.8e-4 of the channel range).
                EXPECT_LT(reduced_mean, 1.5 * full_mean) << name << " layer " << layer;
            }
            std::printf(
                "%s K=%d layer %d: radiance max %.3g mean %.3g weights max %.3g mean %.3g\n", name,
                K, layer, e.radiance.max_rel, e.radiance.mean_abs, e.weights.max_rel,
                e.weights.mean_abs);
            // Measured (llvmpipe, K = 4 and 8, worst layer): radiance max
            // 0.168 (sunrise, a texel by the sun) mean 2.6e-3; weights max
            // 0.024 mean 1.4e-3. Limits ~2x.
            EXPECT_LT(e.radiance.max_rel, 0.3) << name << " layer " << layer;
            EXPECT_LT(e.radiance.mean_abs, 5e-3) << name << " layer " << layer;
            EXPECT_LT(e.weights.max_rel, 0.05) << name << " layer " << layer;
            EXPECT_LT(e.weights.mean_abs, 3e-3) << name << " layer " << layer;
        }
    }
}

// The survey of docs/BENCHMARKS.md: every studio light, K = 4
// and 8, both resolutions, per layer. Slow (16 CPU prefilters at 256 x 128);
// run with --gtest_also_run_disabled_tests.
TEST(GpuKneiphof2025PrefilterReduced, DISABLED_SurveyOfTheStudioLights) {
    GLINTLAB_REQUIRE_GL();
    for (const char* name :
         {"city", "courtyard", "forest", "interior", "night", "studio", "sunrise", "sunset"}) {
        const std::filesystem::path path = std::string(kWorldDir) + name + ".exr";
        if (!std::filesystem::exists(path)) continue;
        const EnvironmentMap env(read_environment_image(path, 1.0f), 1.0f, 0.0f);
        const gl::Texture source = upload(env.image());
        for (int K : {4, 8}) {
            Kneiphof2025PrefilterOptions o;
            o.levels = K;
            const Kneiphof2025Environment cpu(env, o);
            gl::Kneiphof2025GpuPrefilter full(o);
            gl::Kneiphof2025GpuPrefilter reduced(o,
                                                 gl::Kneiphof2025GpuPrefilter::Resolution::Reduced);
            full.run(source.get(), env.image().width, env.image().height, 1.0f);
            reduced.run(source.get(), env.image().width, env.image().height, 1.0f);
            for (int layer = 0; layer < o.mip_count; ++layer) {
                const Kneiphof2025Level& c = cpu.mips()[static_cast<size_t>(layer)];
                const Kneiphof2025Level fl = full.read_layer(layer), rl = reduced.read_layer(layer);
                const SplitError f = compare_split(fl, c, K);
                const SplitError r = compare_split(rl, c, K);
                if (K == 4 && layer > 0) {
                    // Both against the kernel integral, every 8th texel.
                    const float rough = static_cast<float>(layer) / 6.0f;
                    double fmax = 0, fmean = 0, rmax = 0, rmean = 0, scale = 0;
                    std::vector<std::pair<glm::vec3, size_t>> refs;
                    for (int y = 4; y < c.height; y += 8)
                        for (int x = 4; x < c.width; x += 8) {
                            const glm::vec3 ref = kernel_integral(cpu.mips()[0], K, rough, x, y);
                            refs.push_back({ref, size_t(y) * c.width + x});
                            scale = std::max(scale, double(std::max({ref.x, ref.y, ref.z})));
                        }
                    for (const auto& [ref, i] : refs)
                        for (int ch = 0; ch < 3; ++ch) {
                            const double df = std::abs(fl.data[i * 7 + ch] - ref[ch]) / scale;
                            const double dr = std::abs(rl.data[i * 7 + ch] - ref[ch]) / scale;
                            fmax = std::max(fmax, df);
                            rmax = std::max(rmax, dr);
                            fmean += df / (3.0 * refs.size());
                            rmean += dr / (3.0 * refs.size());
                        }
                    std::printf(
                        "INTEGRAL %-9s layer %d | full: max %.2e mean %.2e | reduced: max %.2e "
                        "mean %.2e\n",
                        name, layer, fmax, fmean, rmax, rmean);
                }
                std::printf(
                    "SURVEY %-9s K=%d layer %d shift %d | full: rad %.2e %.2e w %.2e %.2e | "
                    "reduced: rad %.2e %.2e w %.2e %.2e\n",
                    name, K, layer, reduced.filter_shift(layer), f.radiance.max_rel,
                    f.radiance.mean_abs, f.weights.max_rel, f.weights.mean_abs, r.radiance.max_rel,
                    r.radiance.mean_abs, r.weights.max_rel, r.weights.mean_abs);
            }
        }
    }
}

TEST(GpuKneiphof2025Prefilter, RejectsBadOptions) {
    GLINTLAB_REQUIRE_GL();
    Kneiphof2025PrefilterOptions o;
    o.levels = 5;
    EXPECT_THROW(gl::Kneiphof2025GpuPrefilter{o}, Error);
    o.levels = 8;
    o.base_width = 100;
    EXPECT_THROW(gl::Kneiphof2025GpuPrefilter{o}, Error);
}

// The renderer's dynamic IBL (prefiltered on the GPU in every frame) renders
// the image of its static mode (CPU-prefiltered maps) up to the prefilter
// differences measured above; the glint pattern is the same (same hashes).
// Measured on forest.exr: mean 7.3e-5 with the lobe (2.9e-5 with the split
// sum), 1e-4 of the pixels mismatching; limits 1e-3 and
// 1% (a prefilter that missed the scale or the levels moves the mean by
// far more). "smooth": "lobe": the dynamic maps carry no sun channel (the
// default "lobe_sun" is the lobe there; docs/MODELS.md).
TEST(GpuKneiphof2025Prefilter, DynamicEnvironmentRendersTheStaticImage) {
    GLINTLAB_REQUIRE_GL();
    nlohmann::json j;
    j["film"] = {{"width", 96}, {"height", 96}};
    j["render"] = {{"integrator", "direct"}, {"spp", 1}, {"seed", 1}};
    j["camera"] = {{"eye", {0, 0, 3.2}}, {"target", {0, 0, 0}}, {"fov_deg", 45}};
    j["materials"] = {{{"name", "g"},
                       {"type", "glint"},
                       {"model", "kneiphof2025"},
                       {"ndf", "ggx"},
                       {"roughness", 0.3},
                       {"log_density", 12.0},
                       {"kneiphof2025", {{"smooth", "lobe"}}}}};
    j["shapes"] = {{{"type", "sphere"}, {"radius", 1.0}, {"material", "g"}}};
    const std::string forest = "/usr/share/blender/datafiles/studiolights/world/forest.exr";
    if (std::filesystem::exists(forest))
        j["lights"] = {{{"type", "environment"}, {"file", forest}, {"rotation_deg", 90}}};
    else
        j["lights"] = {{{"type", "environment"}, {"radiance", {0.8, 0.9, 1.0}}}};
    const Scene scene = parse_scene(j, "test:dynamic");
    GpuRenderer renderer(scene);
    renderer.render(scene);
    const Image static_image = renderer.read_image();
    // The limits above are those of the full-resolution prefilter (option
    // dynamic_full_resolution), whose layers are the CPU's to rounding.
    renderer.set_model_option("kneiphof2025", "dynamic_environment", true);
    renderer.set_model_option("kneiphof2025", "dynamic_full_resolution", true);
    renderer.render(scene);
    renderer.render(scene);  // re-run every frame
    const Image dynamic_image = renderer.read_image();
    const ImageAgreement a = compare_images(dynamic_image, static_image, 8, 0.02f, 0.1f);
    RecordProperty("mean_rel", std::to_string(a.mean_relative_error));
    RecordProperty("mismatch", std::to_string(a.mismatch_fraction));
    std::printf("dynamic vs static: mean %.3g smoothed %.3g mismatch %.3g\n", a.mean_relative_error,
                a.smoothed_relative_l1, a.mismatch_fraction);
    ASSERT_GT(a.mean_b, 0.01);
    EXPECT_LT(a.mean_relative_error, 1e-3);
    EXPECT_LT(a.mismatch_fraction, 0.01);

    // The default dynamic prefilter (Resolution::Reduced: the rough layers
    // on coarser grids, upsampled). Measured (llvmpipe): mean
    // 1.09e-3, mismatch 4.1e-3 (15x and 38x the full resolution's): roughness 0.3
    // blends layers 1 (exact) and 2 (filtered at 128 x 64), whose texels
    // near the sun differ from the CPU's by the slope breaks of the kernel's
    // bilinear pyramid lookups (kneiphof2025_prefilter_gpu.h). Limits ~2x.
    renderer.set_model_option("kneiphof2025", "dynamic_full_resolution", false);
    renderer.render(scene);
    const Image reduced_image = renderer.read_image();
    const ImageAgreement r = compare_images(reduced_image, static_image, 8, 0.02f, 0.1f);
    RecordProperty("reduced_mean_rel", std::to_string(r.mean_relative_error));
    RecordProperty("reduced_mismatch", std::to_string(r.mismatch_fraction));
    std::printf("reduced dynamic vs static: mean %.3g smoothed %.3g mismatch %.3g\n",
                r.mean_relative_error, r.smoothed_relative_l1, r.mismatch_fraction);
    EXPECT_LT(r.mean_relative_error, 2.5e-3);
    EXPECT_LT(r.mismatch_fraction, 0.01);
}

}  // namespace
}  // namespace glintlab
