#include "glintlab/render/surface_bsdf.h"

#include <algorithm>
#include <cmath>

#include "glintlab/glints/glint_textures.h"
#include "glintlab/render/light_sampling.h"

namespace glintlab {
namespace {

MicrofacetDistribution distribution(NdfType ndf, float ax, float ay) {
    MicrofacetDistribution d;
    d.ndf = ndf;
    d.alpha_x = ax;
    d.alpha_y = ay;
    return d;
}

template <typename... Ts>
struct Overloaded : Ts... {
    using Ts::operator()...;
};

}  // namespace

ShadingFrame shading_frame(const SurfaceHit& hit) {
    ShadingFrame f;
    f.n = hit.ns;
    const glm::vec3 t = hit.dpdu - f.n * glm::dot(f.n, hit.dpdu);
    const float len = glm::length(t);
    if (len > 1e-12f && std::isfinite(len)) {
        f.t = t / len;
        f.b = glm::cross(f.n, f.t);
    } else {
        orthonormal_basis(f.n, &f.t, &f.b);
    }
    return f;
}

SurfaceBsdf make_surface_bsdf(const MaterialDesc& m, const SurfaceHit& hit, glm::vec3 wo,
                              const Footprint* footprint) {
    ShadingFrame frame = shading_frame(hit);
    // Opaque materials are two-sided: look at them from the side of wo. The
    // dielectric keeps its orientation (inside/outside matters for eta).
    if (m.type != MaterialDesc::Type::Dielectric && glm::dot(wo, frame.n) < 0.0f) {
        frame.n = -frame.n;
        frame.b = -frame.b;  // keeps (t, b, n) right-handed
    }
    glm::vec3 albedo = m.albedo;
    float alpha_x = m.alpha_x, alpha_y = m.alpha_y;
    if (m.textures) {
        const MaterialTextures& t = *m.textures;
        if (t.albedo) albedo = t.albedo->lookup(hit.uv, footprint);
        // Conductors and dielectrics take α in [0, 1] (0: a mirror).
        if (t.alpha_x_sq)
            alpha_x = std::sqrt(std::max(t.alpha_x_sq->lookup(hit.uv, footprint).x, 0.0f));
        if (t.alpha_y_sq)
            alpha_y = std::sqrt(std::max(t.alpha_y_sq->lookup(hit.uv, footprint).x, 0.0f));
    }
    switch (m.type) {
        case MaterialDesc::Type::Diffuse: {
            DiffuseBxdf b;
            b.albedo = albedo;
            return SurfaceBsdf(frame, Bxdf(b));
        }
        case MaterialDesc::Type::Conductor: {
            ConductorBxdf b;
            b.dist = distribution(m.ndf, alpha_x, alpha_y);
            b.eta = m.eta;
            b.k = m.k;
            return SurfaceBsdf(frame, Bxdf(b));
        }
        case MaterialDesc::Type::Dielectric: {
            DielectricBxdf b;
            b.dist = distribution(m.ndf, alpha_x, alpha_y);
            b.eta = m.eta.x;
            return SurfaceBsdf(frame, Bxdf(b));
        }
        case MaterialDesc::Type::Plastic: {
            PlasticBxdf b;
            b.diffuse = albedo;
            b.dist = distribution(m.ndf, alpha_x, alpha_y);
            b.eta = m.eta.x;
            return SurfaceBsdf(frame, Bxdf(b));
        }
        case MaterialDesc::Type::Glint:
            break;
    }
    GlintBxdf g;
    g.desc = &m.glint;
    if (footprint) {
        g.has_footprint = true;
        g.footprint = *footprint;
    }
    if (m.glint.textures)
        return SurfaceBsdf(
            frame, g,
            std::make_shared<const GlintDesc>(resolve_glint_textures(m.glint, hit.uv, footprint)));
    return SurfaceBsdf(frame, g);
}

glm::vec3 SurfaceBsdf::f(glm::vec3 wo, glm::vec3 wi) const {
    const glm::vec3 lo = frame_.to_local(wo), li = frame_.to_local(wi);
    return std::visit(Overloaded{[&](const Bxdf& b) { return bxdf_f(b, lo, li); },
                                 [&](const GlintBxdf& b) { return b.f(lo, li); }},
                      lobe_);
}

float SurfaceBsdf::pdf(glm::vec3 wo, glm::vec3 wi) const {
    const glm::vec3 lo = frame_.to_local(wo), li = frame_.to_local(wi);
    return std::visit(Overloaded{[&](const Bxdf& b) { return bxdf_pdf(b, lo, li); },
                                 [&](const GlintBxdf& b) { return b.pdf(lo, li); }},
                      lobe_);
}

std::optional<BsdfSample> SurfaceBsdf::sample(glm::vec3 wo, float uc, glm::vec2 u) const {
    const glm::vec3 lo = frame_.to_local(wo);
    auto s = std::visit(Overloaded{[&](const Bxdf& b) { return bxdf_sample(b, lo, uc, u); },
                                   [&](const GlintBxdf& b) { return b.sample(lo, uc, u); }},
                        lobe_);
    if (s) s->wi = frame_.to_world(s->wi);
    return s;
}

bool SurfaceBsdf::is_specular() const {
    return std::visit(Overloaded{[&](const Bxdf& b) { return bxdf_is_specular(b); },
                                 [&](const GlintBxdf& b) { return b.is_specular(); }},
                      lobe_);
}

}  // namespace glintlab
