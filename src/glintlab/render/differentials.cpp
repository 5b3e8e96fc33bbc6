#include "glintlab/render/differentials.h"

#include <cmath>

namespace glintlab {
namespace {

// a·b − c·d with one rounding error (Kahan's algorithm via fma).
float difference_of_products(float a, float b, float c, float d) {
    const float cd = c * d;
    const float err = std::fma(-c, d, cd);
    const float dop = std::fma(a, b, -cd);
    return dop + err;
}

float clamp_finite(float v) {
    // Grazing rays can give huge or non-finite derivatives; pbrt clamps to ±1e8.
    return std::isfinite(v) ? std::clamp(v, -1e8f, 1e8f) : 0.0f;
}

}  // namespace

SurfaceDifferentials compute_differentials(const RayDifferential& ray, const SurfaceHit& hit,
                                           float scale) {
    SurfaceDifferentials out;
    out.footprint.uv = hit.uv;
    out.footprint.duvdx = out.footprint.duvdy = glm::vec2(0.0f);
    if (!ray.has_differentials) return out;
    const glm::vec3 d0 = glm::normalize(ray.ray.d);
    out.dwodx = (d0 - glm::normalize(ray.rx.d)) * scale;
    out.dwody = (d0 - glm::normalize(ray.ry.d)) * scale;
    if (!std::isfinite(out.dwodx.x + out.dwodx.y + out.dwodx.z + out.dwody.x + out.dwody.y +
                       out.dwody.z))
        out.dwodx = out.dwody = glm::vec3(0.0f);
    const glm::vec3 n = hit.ng;
    const float d = glm::dot(n, hit.p);
    auto plane_point = [&](const Ray& r, glm::vec3* p) {
        const float denom = glm::dot(n, r.d);
        if (denom == 0.0f) return false;
        const float t = (d - glm::dot(n, r.o)) / denom;
        if (!std::isfinite(t)) return false;
        *p = r.o + t * r.d;
        return true;
    };
    glm::vec3 px, py;
    if (!plane_point(ray.rx, &px) || !plane_point(ray.ry, &py)) return out;
    out.dpdx = (px - hit.p) * scale;
    out.dpdy = (py - hit.p) * scale;

    // Least squares: [dpdu dpdv] (du, dv)ᵀ ≈ dpdx, via the 2x2 normal equations.
    const float ata00 = glm::dot(hit.dpdu, hit.dpdu), ata01 = glm::dot(hit.dpdu, hit.dpdv);
    const float ata11 = glm::dot(hit.dpdv, hit.dpdv);
    float inv_det = 1.0f / difference_of_products(ata00, ata11, ata01, ata01);
    if (!std::isfinite(inv_det)) inv_det = 0.0f;
    const float atb0x = glm::dot(hit.dpdu, out.dpdx), atb1x = glm::dot(hit.dpdv, out.dpdx);
    const float atb0y = glm::dot(hit.dpdu, out.dpdy), atb1y = glm::dot(hit.dpdv, out.dpdy);
    out.footprint.duvdx = {
        clamp_finite(difference_of_products(ata11, atb0x, ata01, atb1x) * inv_det),
        clamp_finite(difference_of_products(ata00, atb1x, ata01, atb0x) * inv_det)};
    out.footprint.duvdy = {
        clamp_finite(difference_of_products(ata11, atb0y, ata01, atb1y) * inv_det),
        clamp_finite(difference_of_products(ata00, atb1y, ata01, atb0y) * inv_det)};
    return out;
}

}  // namespace glintlab
