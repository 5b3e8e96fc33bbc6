#include "glintlab/render/render_memory.h"

#include <fmt/format.h>

#include "glintlab/scene/environment.h"

namespace glintlab {

std::vector<MemoryItem> estimate_render_memory(const Scene& scene, bool gpu) {
    std::vector<MemoryItem> items;
    const uint64_t pixels = uint64_t(scene.camera.width) * uint64_t(scene.camera.height);
    // CPU: the linear image, the per-pixel glint layer of image passes
    // (GlintPostSample, 5 floats), the bloomed preview and its blur scratch
    // (3 RGB float images), the 8-bit PNG. GPU: in addition two RGBA32F
    // colour attachments, a 32-bit depth buffer and the read-back copy.
    uint64_t per_pixel = 12 + 20 + 3 * 12 + 3;
    if (gpu) per_pixel += 2 * 16 + 4 + 16;
    items.push_back({fmt::format("film {}x{} ({} bytes per pixel)", scene.camera.width,
                                 scene.camera.height, per_pixel),
                     pixels * per_pixel});
    uint64_t triangles = 0, vertices = 0;
    for (const Shape& s : scene.shapes) {
        if (const auto* mesh = std::get_if<TriangleMesh>(&s.geometry)) {
            triangles += mesh->triangles.size();
            vertices += mesh->positions.size();
        }
    }
    if (triangles > 0) {
        // Positions, normals, uvs (32 bytes per vertex) and indices as loaded,
        // Embree's copy of them and its BVH (~64 bytes per triangle), the
        // per-triangle ∂p/∂u, ∂p/∂v (24 bytes).
        const uint64_t bytes = vertices * 32 * 2 + triangles * (12 * 2 + 64 + 24);
        items.push_back(
            {fmt::format("meshes ({} triangles, {} vertices, with the BVH)", triangles, vertices),
             bytes});
    }
    for (const Light& l : scene.lights) {
        if (const auto* e = std::get_if<EnvironmentLight>(&l); e && e->map) {
            const Image& img = e->map->image();
            // RGB float texels, plus the sampling distribution's weights and
            // CDFs (2 floats per cell of the grid refined to >= 64 rows).
            const uint64_t texels = uint64_t(img.width) * uint64_t(img.height);
            items.push_back(
                {fmt::format("environment map {}x{}", img.width, img.height), texels * (12 + 8)});
        }
    }
    return items;
}

}  // namespace glintlab
