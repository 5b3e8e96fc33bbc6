// A normal map's footprint statistics turned into a shading frame and a
// widened lobe: the GLSL side of core/normal_map.h (normal_from_slope,
// tangent_frame_around) and render/surface_bsdf.cpp (the α² + 2Σ widening),
// shared by the forward pass (realtime/shaders/normal_map.glsl), the
// export (export/glint_export.frag.glsl) and the CPU's widening
// (render/surface_bsdf.cpp), so all tilt and widen alike.
// Slopes follow the microfacet convention (Heitz 2014, Eq. 36): a normal
// (x, y, z) of the tangent frame has slope (−x/z, −y/z).
#ifndef GLINTLAB_CORE_SLOPE_FRAME_GLSL
#define GLINTLAB_CORE_SLOPE_FRAME_GLSL

// core/normal_map.cpp kMomentLodBias: the moments are read at log2(1/√3)
// relative to OpenGL's level of detail, the window with the footprint's
// own spatial variance.
const float kSlopeMomentLodBias = -0.79248125f;

// Σ = E[s sᵀ] − s̄ s̄ᵀ from the filtered first and second moments, kept
// positive semi-definite: (xx, yy, xy). `second_xy`: E[s_x s_y], or 0 with
// `correlated` false where only the variances are wanted.
vec3 slope_covariance(vec2 mean, vec2 second, float second_xy, bool correlated) {
    float xx = max(second.x - mean.x * mean.x, 0.0f);
    float yy = max(second.y - mean.y * mean.y, 0.0f);
    if (!correlated) return vec3(xx, yy, 0.0f);
    float bound = sqrt(xx * yy);
    return vec3(xx, yy, clamp(second_xy - mean.x * mean.y, -bound, bound));
}

// Slope statistics of a map in glTF's tangent frame (x along ∂p/∂u, y along
// bitangent_sign (n × t)) expressed in the shading frame (t, b = n × t, n),
// after the two-sided flip that negates n and b (`back`): the slope's x
// changes sign with the flip, its y with a mirrored bitangent.
vec2 mean_slope_in_shading_frame(bool back, float bitangent_sign, vec2 mean) {
    return mean * vec2(back ? -1.0f : 1.0f, bitangent_sign);
}
void slopes_in_shading_frame(bool back, float bitangent_sign, INOUT(vec2) mean,
                             INOUT(vec3) cov) {
    mean = mean_slope_in_shading_frame(back, bitangent_sign, mean);
    cov.z *= (back ? -1.0f : 1.0f) * bitangent_sign;
}

// Tilts the frame (t, b, n) to the normal of slope `mean` in it,
// normalize(−s̄x, −s̄y, 1); the new tangent is the old one's projection
// (core/normal_map.h tangent_frame_around).
void tilt_frame_to_slope(vec2 mean, INOUT(vec3) t, INOUT(vec3) b, INOUT(vec3) n) {
    vec3 nl = normalize(vec3(-mean.x, -mean.y, 1.0f));
    vec3 tl = normalize(vec3(1.0f, 0.0f, 0.0f) - nl * nl.x);
    vec3 bl = cross(nl, tl);
    vec3 tw = tl.x * t + tl.y * b + tl.z * n;
    vec3 bw = bl.x * t + bl.y * b + bl.z * n;
    vec3 nw = nl.x * t + nl.y * b + nl.z * n;
    t = tw;
    b = bw;
    n = nw;
}

// A mapped normal that faces away from the viewer would shade its pixel
// black (every lobe and the ground truth's facets need wo above their
// surface), and one just past the boundary would switch a region from lit
// to black between two frames. So the mapped normal is turned towards the
// base normal, in their common plane, until wo makes at least this
// fraction of its cosine with the base normal: wo·n ≥ 0.1 wo_z. (Blender
// Cycles bends its shading normals in the same plane for the same reason,
// with a criterion on the mirror direction.) Normals that pass are kept.
// The fraction: on the compare suite's bumps at grazing view (LEAN) the
// one-lobe filter's excess over the truth grows with it (smooth +16.9 %,
// +17.6 %, +20.5 % at 0.01, 0.1, 0.25), the unfiltered rows do not move,
// and 0.1 keeps the turned normal clear of the grazing limit.
const float kVisibleNormalCosFraction = 0.1f;

// wo·n of the unit normal of slope s, normalize(−s_x, −s_y, 1); wo unit.
float cos_to_slope_normal(vec2 s, vec3 wo) {
    return (wo.z - dot(s, vec2(wo.x, wo.y))) / sqrt(1.0f + dot(s, s));
}

// The slope s shortened to k s, k in [0, 1] the largest that keeps
// wo·n ≥ kVisibleNormalCosFraction wo_z (a single crossing: (wo_z − k a)² =
// c² (1 + k² |s|²) has one root where wo_z − k a > 0 and the cosine falls
// from wo_z at k = 0 below c at k = 1). Bisection to 2⁻²⁴, only where the
// slope fails; continuous in s and wo. wo_z ≤ 0 (no view given): s.
vec2 visible_slope(vec2 s, vec3 wo) {
    float c = kVisibleNormalCosFraction * wo.z;
    if (!(wo.z > 0.0f) || cos_to_slope_normal(s, wo) >= c) return s;
    float lo = 0.0f;
    float hi = 1.0f;
    for (int i = 0; i < 24; ++i) {
        float mid = 0.5f * (lo + hi);
        if (cos_to_slope_normal(mid * s, wo) >= c)
            lo = mid;
        else
            hi = mid;
    }
    return lo * s;
}

// A lobe's α along an axis widened by the footprint's slope variance along
// it: α² + 2σ² (a Beckmann lobe's α² is twice its slope variance; LEAN
// mapping, Olano & Baker, I3D 2010), at most max_alpha.
float slope_widened_alpha(float alpha, float slope_variance, float max_alpha) {
    return min(sqrt(alpha * alpha + 2.0f * slope_variance), max_alpha);
}

// A lobe of slope covariance C = [[α_x²/2, c_xy], [c_xy, α_y²/2]] (a lobe
// already widened along x and y, and the footprint's Σ_xy) along C's
// principal axes: (α_1, α_2, θ), axis 1 at θ from x (radians, in (−π/2,
// π/2]), each α at most max_alpha. Beckmann's and GGX's slopes depend on
// sᵀC⁻¹s only, so the sheared lobe (ndf.glsl D_Microfacet_correlated) is this
// anisotropic one turned by θ exactly. θ = 0 where c_xy = 0.
vec3 principal_slope_lobe(float alpha_x, float alpha_y, float covariance_xy, float max_alpha) {
    float xx = 0.5f * alpha_x * alpha_x, yy = 0.5f * alpha_y * alpha_y;
    if (covariance_xy == 0.0f || isnan(covariance_xy) || isinf(covariance_xy))
        return vec3(alpha_x, alpha_y, 0.0f);
    float angle = 0.5f * atan(2.0f * covariance_xy, xx - yy);
    float mid = 0.5f * (xx + yy);
    float radius = sqrt(0.25f * (xx - yy) * (xx - yy) + covariance_xy * covariance_xy);
    return vec3(min(sqrt(2.0f * (mid + radius)), max_alpha),
                min(sqrt(2.0f * max(mid - radius, 0.0f)), max_alpha), angle);
}

// The correlation of a footprint's slopes, Σ_xy / (σ_x σ_y) with σ_i² = α_i²/2
// of the widened lobe, kept within [−0.99, 0.99] as Chermain et al. 2021's
// shader keeps theirs (their slope transform divides by √(1 − ρ²)); 0 where
// it is not finite.
float slope_correlation(float covariance_xy, float alpha_x, float alpha_y) {
    float rho = 2.0f * covariance_xy / (alpha_x * alpha_y);
    if (isnan(rho) || isinf(rho)) return 0.0f;
    return clamp(rho, -0.99f, 0.99f);
}

// The covariance (xx, yy, xy) of a slope field linear over the pixel's
// uniform footprint parallelogram, from its change per pixel step in x and
// y: (gx gxᵀ + gy gyᵀ) / 12 (a uniform variable on a unit interval has
// variance 1/12).
vec3 linear_slope_covariance(vec2 gx, vec2 gy) {
    return vec3(gx.x * gx.x + gy.x * gy.x, gx.y * gx.y + gy.y * gy.y, gx.x * gx.y + gy.x * gy.y) /
           12.0f;
}

// LEAN under footprints smaller than the finest level's texels. The
// chain's level 0 holds each texel cell's moments of the bilinear surface,
// so a footprint far inside a cell reads the cell's spread (up to the
// spread of the texels around it) where the surface it covers is nearly one
// normal: lobes would widen in a texel-sized pattern as the camera comes
// close (Σ 10-470× the surface's own at a quarter to a sixteenth of a
// texel; scene/normal_map_reader_test.cpp). Footprints up to half a texel
// take the surface's own statistics (lean_blend_surface), footprints from
// one texel the chain's, linear in log2(width) between. (Taking the
// surface's up to 1.7 texels follows Σ closer there too, but one lobe per
// cell then moved the scratches' lean_mixture image from +2-8 % to +17-23 %
// of the truth for Beckmann lobes: near a texel neither Σ gives the image.)
// `lod`: the chain's biased λ.
float lean_chain_weight(float lod) {
    return clamp(lod - kSlopeMomentLodBias + 1.0f, 0.0f, 1.0f);
}
// `t` = lean_chain_weight; the surface's slope at the footprint's centre
// and at ± half its axes (duvdx: px, nx; duvdy: py, ny). Along each axis the
// slope is the quadratic through the three, the axis a uniform variable on
// [−h, h]: mean c + q/6 and variance g²/12 + q²/45, g = p − n the change,
// q = p + n − 2c the curvature (the curvature term keeps the spread where
// the slope peaks, which the change alone misses); the two axes add. Σ_xy
// only where `correlated`.
void lean_blend_surface(float t, vec2 centre, vec2 px, vec2 nx, vec2 py, vec2 ny,
                        bool correlated, INOUT(vec2) mean, INOUT(vec3) cov) {
    vec2 gx = px - nx, gy = py - ny;
    vec2 qx = px + nx - 2.0f * centre, qy = py + ny - 2.0f * centre;
    vec3 surface_cov = linear_slope_covariance(gx, gy) +
                       vec3(qx.x * qx.x + qy.x * qy.x, qx.y * qx.y + qy.y * qy.y,
                            qx.x * qx.y + qy.x * qy.y) /
                           45.0f;
    if (!correlated) surface_cov.z = 0.0f;
    mean = mix(centre + (qx + qy) / 6.0f, mean, t);
    cov = mix(surface_cov, cov, t);
}

#endif
