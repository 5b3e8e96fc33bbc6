#include "glintlab/scene/shapes_heightfield.h"

#include <algorithm>
#include <cmath>

#include "glintlab/core/error.h"
#include "glintlab/core/hash.h"

namespace glintlab {

namespace {

void check_settings(const HeightfieldSettings& s) {
    if (!(s.size.x > 0.0f) || !(s.size.y > 0.0f) || !std::isfinite(s.size.x) ||
        !std::isfinite(s.size.y))
        fail("heightfield: size must be finite and > 0, got ({}, {})", s.size.x, s.size.y);
    if (s.resolution < 1 || s.resolution > 4096)
        fail("heightfield: resolution must be in [1, 4096], got {}", s.resolution);
    if (!std::isfinite(s.amplitude))
        fail("heightfield: amplitude must be finite, got {}", s.amplitude);
    if (!(s.frequency > 0.0f) || !std::isfinite(s.frequency))
        fail("heightfield: frequency must be finite and > 0, got {}", s.frequency);
    if (s.octaves < 1 || s.octaves > 16)
        fail("heightfield: octaves must be in [1, 16], got {}", s.octaves);
}

// Lattice value in [-1, 1) at an integer cell corner.
float lattice_value(glm::ivec2 corner, uint32_t seed) {
    return 2.0f * shader::uint_to_unit_float(shader::hash_cell(corner, seed)) - 1.0f;
}

// Quintic fade 6t^5 - 15t^4 + 10t^3: first and second derivatives vanish at
// the lattice lines, so the interpolated field (and its normals) is smooth
// across cells.
float fade(float t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

float value_noise(glm::vec2 x, uint32_t seed) {
    const glm::vec2 cell = glm::floor(x);
    const glm::ivec2 c(cell);
    const glm::vec2 f = x - cell;
    const float wx = fade(f.x);
    const float wy = fade(f.y);
    const float v00 = lattice_value(c, seed);
    const float v10 = lattice_value(c + glm::ivec2(1, 0), seed);
    const float v01 = lattice_value(c + glm::ivec2(0, 1), seed);
    const float v11 = lattice_value(c + glm::ivec2(1, 1), seed);
    return glm::mix(glm::mix(v00, v10, wx), glm::mix(v01, v11, wx), wy);
}

}  // namespace

float procedural_height(const HeightfieldSettings& settings, glm::vec2 uv) {
    float sum = 0.0f;
    float weight_sum = 0.0f;
    float weight = 1.0f;
    float frequency = settings.frequency;
    for (int k = 0; k < settings.octaves; ++k) {
        // Each octave gets its own lattice so octaves are not scaled copies.
        const uint32_t octave_seed = shader::hash_combine(settings.seed, static_cast<uint32_t>(k));
        sum += weight * value_noise(uv * frequency, octave_seed);
        weight_sum += weight;
        weight *= 0.5f;
        frequency *= 2.0f;
    }
    return sum / weight_sum;
}

TriangleMesh make_heightfield(const HeightfieldSettings& settings,
                              std::function<float(glm::vec2 uv)> height) {
    check_settings(settings);
    if (!height) height = [&settings](glm::vec2 uv) { return procedural_height(settings, uv); };
    const int n = settings.resolution;
    const int stride = n + 1;
    const float step = 1.0f / static_cast<float>(n);

    // Sample the height once per vertex; the normals reuse the samples.
    std::vector<float> h(static_cast<size_t>(stride) * stride);
    auto at = [&](int i, int j) -> float& { return h[static_cast<size_t>(j) * stride + i]; };
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const glm::vec2 uv(static_cast<float>(i) * step, static_cast<float>(j) * step);
            at(i, j) = settings.amplitude * height(uv);
        }

    TriangleMesh mesh;
    const size_t count = h.size();
    mesh.positions.reserve(count);
    mesh.normals.reserve(count);
    mesh.uvs.reserve(count);
    const glm::vec2 s = settings.size;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            const glm::vec2 uv(static_cast<float>(i) * step, static_cast<float>(j) * step);
            mesh.positions.emplace_back((uv.x - 0.5f) * s.x, at(i, j), (0.5f - uv.y) * s.y);
            mesh.uvs.push_back(uv * settings.uv_scale);
            // Derivatives of the displaced height y(u, v) by differences over
            // the neighbouring samples (one-sided on the border).
            const int i0 = std::max(i - 1, 0), i1 = std::min(i + 1, n);
            const int j0 = std::max(j - 1, 0), j1 = std::min(j + 1, n);
            const float dy_du = (at(i1, j) - at(i0, j)) / (static_cast<float>(i1 - i0) * step);
            const float dy_dv = (at(i, j1) - at(i, j0)) / (static_cast<float>(j1 - j0) * step);
            // p(u, v) = ((u - 1/2) sx, y, (1/2 - v) sz), so
            // dp/du = (sx, y_u, 0), dp/dv = (0, y_v, -sz) and
            // n = dp/du x dp/dv = (-sz y_u, sx sz, sx y_v).
            const glm::vec3 normal(-s.y * dy_du, s.x * s.y, s.x * dy_dv);
            mesh.normals.push_back(glm::normalize(normal));
        }
    }
    // Same layout as make_quad: i runs along +x (u), j along -z (v), and
    // cross(dp/du, dp/dv) is +y, so (a, b, c) with b = a + du, c = b + dv is
    // counter-clockwise seen from above.
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const auto a = static_cast<unsigned>(j * stride + i);
            const unsigned b = a + 1, c = b + static_cast<unsigned>(stride),
                           d = a + static_cast<unsigned>(stride);
            mesh.triangles.emplace_back(a, b, c);
            mesh.triangles.emplace_back(a, c, d);
        }
    return mesh;
}

}  // namespace glintlab
