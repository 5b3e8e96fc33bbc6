// The "normal_map" key (docs/SCENE_FORMAT.md, "Normal maps"): decoding,
// glTF's scale, the LEAN moments' footprint statistics, and the errors a
// user meets.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "glintlab/core/glsl.h"
#include "glintlab/core/image.h"
#include "glintlab/core/image_test_util.h"
#include "glintlab/loader/scene_loader.h"

GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/core/slope_frame.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {
namespace {

using testing::ScratchDir;

// A PNG whose stored codes are exactly `codes` (write_png encodes linear
// values to sRGB codes: hand it the decoded codes).
void write_png_codes(const Image& codes, const std::filesystem::path& path) {
    Image linear = codes;
    for (glm::vec3& p : linear.pixels)
        p = glm::vec3(srgb_decode(p.x / 255.0f), srgb_decode(p.y / 255.0f),
                      srgb_decode(p.z / 255.0f));
    write_png(linear, path);
}

nlohmann::json scene_with(const nlohmann::json& normal_map, const std::string& type = "conductor",
                          const nlohmann::json& shape = {{"type", "quad"}, {"size", {2, 2}}}) {
    nlohmann::json m = {{"name", "m"}, {"type", type}, {"normal_map", normal_map}};
    if (type == "glint") m["model"] = "smooth";
    nlohmann::json s = shape;
    s["material"] = "m";
    return {{"camera", {{"eye", {0, 1, 3}}, {"target", {0, 0, 0}}}},
            {"film", {{"width", 8}, {"height", 8}}},
            {"materials", {m}},
            {"shapes", {s}},
            {"lights", {{{"type", "directional"}, {"direction", {0, 1, 0}}}}}};
}

std::string load_error(const nlohmann::json& doc, const std::filesystem::path& file) {
    try {
        parse_scene(doc, file);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

TEST(NormalMapReader, EightBitCodesDecodeToUnitNormalsAndScaleMultipliesXY) {
    ScratchDir dir;
    // (x, y, z) = 2c − 1: codes (191, 128, 225) ≈ (0.498, 0.004, 0.765).
    write_png_codes(Image(2, 2, glm::vec3(191, 128, 225)), dir / "n.png");
    for (const float scale : {1.0f, 2.0f, 0.0f}) {
        const Scene scene =
            parse_scene(scene_with({{"texture", "n.png"}, {"scale", scale}}), dir / "s.json");
        const NormalMap& map = *scene.materials[0].normal_map;
        const glm::vec3 n = 2.0f * glm::vec3(191, 128, 225) / 255.0f - 1.0f;
        // glTF: normalize((2c − 1) · (scale, scale, 1)); slope = −(x, y)/z.
        const glm::vec2 expected = -scale * glm::vec2(n.x, n.y) / n.z;
        const glm::vec2 s = map.slope_at({0.3f, 0.6f});
        EXPECT_NEAR(s.x, expected.x, 1e-5f) << scale;
        EXPECT_NEAR(s.y, expected.y, 1e-5f) << scale;
    }
}

// The scene whose material's normal map is the 64 × 64 map of unit normals
// `normal(x, y)` (signed EXR in `dir`), and a footprint of 16 × 16 texels
// at its centre.
Scene scene_of_map(const ScratchDir& dir, const std::function<glm::vec3(int, int)>& normal) {
    Image n(64, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) n.at(x, y) = normal(x, y);
    write_exr(n, dir / "n.exr");
    return parse_scene(scene_with({{"texture", "n.exr"}, {"encoding", "signed"}}), dir / "s.json");
}

Footprint wide_footprint() {
    Footprint fp;
    fp.uv = glm::vec2(0.5f);
    fp.duvdx = glm::vec2(0.25f, 0.0f);
    fp.duvdy = glm::vec2(0.0f, 0.25f);
    return fp;
}

TEST(NormalMapReader, LeanMomentsGiveTheFootprintsMeanAndCovariance) {
    ScratchDir dir;
    // A 64 × 64 checker of two normals tilted ±0.3 in slope along x, and
    // 0.1 along y everywhere: over a footprint of many texels the mean slope
    // is (0, s_y) and the covariance that of the bilinear surface the
    // lookups reconstruct, s_x = 0.3 (1 − 2f_x)(1 − 2f_y) between texel
    // centres: E[s_x²] = 0.09 / 9 (not the texels' 0.09), uncorrelated.
    const Scene scene = scene_of_map(dir, [](int x, int y) {
        const float sx = ((x + y) % 2) ? 0.3f : -0.3f, sy = 0.1f;
        return glm::normalize(glm::vec3(-sx, -sy, 1.0f));
    });
    const NormalMap& map = *scene.materials[0].normal_map;
    const Footprint fp = wide_footprint();
    const SlopeStatistics s = map.lookup(fp.uv, &fp);
    EXPECT_NEAR(s.mean.x, 0.0f, 1e-4f);
    EXPECT_NEAR(s.mean.y, 0.1f, 1e-4f);
    EXPECT_NEAR(s.covariance.x, 0.01f, 1e-5f);
    EXPECT_NEAR(s.covariance.y, 0.0f, 1e-5f);
    EXPECT_NEAR(s.covariance.z, 0.0f, 1e-5f);
    // Without a footprint: one point of the finest level, no covariance.
    const SlopeStatistics point = map.lookup(glm::vec2(0.5f / 64.0f), nullptr);
    EXPECT_NEAR(std::abs(point.mean.x), 0.3f, 1e-4f);
    EXPECT_EQ(point.covariance, glm::vec3(0.0f));
    // "filtering": "none" ignores the footprint.
    const Scene none = parse_scene(
        scene_with({{"texture", "n.exr"}, {"encoding", "signed"}, {"filtering", "none"}}),
        dir / "s.json");
    const SlopeStatistics unfiltered = none.materials[0].normal_map->lookup(fp.uv, &fp);
    EXPECT_EQ(unfiltered.covariance, glm::vec3(0.0f));
}

// The footprint statistics of the bilinear surface the ground truth's
// facets follow (NormalMap::slope_at), by 24 × 24 midpoint samples over
// the footprint's parallelogram.
SlopeStatistics surface_statistics(const NormalMap& map, const Footprint& fp) {
    constexpr int n = 24;
    glm::vec2 sum(0.0f);
    glm::vec3 squares(0.0f);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const glm::vec2 s = map.slope_at(fp.uv + ((i + 0.5f) / n - 0.5f) * fp.duvdx +
                                             ((j + 0.5f) / n - 0.5f) * fp.duvdy);
            sum += s;
            squares += glm::vec3(s.x * s.x, s.y * s.y, s.x * s.y);
        }
    SlopeStatistics out;
    out.mean = sum / float(n * n);
    squares /= float(n * n);
    out.covariance = squares - glm::vec3(out.mean.x * out.mean.x, out.mean.y * out.mean.y,
                                         out.mean.x * out.mean.y);
    return out;
}

TEST(NormalMapReader, FootprintsNearATexelTakeTheSurfacesOwnSpread) {
    ScratchDir dir;
    // Three maps: uncorrelated texels (slopes uniform in ±0.3), diagonal
    // ridges 8 texels wide and a smooth field (periods 32 and 16). Between
    // texels the bilinear surface ramps from one slope to the next, so a
    // footprint a sixteenth of a texel wide sees almost one normal; the
    // chain's interpolated cell moments give it the cells' spread.
    // (core/slope_frame.glsl lean_chain_weight says why the chain keeps
    // footprints from one texel, where it overstates Σ too.)
    auto hash = [](uint32_t h) {
        h ^= h >> 16, h *= 0x7feb352du, h ^= h >> 15, h *= 0x846ca68bu, h ^= h >> 16;
        return float(h) / 4294967296.0f;
    };
    const std::function<glm::vec2(int, int)> maps[] = {
        [&](int x, int y) {
            const uint32_t k = uint32_t(y * 64 + x) * 2u;
            return glm::vec2(0.6f * hash(k) - 0.3f, 0.6f * hash(k + 1u) - 0.3f);
        },
        [](int x, int y) {
            const float v = 0.3f * std::sin(2.0f * std::numbers::pi_v<float> * float(x + y) / 8.0f);
            return glm::vec2(v, -v);
        },
        [](int x, int y) {
            const float w = 2.0f * std::numbers::pi_v<float>;
            return glm::vec2(0.3f * std::sin(w * float(x) / 32.0f),
                             0.2f * std::cos(w * float(y) / 16.0f));
        }};
    const char* names[] = {"noise", "ridges", "smooth"};
    for (int m = 0; m < 3; ++m) {
        const Scene scene = scene_of_map(dir, [&](int x, int y) {
            const glm::vec2 s = maps[m](x, y);
            return glm::normalize(glm::vec3(-s.x, -s.y, 1.0f));
        });
        const NormalMap& map = *scene.materials[0].normal_map;
        for (const float texels : {1.0f / 16.0f, 0.25f, 0.5f, 0.75f, 1.0f, 4.0f}) {
            double error = 0.0, chain_error = 0.0, spread = 0.0;
            for (int k = 0; k < 128; ++k) {
                Footprint fp;
                fp.uv = glm::vec2(std::fmod(0.137f + 0.618034f * float(k), 1.0f),
                                  std::fmod(0.291f + 0.754878f * float(k), 1.0f));
                fp.duvdx = glm::vec2(texels / 64.0f, 0.0f);
                fp.duvdy = glm::vec2(0.0f, texels / 64.0f);
                const SlopeStatistics truth = surface_statistics(map, fp);
                const SlopeStatistics s = map.lookup(fp.uv, &fp, true);
                // The mip chain alone (LEAN's interpolated moments).
                const glm::vec4 c = map.slopes->lookup4(fp.uv, &fp, shader::kSlopeMomentLodBias);
                const float c_xy =
                    map.cross_moment->lookup4(fp.uv, &fp, shader::kSlopeMomentLodBias).x;
                const glm::vec3 chain =
                    shader::slope_covariance(glm::vec2(c.x, c.y), glm::vec2(c.z, c.w), c_xy, true);
                // Σ_xx, Σ_yy and Σ_xy (twice: Σ's off-diagonal pair).
                const glm::vec3 weight(1.0f, 1.0f, 2.0f);
                error += glm::dot(glm::abs(s.covariance - truth.covariance), weight);
                chain_error += glm::dot(glm::abs(chain - truth.covariance), weight);
                spread += truth.covariance.x + truth.covariance.y;
            }
            const std::string at = fmt::format("{}_{}", names[m], texels);
            RecordProperty("error_" + at, fmt::format("{:.3f}", error / spread));
            RecordProperty("chain_error_" + at, fmt::format("{:.3f}", chain_error / spread));
            SCOPED_TRACE(at);
            // Measured error / spread up to half a texel: 0.012-0.20 (the
            // chain: 3.7-702); from one texel the chain's own. The largest
            // is the uncorrelated texels' at half a texel: the five fetches
            // miss the bilinear patch's twist (its uv term), which feeds Σ.
            if (texels <= 0.5f) {
                EXPECT_LT(error, 0.25 * spread);
            }
            EXPECT_LT(error, chain_error + 0.02 * spread);
        }
    }
}

TEST(NormalMapReader, CrossMomentGivesTheCorrelationOfDiagonalRidges) {
    ScratchDir dir;
    // Ridges along the diagonal x = −y: s_x = s_y = ±0.2 in alternate
    // diagonal bands of texels, so over a footprint of many texels the
    // slopes are perfectly correlated: Σ_xy = Σ_xx = Σ_yy. The bilinear
    // surface between the bands keeps that (both components interpolate
    // alike). Σ_xy only where the caller asks for it.
    const Scene scene = scene_of_map(dir, [](int x, int y) {
        const float v = ((x + y) / 2) % 2 ? 0.2f : -0.2f;
        return glm::normalize(glm::vec3(-v, -v, 1.0f));
    });
    const NormalMap& map = *scene.materials[0].normal_map;
    const Footprint fp = wide_footprint();
    const SlopeStatistics s = map.lookup(fp.uv, &fp);
    EXPECT_EQ(s.covariance.z, 0.0f);
    EXPECT_GT(s.covariance.x, 0.01f);
    EXPECT_NEAR(s.covariance.y, s.covariance.x, 1e-5f);
    const SlopeStatistics c = map.lookup(fp.uv, &fp, true);
    EXPECT_EQ(c.mean, s.mean);
    EXPECT_EQ(glm::vec2(c.covariance), glm::vec2(s.covariance));
    EXPECT_NEAR(c.covariance.z, s.covariance.x, 1e-5f);
    // Without a footprint there is no spread, hence no correlation.
    EXPECT_EQ(map.lookup(fp.uv, nullptr, true).covariance, glm::vec3(0.0f));
}

TEST(NormalMapReader, LeanMixtureTilesTheFootprintWithSubFootprints) {
    ScratchDir dir;
    // A slope ramp s_x = 0.4 (x − 32) / 64 across 64 texels: the footprint's
    // halves have different mean slopes, whose average is the footprint's.
    auto ramp = [](int x, int) {
        const float sx = 0.4f * (float(x) + 0.5f - 32.0f) / 64.0f;
        return glm::normalize(glm::vec3(-sx, 0.0f, 1.0f));
    };
    const Scene lean = scene_of_map(dir, ramp);
    const Scene scene = parse_scene(scene_with({{"texture", "n.exr"},
                                                {"encoding", "signed"},
                                                {"filtering", "lean_mixture"},
                                                {"mixture", 2}}),
                                    dir / "s.json");
    const NormalMap& map = *scene.materials[0].normal_map;
    ASSERT_EQ(map.filtering, NormalMap::Filtering::LeanMixture);
    ASSERT_EQ(map.mixture, 2);
    Footprint fp;
    fp.uv = glm::vec2(0.5f);
    fp.duvdx = glm::vec2(0.25f, 0.0f);
    fp.duvdy = glm::vec2(0.0f, 0.125f);
    // u in [0, 1) picks cell floor(4u): x fastest, each cell half the axes.
    glm::vec2 mean_of_means(0.0f);
    for (int cell = 0; cell < 4; ++cell) {
        const Footprint sub = map.sample_footprint(fp, (float(cell) + 0.5f) / 4.0f);
        const glm::vec2 centre = fp.uv + (float(cell % 2) - 0.5f) * 0.5f * fp.duvdx +
                                 (float(cell / 2) - 0.5f) * 0.5f * fp.duvdy;
        EXPECT_NEAR(glm::length(sub.uv - centre), 0.0f, 1e-6f) << cell;
        EXPECT_EQ(sub.duvdx, fp.duvdx * 0.5f);
        EXPECT_EQ(sub.duvdy, fp.duvdy * 0.5f);
        mean_of_means += 0.25f * map.lookup(sub.uv, &sub).mean;
    }
    // u = 1 (rounding) stays in the last cell.
    EXPECT_EQ(map.sample_footprint(fp, 1.0f).uv, map.sample_footprint(fp, 0.99f).uv);
    // The left and right halves' means differ by the ramp over half the
    // footprint (0.4 · 0.125 = 0.05); together they are the footprint's.
    const float left = map.lookup(map.sample_footprint(fp, 0.1f).uv, nullptr).mean.x;
    const float right = map.lookup(map.sample_footprint(fp, 0.3f).uv, nullptr).mean.x;
    EXPECT_NEAR(right - left, 0.05f, 2e-3f);
    const SlopeStatistics whole = lean.materials[0].normal_map->lookup(fp.uv, &fp);
    EXPECT_NEAR(mean_of_means.x, whole.mean.x, 2e-3f);
    // Lean and none read the footprint itself.
    const Footprint same = lean.materials[0].normal_map->sample_footprint(fp, 0.9f);
    EXPECT_EQ(same.uv, fp.uv);
    EXPECT_EQ(same.duvdx, fp.duvdx);

    std::string e = load_error(
        scene_with({{"texture", "n.exr"}, {"encoding", "signed"}, {"mixture", 2}}), dir / "s.json");
    EXPECT_NE(e.find("mixture"), std::string::npos) << e;
    EXPECT_NE(e.find("lean_mixture"), std::string::npos) << e;
    e = load_error(scene_with({{"texture", "n.exr"},
                               {"encoding", "signed"},
                               {"filtering", "lean_mixture"},
                               {"mixture", 9}}),
                   dir / "s.json");
    EXPECT_NE(e.find("mixture"), std::string::npos) << e;
    EXPECT_NE(e.find("8"), std::string::npos) << e;
}

TEST(NormalMapReader, BadMapsNameTheFileTheTexelAndTheRange) {
    ScratchDir dir;
    Image black(3, 2, glm::vec3(128, 128, 255));
    black.at(2, 1) = glm::vec3(0.0f);  // decodes to (−1, −1, −1): length 1.73
    write_png_codes(black, dir / "black.png");
    std::string e = load_error(scene_with({{"texture", "black.png"}}), dir / "s.json");
    EXPECT_NE(e.find("black.png"), std::string::npos) << e;
    EXPECT_NE(e.find("/materials/0/normal_map"), std::string::npos) << e;
    EXPECT_NE(e.find("texel (x=2, y=1)"), std::string::npos) << e;
    EXPECT_NE(e.find("[0.5, 1.5]"), std::string::npos) << e;

    write_png_codes(Image(2, 2, glm::vec3(128)), dir / "grey.png");
    e = load_error(scene_with({{"texture", "grey.png"}}), dir / "s.json");
    EXPECT_NE(e.find("grey"), std::string::npos) << e;

    write_png_codes(Image(2, 2, glm::vec3(128, 128, 255)), dir / "flat.png");
    e = load_error(scene_with({{"texture", "flat.png"}, {"encoding", "signed"}}), dir / "s.json");
    EXPECT_NE(e.find("\"unorm\""), std::string::npos) << e;
    e = load_error(scene_with({{"texture", "flat.png"}, {"scale", 11}}), dir / "s.json");
    EXPECT_NE(e.find("scale"), std::string::npos) << e;
    e = load_error(scene_with({{"texture", "flat.png"}, {"filtering", "box"}}), dir / "s.json");
    EXPECT_NE(e.find("lean"), std::string::npos) << e;
    e = load_error(scene_with("flat.png"), dir / "s.json");
    EXPECT_NE(e.find("normal map object"), std::string::npos) << e;
    e = load_error(scene_with({{"texture", "missing.png"}}), dir / "s.json");
    EXPECT_NE(e.find("missing.png"), std::string::npos) << e;

    // A mesh without uvs cannot place the map.
    {
        std::ofstream obj(dir / "tri.obj");
        obj << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    }
    e = load_error(
        scene_with({{"texture", "flat.png"}}, "diffuse", {{"type", "obj"}, {"file", "tri.obj"}}),
        dir / "s.json");
    EXPECT_NE(e.find("normal_map"), std::string::npos) << e;
    EXPECT_NE(e.find("no uvs"), std::string::npos) << e;

    // export and the web page take numbers only: they name the key.
    const Scene flat = parse_scene(scene_with({{"texture", "flat.png"}}), dir / "s.json");
    try {
        require_untextured(flat.materials[0], flat.file, "export");
        ADD_FAILURE() << "no error";
    } catch (const std::exception& ex) {
        EXPECT_NE(std::string(ex.what()).find("normal_map"), std::string::npos) << ex.what();
    }
}

TEST(NormalMapReader, NormalsAtOrBelowTheTangentPlaneAreClampedAndCounted) {
    ScratchDir dir;
    Image n(2, 1);
    n.at(0, 0) = glm::vec3(1.0f, 0.0f, 0.0f);   // in the plane
    n.at(1, 0) = glm::vec3(0.0f, 0.6f, -0.8f);  // below it
    write_exr(n, dir / "n.exr");
    ::testing::internal::CaptureStderr();
    const Scene scene =
        parse_scene(scene_with({{"texture", "n.exr"}, {"encoding", "signed"}}), dir / "s.json");
    const std::string warning = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(warning.find("2 texels"), std::string::npos) << warning;
    const NormalMap& map = *scene.materials[0].normal_map;
    const glm::vec2 a = map.slope_at({0.25f, 0.5f}), b = map.slope_at({0.75f, 0.5f});
    // Clamped to z = 0.05: slope length sqrt(1 − 0.05²)/0.05 ≈ 19.97, azimuth kept.
    EXPECT_NEAR(glm::length(a), 19.97f, 0.01f);
    EXPECT_LT(a.x, 0.0f);
    EXPECT_NEAR(glm::length(b), 19.97f, 0.01f);
    EXPECT_LT(b.y, 0.0f);
}

}  // namespace
}  // namespace glintlab
