#include "glintlab/render/surface_bsdf.h"

#include <algorithm>
#include <cmath>

#include "glintlab/core/glsl.h"
#include "glintlab/core/normal_map.h"
#include "glintlab/glints/glint_textures.h"
#include "glintlab/glints/registry.h"
#include "glintlab/render/light_sampling.h"

// The widening, the slopes' correlation and the visible mean normal, as the
// forward pass and the exported shaders compute them.
GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/core/slope_frame.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {
namespace {

MicrofacetDistribution distribution(NdfType ndf, float ax, float ay) {
    MicrofacetDistribution d;
    d.ndf = ndf;
    d.alpha_x = ax;
    d.alpha_y = ay;
    return d;
}

// The normal map at a hit, in the hit's local frame (docs/MODELS.md,
// "Normal maps"): the footprint's mean slope and slope covariance, and the
// signs that carry the map's (x, y) onto the frame's (t, b).
struct LocalBump {
    Footprint footprint;  // the one the map was read over (a sub-footprint under lean_mixture)
    bool filtered = false;
    SlopeStatistics slopes;  // in the shading frame's axes
    glm::vec2 axes{1.0f};
};

// `correlated`: the lobe reads Σ_xy (left 0 otherwise).
LocalBump local_bump(const NormalMap& map, const SurfaceHit& hit, const ShadingFrame& frame,
                     bool back, const SurfaceDifferentials* differentials, bool correlated) {
    LocalBump bump;
    bump.footprint.uv = hit.uv;
    if (differentials) {
        bump.footprint = map.sample_footprint(differentials->footprint, differentials->mixture_u);
        bump.filtered = true;
    }
    // glTF's bitangent: "up" in the image, i.e. against ∂p/∂v (v runs down
    // the image); frame.b = n × t is it unless the uv mapping is mirrored.
    // A mesh's vertex tangents carry that sign (w).
    if (hit.tangent.w != 0.0f)
        bump.axes.y = hit.tangent.w;
    else
        bump.axes.y = glm::dot(frame.b, hit.dpdv) <= 0.0f ? 1.0f : -1.0f;
    // Seen from behind, the surface's normal is −n: the map's normal (x, y,
    // z) becomes (−x, y, z) in the flipped frame (t, −b, −n).
    if (back) bump.axes.x = -1.0f;
    bump.slopes =
        map.lookup(bump.footprint.uv, bump.filtered ? &bump.footprint : nullptr, correlated);
    bump.slopes.mean *= bump.axes;
    bump.slopes.covariance.z *= bump.axes.x * bump.axes.y;
    return bump;
}

// Whether the lobe of material m reads the map's Σ_xy: every lobe but a
// diffuse one, and the glint lobes of models that widen by the map and
// shear their target by the correlation (as the forward pass decides it).
bool reads_map_correlation(const MaterialDesc& m) {
    if (m.type == MaterialDesc::Type::Diffuse) return false;
    if (m.type != MaterialDesc::Type::Glint) return true;
    const GlintModelDescriptor& model = glint_model(m.glint.model_id);
    return m.glint.model_id != GlintModelId::Explicit && model.textured_roughness &&
           model.reads_slope_correlation && model.reads_slope_correlation(m.glint);
}

// The frame around the footprint's mean normal, its tangent the projection
// of the base frame's (∂p/∂u).
ShadingFrame tilted_frame(const ShadingFrame& base, glm::vec3 local_normal) {
    ShadingFrame f;
    glm::vec3 t, b;
    tangent_frame_around(local_normal, &t, &b);
    f.n = base.to_world(local_normal);
    f.t = base.to_world(t);
    f.b = base.to_world(b);
    return f;
}

// The surface's own turning over the footprint (docs/MODELS.md, "Curved
// surfaces"): the macro normal's slope in the local frame (t, b, n) as a
// linear function of the uv offset, columns ∂s/∂u and ∂s/∂v. At the hit the
// slope is 0 and ∂s = −(t·∂n, b·∂n) (s = (−x/z, −y/z), normal_map.h).
// `back`: the frame was flipped to the side of wo, so the normal is −ns.
glm::mat2 macro_slope_gradient(const SurfaceHit& hit, const ShadingFrame& frame, bool back) {
    const float sign = back ? 1.0f : -1.0f;
    const glm::vec3 du = sign * hit.dndu, dv = sign * hit.dndv;
    return glm::mat2(glm::vec2(glm::dot(frame.t, du), glm::dot(frame.b, du)),
                     glm::vec2(glm::dot(frame.t, dv), glm::dot(frame.b, dv)));
}

// The covariance (xx, yy, xy) of slopes J Δ over the footprint's
// parallelogram, Δ uniform over {a duvdx + b duvdy : a, b in [−½, ½]}:
// J (duvdx duvdxᵀ + duvdy duvdyᵀ) Jᵀ / 12 (a uniform variable on a unit
// interval has variance 1/12).
glm::vec3 footprint_slope_covariance(const glm::mat2& J, const Footprint& fp) {
    return shader::linear_slope_covariance(J * fp.duvdx, J * fp.duvdy);
}

// The pixel's view differentials in the shading frame (core/
// view_differentials.glsl): the ray differentials' change of the direction
// to the eye, and the unit shading normal's change ∂n/∂u ∂u/∂x + ∂n/∂v ∂v/∂x
// over the footprint (negated with the two-sided flip, `back`), as the
// forward pass takes dFdx of the same two vectors.
ViewDifferentials view_differentials(const SurfaceDifferentials& d, const SurfaceHit& hit,
                                     const ShadingFrame& frame, bool back, glm::vec3 wo) {
    const float sign = back ? -1.0f : 1.0f;
    const glm::vec2 duvdx = d.footprint.duvdx, duvdy = d.footprint.duvdy;
    const glm::vec3 dndx = sign * (duvdx.x * hit.dndu + duvdx.y * hit.dndv);
    const glm::vec3 dndy = sign * (duvdy.x * hit.dndu + duvdy.y * hit.dndv);
    ViewDifferentials v;
    v.wo = frame.to_local(glm::normalize(wo));
    v.wo_dx = frame.to_local(d.dwodx);
    v.wo_dy = frame.to_local(d.dwody);
    v.n_dx = glm::vec2(glm::dot(frame.t, dndx), glm::dot(frame.b, dndx));
    v.n_dy = glm::vec2(glm::dot(frame.t, dndy), glm::dot(frame.b, dndy));
    const float all = v.wo_dx.x + v.wo_dx.y + v.wo_dx.z + v.wo_dy.x + v.wo_dy.y + v.wo_dy.z +
                      v.n_dx.x + v.n_dx.y + v.n_dy.x + v.n_dy.y;
    if (!std::isfinite(all)) {  // no sweep: the unfiltered lookup
        v.wo_dx = v.wo_dy = glm::vec3(0.0f);
        v.n_dx = v.n_dy = glm::vec2(0.0f);
    }
    return v;
}

template <typename... Ts>
struct Overloaded : Ts... {
    using Ts::operator()...;
};
// C++20 deduces this from the aggregate; clang 14 (the sanitizer tree's
// compiler) does not yet, so the guide is spelled out.
template <typename... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

}  // namespace

ShadingFrame shading_frame(const SurfaceHit& hit, bool vertex_tangent) {
    ShadingFrame f;
    f.n = hit.ns;
    // The candidate tangents in order, made orthogonal to n; the first that
    // is not degenerate wins.
    auto take = [&f](glm::vec3 candidate) {
        const glm::vec3 t = candidate - f.n * glm::dot(f.n, candidate);
        const float len = glm::length(t);
        if (!(len > 1e-12f && std::isfinite(len))) return false;
        f.t = t / len;
        f.b = glm::cross(f.n, f.t);
        return true;
    };
    if (vertex_tangent && hit.tangent.w != 0.0f && take(glm::vec3(hit.tangent))) return f;
    if (!take(hit.dpdu)) orthonormal_basis(f.n, &f.t, &f.b);
    return f;
}

SurfaceBsdf make_surface_bsdf(const MaterialDesc& m, const SurfaceHit& hit, glm::vec3 wo,
                              const SurfaceDifferentials* differentials) {
    const Footprint* footprint = differentials ? &differentials->footprint : nullptr;
    ShadingFrame frame = shading_frame(hit, m.normal_map != nullptr);
    // Opaque materials are two-sided: look at them from the side of wo. The
    // dielectric keeps its orientation (inside/outside matters for eta).
    const bool back = m.type != MaterialDesc::Type::Dielectric && glm::dot(wo, frame.n) < 0.0f;
    std::optional<LocalBump> bump;
    if (m.normal_map)
        bump = local_bump(*m.normal_map, hit, frame, back, differentials, reads_map_correlation(m));
    if (back) {
        frame.n = -frame.n;
        frame.b = -frame.b;  // keeps (t, b, n) right-handed
    }
    // wo in the base frame; the mean normal is kept facing it
    // (core/slope_frame.glsl visible_slope), as the ground truth keeps each
    // facet's map normal.
    const glm::vec3 wo_base = frame.to_local(glm::normalize(wo));
    if (bump) bump->slopes.mean = shader::visible_slope(bump->slopes.mean, wo_base);
    // The glint material's curvature over the footprint, in the base frame.
    glm::mat2 slope_gradient(0.0f);
    glm::vec3 curvature_cov(0.0f);
    if (m.type == MaterialDesc::Type::Glint && m.glint.curvature && footprint) {
        slope_gradient = macro_slope_gradient(hit, frame, back);
        curvature_cov = footprint_slope_covariance(slope_gradient, *footprint);
        if (!std::isfinite(curvature_cov.x + curvature_cov.y + curvature_cov.z)) {
            slope_gradient = glm::mat2(0.0f);
            curvature_cov = glm::vec3(0.0f);
        }
    }
    const bool curved = slope_gradient != glm::mat2(0.0f);
    // The frame every lobe but the ground truth's sees: tilted to the
    // footprint's mean normal. (`explicit` keeps the base frame and
    // composes each facet with the map at its own position.)
    const ShadingFrame base_frame = frame;
    if (bump) frame = tilted_frame(frame, bump->slopes.normal());
    glm::vec3 albedo = m.albedo;
    float metallic = m.metallic;
    float alpha_x = m.alpha_x, alpha_y = m.alpha_y;
    if (m.textures) {
        const MaterialTextures& t = *m.textures;
        if (t.albedo) albedo = t.albedo->lookup(hit.uv, footprint);
        // One lookup for the one-value inputs that share a packed texture
        // (a glTF metallic-roughness map's roughness and metallic).
        const TextureInput* scalars[3] = {t.metallic.get(), t.alpha_x_sq.get(), t.alpha_y_sq.get()};
        float values[3] = {metallic, alpha_x * alpha_x, alpha_y * alpha_y};
        lookup_scalars(scalars, hit.uv, footprint, values);
        // The footprint's mean metallic mixes the two lobes as the texels do:
        // f is linear in it.
        metallic = std::clamp(values[0], 0.0f, 1.0f);
        // Conductors and dielectrics take α in [0, 1] (0: a mirror).
        if (t.alpha_x_sq) alpha_x = std::sqrt(std::max(values[1], 0.0f));
        if (t.alpha_y_sq) alpha_y = std::sqrt(std::max(values[2], 0.0f));
    }
    if (bump && m.type != MaterialDesc::Type::Diffuse && m.type != MaterialDesc::Type::Glint) {
        const glm::vec3 c = bump->slopes.covariance;
        // The lobe of slope covariance diag(α_x², α_y²)/2 + Σ, Σ_xy included,
        // is an anisotropic lobe along that matrix's principal axes: the
        // frame turns to them.
        const glm::vec3 lobe = shader::principal_slope_lobe(
            shader::slope_widened_alpha(alpha_x, c.x, 4.0f),
            shader::slope_widened_alpha(alpha_y, c.y, 4.0f), c.z, 4.0f);
        alpha_x = lobe.x;
        alpha_y = lobe.y;
        if (lobe.z != 0.0f) {
            const glm::vec3 t = std::cos(lobe.z) * frame.t + std::sin(lobe.z) * frame.b;
            frame.t = t;
            frame.b = glm::cross(frame.n, t);
        }
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
        case MaterialDesc::Type::MetallicRoughness: {
            MetallicRoughnessBxdf b;
            b.base_color = albedo;
            b.metallic = metallic;
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
        g.has_view = true;
        g.view = view_differentials(*differentials, hit, frame, back, wo);
    }
    const GlintModelDescriptor& model = glint_model(m.glint.model_id);
    const bool is_explicit = m.glint.model_id == GlintModelId::Explicit;
    const bool widens_curvature = curved && model.filters_curvature;
    if (!m.glint.textures && !bump && !widens_curvature && !(curved && is_explicit))
        return SurfaceBsdf(frame, g);
    auto resolved = std::make_shared<GlintDesc>(resolve_glint_textures(m.glint, hit.uv, footprint));
    if (is_explicit) {
        // The ground truth composes each facet with the map and the curved
        // surface at its own position, in the base frame.
        if (bump) {
            resolved->normal_map = m.normal_map;
            resolved->normal_map_axes = bump->axes;
            resolved->normal_map_view = wo_base;
        }
        resolved->slope_gradient = slope_gradient;
        return SurfaceBsdf(base_frame, g, std::move(resolved));
    }
    // Models whose precomputed tables hold one roughness (wang2020,
    // kneiphof2025: glint_model_descriptor.h) take the mean normal only.
    const bool map_widens = bump && model.textured_roughness;
    if (map_widens || widens_curvature) {
        glm::vec3 c = widens_curvature ? curvature_cov : glm::vec3(0.0f);
        if (map_widens) c += bump->slopes.covariance;  // Σ_xy 0 where not read
        // Glint NDF axes stay on the uv axes (the models' grids follow
        // them): a model that reads the slopes' correlation shears its
        // target by it (chermain2020 with Chermain et al. 2021's slope
        // correlation, the D of smooth, deliot2023, zirr2016 and jakob2014);
        // the others drop it.
        const bool correlated =
            model.reads_slope_correlation && model.reads_slope_correlation(*resolved);
        resolved->alpha_x = shader::slope_widened_alpha(resolved->alpha_x, c.x, 1.0f);
        resolved->alpha_y = shader::slope_widened_alpha(resolved->alpha_y, c.y, 1.0f);
        resolved->alpha_varies = true;
        if (correlated && c.z != 0.0f)
            resolved->slope_correlation =
                shader::slope_correlation(c.z, resolved->alpha_x, resolved->alpha_y);
    }
    return SurfaceBsdf(frame, g, std::move(resolved));
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
