#include "glintlab/render/image_check.h"

#include <cmath>

#include <fmt/format.h>

#include "glintlab/core/error.h"
#include "glintlab/glints/registry.h"
#include "glintlab/render/accel.h"

namespace glintlab {
namespace {

bool finite(glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

std::optional<BadPixel> find_non_finite_pixel(const Image& image) {
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (!finite(image.at(x, y))) return BadPixel{x, y, image.at(x, y)};
    return std::nullopt;
}

std::string describe_pixel_surface(const Scene& scene, int x, int y) {
    const Accelerator accel(scene);
    const RayDifferential rd = scene.camera.generate(glm::vec2(float(x) + 0.5f, float(y) + 0.5f));
    const std::optional<SurfaceHit> hit = accel.intersect(rd.ray, INFINITY);
    if (!hit || hit->shape < 0 || hit->shape >= int(scene.shapes.size()))
        return "no surface at the pixel centre (the background / environment)";
    const Shape& shape = scene.shapes[size_t(hit->shape)];
    if (shape.material < 0 || shape.material >= int(scene.materials.size()))
        return fmt::format("shape '{}' (no material)", shape.name);
    const MaterialDesc& m = scene.materials[size_t(shape.material)];
    if (m.type == MaterialDesc::Type::Glint)
        return fmt::format("shape '{}', material '{}' (glint, model {})", shape.name, m.name,
                           glint_model(m.glint.model_id).name);
    return fmt::format("shape '{}', material '{}' ({})", shape.name, m.name,
                       material_type_name(m.type));
}

void require_finite_image(const Scene& scene, const Image& image, const std::string& what) {
    const std::optional<BadPixel> bad = find_non_finite_pixel(image);
    if (!bad) return;
    int count = 0;
    for (const glm::vec3& v : image.pixels) count += finite(v) ? 0 : 1;
    fail(
        "{}: {} pixel(s) are NaN or Inf (a defect of the renderer, please report it); the first, "
        "pixel ({}, {}) = ({}, {}, {}), shows {}",
        what, count, bad->x, bad->y, bad->value.x, bad->value.y, bad->value.z,
        describe_pixel_surface(scene, bad->x, bad->y));
}

}  // namespace glintlab
