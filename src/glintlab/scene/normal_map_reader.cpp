#include "glintlab/scene/normal_map_reader.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "glintlab/core/error.h"

namespace glintlab {
namespace {

// The steepest normal a texel may hold, as its z after normalisation: 87.1°
// from the surface normal, slope 20. Steeper texels (and those at or below
// the tangent plane) are clamped to it, with one warning that counts them:
// slopes grow without bound towards the plane and no lobe is defined below it.
constexpr float kMinNormalZ = 0.05f;

// The second moments (s_x², s_y², s_x s_y) of the surface the bilinear
// lookup reconstructs, averaged over each texel's cell. LEAN mapping as
// published squares the texels, which overstates the spread of a bilinear
// surface (by 9/4 for uncorrelated texels: bilinear weights average
// variance away); the ground truth composes its facets with the bilinear
// surface, so the chain must hold that surface's moments. The cell of texel
// (x, y) is four half-texel squares, each inside one bilinear patch, where
// s² is of degree 2 in each coordinate: 2 × 2 Gauss–Legendre points per
// square integrate it exactly.
std::vector<float> bilinear_cell_moments(const std::vector<glm::vec2>& s, int width, int height,
                                         TextureWraps wrap) {
    const float g = 0.25f / std::sqrt(3.0f);  // node offset in a half-texel interval
    const float nodes[4] = {-0.25f - g, -0.25f + g, 0.25f - g, 0.25f + g};
    std::vector<float> out;
    out.reserve(s.size() * 3);
    auto at = [&](int x, int y) {
        return s[size_t(wrap_texel_index(y, height, wrap.v)) * size_t(width) +
                 size_t(wrap_texel_index(x, width, wrap.u))];
    };
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            glm::vec3 sum(0.0f);
            for (const float oy : nodes)
                for (const float ox : nodes) {
                    const float px = float(x) + ox, py = float(y) + oy;
                    const int ix = int(std::floor(px)), iy = int(std::floor(py));
                    const float fx = px - float(ix), fy = py - float(iy);
                    const glm::vec2 v =
                        glm::mix(glm::mix(at(ix, iy), at(ix + 1, iy), fx),
                                 glm::mix(at(ix, iy + 1), at(ix + 1, iy + 1), fx), fy);
                    sum += glm::vec3(v.x * v.x, v.y * v.y, v.x * v.y);
                }
            sum /= 16.0f;
            out.insert(out.end(), {sum.x, sum.y, sum.z});
        }
    return out;
}

}  // namespace

std::shared_ptr<const NormalMap> read_normal_map(JsonObject& material, std::string_view key,
                                                 TextureFileCache& files) {
    if (const nlohmann::json* v = material.raw(key); !v || !v->is_object())
        material.error(key, "expected a normal map object {\"texture\": \"n.png\", \"scale\": 1}");
    std::optional<JsonObject> block = material.object(key);
    JsonObject& b = *block;
    const TextureSource source = read_texture_source(b, files);
    const std::filesystem::path& file = source.file;
    const std::shared_ptr<const TextureImage>& image = source.image;
    const std::string where = fmt::format("{} ({})", b.path(), file.string());
    // glTF's normalTexture.scale: the x and y components are multiplied by it
    // before the normal is renormalised.
    const float scale = float(b.number("scale", 1.0, -10.0, 10.0));
    // "unorm": the texel holds (n + 1) / 2 (every PNG/JPEG normal map, and
    // EXR maps baked the same way); "signed": the texel is n itself.
    const std::string encoding =
        b.string("encoding", "unorm", std::vector<std::string>{"unorm", "signed"});
    if (encoding == "signed" && image->codes)
        b.error("encoding", fmt::format("{} stores unsigned codes (PNG/JPEG): only \"unorm\" "
                                        "can hold a negative component",
                                        file.string()));
    const std::string filtering =
        b.string("filtering", "lean", std::vector<std::string>{"lean", "lean_mixture", "none"});
    // Sub-footprints per axis: 2 halves the footprint, 8 (64 lobes) reaches
    // level 0 of a map already at a footprint of 8 texels.
    int mixture = 1;
    if (filtering == "lean_mixture")
        mixture = b.integer("mixture", 4, 2, 8);
    else if (b.has("mixture"))
        b.error("mixture", fmt::format("applies only to \"filtering\": \"lean_mixture\" (here "
                                       "\"{}\")",
                                       filtering));
    const TextureWraps wrap = read_texture_wrap(b);
    const TextureUvTransform transform = read_uv_transform(b);
    b.finish();
    if (image->grey())
        fail(
            "{}: every texel is grey (r = g = b): a tangent-space normal map stores x, y, z in "
            "r, g, b (a flat map is (0.5, 0.5, 1)); is this a height or roughness map?",
            where);

    const size_t count = image->texels.size();
    std::vector<glm::vec2> slopes;
    slopes.reserve(count);
    size_t clamped = 0;
    for (size_t i = 0; i < count; ++i) {
        const glm::vec4& t = image->texels[i];
        glm::vec3 n = encoding == "unorm" ? 2.0f * glm::vec3(t) - 1.0f : glm::vec3(t);
        const float length = glm::length(n);
        // Quantised unit normals stay within a few per cent of length 1; a
        // length outside [0.5, 1.5] is not a normal (a colour image, a mask).
        if (!(length >= 0.5f && length <= 1.5f))
            fail(
                "{}: texel (x={}, y={}) decodes to the normal ({:.3f}, {:.3f}, {:.3f}) of length "
                "{:.3f}: a normal map's texels are unit vectors (allowed length [0.5, 1.5]{})",
                where, i % size_t(image->width), i / size_t(image->width), n.x, n.y, n.z, length,
                encoding == "unorm" ? ", as (n + 1) / 2 in [0, 1]" : "");
        n = glm::vec3(n.x * scale, n.y * scale, n.z);
        const float scaled_length = glm::length(n);
        n = scaled_length > 0.0f ? n / scaled_length : glm::vec3(0.0f, 0.0f, 1.0f);
        if (!(n.z >= kMinNormalZ)) {
            // Keep the azimuth, lift the normal to the steepest allowed.
            const glm::vec2 xy(n.x, n.y);
            const float r = glm::length(xy);
            const float s = std::sqrt(1.0f - kMinNormalZ * kMinNormalZ);
            const glm::vec2 dir = r > 0.0f ? xy / r : glm::vec2(1.0f, 0.0f);
            n = glm::vec3(dir * s, kMinNormalZ);
            ++clamped;
        }
        slopes.emplace_back(-n.x / n.z, -n.y / n.z);
    }
    if (clamped > 0)
        fmt::print(stderr,
                   "warning: {}: {} texel{} at or beyond {:.1f}° from the surface normal clamped "
                   "to it\n",
                   where, clamped, clamped == 1 ? "" : "s",
                   std::acos(kMinNormalZ) * 180.0 / 3.14159265358979);

    auto map = std::make_shared<NormalMap>();
    map->filtering = filtering == "lean"           ? NormalMap::Filtering::Lean
                     : filtering == "lean_mixture" ? NormalMap::Filtering::LeanMixture
                                                   : NormalMap::Filtering::None;
    map->mixture = mixture;
    auto make = [&](std::vector<float> texels, int channels) {
        auto input = std::make_shared<TextureInput>();
        input->transform = transform;
        input->source = file.string();
        input->texture = std::make_shared<const MipTexture>(image->width, image->height, channels,
                                                            std::move(texels), wrap);
        return input;
    };
    const std::vector<float> moments =
        bilinear_cell_moments(slopes, image->width, image->height, wrap);
    std::vector<float> first(count * 4), cross(count);
    for (size_t i = 0; i < count; ++i) {
        first[i * 4 + 0] = slopes[i].x;
        first[i * 4 + 1] = slopes[i].y;
        first[i * 4 + 2] = moments[i * 3 + 0];
        first[i * 4 + 3] = moments[i * 3 + 1];
        cross[i] = moments[i * 3 + 2];
    }
    map->slopes = make(std::move(first), 4);
    map->cross_moment = make(std::move(cross), 1);
    return map;
}

}  // namespace glintlab
