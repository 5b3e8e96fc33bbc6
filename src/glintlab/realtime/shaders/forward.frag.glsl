// Forward pass, fragment stage (realtime/forward_shaders.h): shading frame,
// footprint, material BRDFs and the light loops. One program per (glint
// model, light set) variant; realtime/forward_shaders.cpp assembles
//     #define GLINTLAB_POINT_LIGHTS N          (point and sphere lights)
//     #define GLINTLAB_DIRECTIONAL_LIGHTS N
//     #define GLINTLAB_ENVIRONMENT 0|1
//     #define GLINTLAB_ENV_SPECULAR_SAMPLES N  (filtered importance sampling)
//     #define GLINTLAB_ENV_DIFFUSE_SAMPLES N
//     #define GLINTLAB_ENV_DEFENSIVE_SAMPLES N (cosine samples of a lobe alone)
//     #define GLINTLAB_ENV_SOURCE_SAMPLES N    (directions in the map's sources)
//     #include "<the model's GPU glue, glints/**/*_gpu.glsl>"
//     #include "glintlab/realtime/shaders/forward.frag.glsl"
// The glue defines glint_ndf (material.glsl's D_P) and optionally
// GLINTLAB_GLINT_OWN_LIGHTS, GLINTLAB_GLINT_SHADES_ENVIRONMENT,
// GLINTLAB_GLINT_SHADES_AREA_LIGHTS with their functions.
#include "glintlab/core/constants.glsl"
#include "glintlab/core/footprint.glsl"
#include "glintlab/microfacet/ndf.glsl"
#include "glintlab/microfacet/masking.glsl"
#include "glintlab/microfacet/fresnel.glsl"
#include "glintlab/microfacet/vndf.glsl"
#include "glintlab/glints/glint_uniforms.glsl"
#include "glintlab/glints/material.glsl"
// Unconditionally: the assembly includes a file once, where it first
// appears, and normal_map.glsl includes it inside its own #ifdef.
#include "glintlab/core/slope_frame.glsl"

in vec3 v_position;
in vec3 v_normal;
in vec2 v_uv;
in vec4 v_dpdu;
out vec4 o_radiance;
// wang2020's §4.4 glint layer (gpu_renderer.cpp): rgb = the environment
// glints of shapes with u_glint_layer set (left out of o_radiance), a = the
// directional-occlusion visibility (1: no occlusion ray here). Every shape
// writes it, so a shape in front clears the layer to (0, 0, 0, 1); it is
// discarded when the framebuffer has no second draw buffer.
layout(location = 1) out vec4 o_glint_layer;
uniform bool u_glint_layer;

// Per-triangle data of meshes (pbrt-v4 Triangle, as render/accel.cpp):
// dp/du of the triangle's uv mapping and the geometric normal.
struct TriangleFrame {
    vec4 dpdu;
    vec4 ng;
};
layout(std430, binding = 0) readonly buffer Triangles { TriangleFrame u_triangles[]; };
uniform bool u_per_triangle_frame;  // meshes: SSBO; spheres: analytic vertex attributes
// Mesa llvmpipe ends every loop of a shader invocation once the iterations
// of all its loops together pass 65535 (gallivm's
// LP_MAX_TGSI_LOOP_ITERATIONS): a long traversal (wang2020's per-particle
// quadtree, once per light and per lean_mixture cell) then returns a
// darker pixel without a word. A loop of u_loop_probe (2) iterations after
// shading runs once there; the fragments where it does are counted
// (GpuRenderer::cut_fragments, which the callers report).
layout(std430, binding = 5) buffer LoopProbe { uint u_cut_fragments; };
uniform int u_loop_probe;
#ifdef GLINTLAB_NORMAL_MAP_MIXTURE
uniform int u_normal_map_mixture;  // "mixture": k of the k x k sub-footprints
#endif
// A closed surface (realtime/gpu_geometry.h): the environment below its
// geometric tangent plane is occluded by the surface itself.
uniform bool u_closed_surface;
uniform bool u_has_normals;         // meshes without normals shade with ng (faceted)

uniform vec3 u_eye;
uniform bool u_orthographic;
uniform vec3 u_view_forward;

#include "glintlab/realtime/shaders/material_uniforms.glsl"
#ifdef GLINTLAB_MATERIAL_TEXTURES
#include "glintlab/realtime/shaders/material_textures.glsl"
#endif
#ifdef GLINTLAB_NORMAL_MAP
#include "glintlab/realtime/shaders/normal_map.glsl"
#endif

#if GLINTLAB_POINT_LIGHTS > 0
// The light loops run to these counts (GLINTLAB_*_LIGHTS, as uniforms): a
// trip count no compiler unrolls, each iteration being a whole shading.
uniform int u_point_light_count;
uniform vec3 u_point_position[GLINTLAB_POINT_LIGHTS];
uniform vec3 u_point_intensity[GLINTLAB_POINT_LIGHTS];
#endif
#if GLINTLAB_DIRECTIONAL_LIGHTS > 0
uniform int u_directional_light_count;
uniform vec3 u_directional_direction[GLINTLAB_DIRECTIONAL_LIGHTS];  // towards the light
uniform vec3 u_directional_irradiance[GLINTLAB_DIRECTIONAL_LIGHTS];
#endif
#ifdef GLINTLAB_GLINT_SHADES_AREA_LIGHTS
// Glint models that shade area lights themselves (glue: glint_area_light)
// need the lights' shapes: sphere lights' radius (0 for point lights) and
// radiance, sun cones' solid angle (0 for delta lights), half-angle cosine
// and radiance.
#if GLINTLAB_POINT_LIGHTS > 0
uniform float u_point_radius[GLINTLAB_POINT_LIGHTS];
uniform vec3 u_point_radiance[GLINTLAB_POINT_LIGHTS];
#endif
#if GLINTLAB_DIRECTIONAL_LIGHTS > 0
uniform float u_directional_solid_angle[GLINTLAB_DIRECTIONAL_LIGHTS];  // 0: delta light
uniform float u_directional_cos_max[GLINTLAB_DIRECTIONAL_LIGHTS];
uniform vec3 u_directional_radiance[GLINTLAB_DIRECTIONAL_LIGHTS];
#endif
#endif

#if GLINTLAB_ENVIRONMENT
layout(binding = 0) uniform sampler2D u_environment;  // lat-long, full mip chain
// The same map without its bright sources (scene/environment_sources.h), read
// by the lobe's samples; the sources are u_environment_source_count directions
// (the map's frame) each carrying a power (radiance × solid angle).
layout(binding = 3) uniform sampler2D u_environment_residual;
uniform float u_environment_scale;
uniform float u_environment_rotation;  // radians about +y
uniform vec2 u_environment_size;       // texels of level 0
uniform int u_environment_source_count;  // 0 (no source) or GLINTLAB_ENV_SOURCE_SAMPLES
uniform vec3 u_environment_source_direction[GLINTLAB_ENV_SOURCE_SAMPLES];
uniform vec3 u_environment_source_power[GLINTLAB_ENV_SOURCE_SAMPLES];

// scene/environment.cpp direction_to_uv.
vec2 environment_uv(vec3 d) {
    float theta = acos(clamp(d.y, -1.0f, 1.0f));
    float phi = atan(d.x, -d.z) - u_environment_rotation;
    float u = 0.5f + phi * INV_TWO_PI;
    return vec2(u - floor(u), theta * INV_PI);
}

// Radiance from world direction d, prefiltered over the solid angle
// `omega` of a sample (Krivanek & Colbert 2008: the filter covers the
// sample's share of the sphere). The footprint is a square of side sqrt(omega)
// on the sphere, which in the lat-long map is sqrt(omega)/pi tall and
// 1/sin(theta) times wider in texels: the level is the one whose texels are
// as tall as the footprint, and up to kEnvironmentTaps taps spread along the
// row cover its width (a coarser level beyond, only within a few degrees of
// a pole). One isotropic level from the footprint's area blurred across rows
// near a pole (maps with a bright zenith read 10 % dark); one from its
// height alone aliased along rows (petals). textureGrad's anisotropic
// filtering would do the same, but Mesa llvmpipe's returns stripes.
const int kEnvironmentTaps = 8;
vec3 environment_filtered(sampler2D map, vec3 d, float omega) {
    vec2 uv = environment_uv(d);
    float side = sqrt(omega);
    float lod = max(log2(side * u_environment_size.y * INV_PI), 0.0f);
    // The footprint's width over a texel's width at that level.
    float du = side * INV_TWO_PI / max(sin(uv.y * PI), 1e-4f);
    float ratio = du * u_environment_size.x / exp2(lod);
    int taps = int(clamp(ceil(ratio), 1.0f, float(kEnvironmentTaps)));
    lod += max(log2(ratio / float(kEnvironmentTaps)), 0.0f);
    du = min(du, 1.0f);
    vec3 sum = vec3(0.0f);
    for (int i = 0; i < taps; ++i) {
        float u = uv.x + du * ((float(i) + 0.5f) / float(taps) - 0.5f);
        sum += textureLod(map, vec2(u, uv.y), lod).rgb;
    }
    return u_environment_scale * sum / float(taps);
}
vec3 environment_radiance(vec3 d, float omega) {
    return environment_filtered(u_environment, d, omega);
}
// The same for the map without its sources (the lobe's samples).
vec3 environment_residual_radiance(vec3 d, float omega) {
    return environment_filtered(u_environment_residual, d, omega);
}

// World direction of source sample k: the map's frame turned by the rotation
// about +y (scene/environment.cpp uv_to_direction: phi_world = phi_map + r).
vec3 environment_source_direction(int k) {
    vec3 m = u_environment_source_direction[k];
    float c = cos(u_environment_rotation), s = sin(u_environment_rotation);
    return vec3(m.x * c - m.z * s, m.y, m.z * c + m.x * s);
}

vec2 hammersley(int i, int n) {
    return vec2((float(i) + 0.5f) / float(n), float(bitfieldReverse(uint(i))) * 2.3283064e-10f);
}
#endif

#if GLINTLAB_POINT_LIGHTS > 0
// Shadows of point lights (and of sphere lights, shaded from their centre,
// whose own sphere is left out of their map): one depth cube per light (a
// cube of u_point_shadow_maps), perspective 90 deg faces from u_point_near[i]
// to u_point_far[i]. The reference depth is that of the face the direction
// falls in (its major axis), after the same normal offset and slope-scaled
// bias as the directional maps, with texels of 2 d / size at distance d.
uniform bool u_point_shadows;
uniform float u_point_near[GLINTLAB_POINT_LIGHTS];
uniform float u_point_far[GLINTLAB_POINT_LIGHTS];
uniform float u_point_shadow_size;  // texels per cube face side
layout(binding = 2) uniform samplerCubeArrayShadow u_point_shadow_maps;
float point_visibility(int i, vec3 p, vec3 ng, vec3 from_light) {
    if (!u_point_shadows) return 1.0f;
    float dist = length(from_light);
    vec3 l = -from_light / dist;  // towards the light
    float c = dot(ng, l);
    vec3 towards = c >= 0.0f ? ng : -ng;
    float cos_l = clamp(abs(c), 0.05f, 1.0f);
    float texel = 2.0f * dist / u_point_shadow_size;
    vec3 v = from_light + towards * (1.5f * texel);
    float tan_l = sqrt(1.0f - cos_l * cos_l) / cos_l;
    float major = max(max(abs(v.x), abs(v.y)), abs(v.z)) - texel * (1.0f + min(tan_l, 10.0f));
    float n = u_point_near[i];
    float f = u_point_far[i];
    if (major <= n) return 1.0f;
    float z_ndc = (f + n) / (f - n) - 2.0f * f * n / ((f - n) * major);  // glm::perspective depth
    return texture(u_point_shadow_maps, vec4(v, float(i)), 0.5f * z_ndc + 0.5f);
}
#endif

#if GLINTLAB_DIRECTIONAL_LIGHTS > 0
// Shadows of directional lights: one orthographic depth map per light (a
// layer of u_shadow_maps) over the scene's bounding sphere. The lookup
// point moves 1.5 texels along the geometric normal towards the light and
// the depth comparison carries a slope-scaled bias (normal-offset shadow
// mapping), so lit surfaces do not shadow themselves; one hardware 2x2
// comparison (GL_LINEAR on a depth-compare texture) softens the edge over a
// texel, where the CPU's shadow ray is hard.
uniform bool u_shadows;
uniform mat4 u_shadow_matrix[GLINTLAB_DIRECTIONAL_LIGHTS];  // world -> [0, 1]^3
uniform float u_shadow_texel;        // world size of a shadow texel
uniform float u_shadow_depth_range;  // world length of the depth range
layout(binding = 1) uniform sampler2DArrayShadow u_shadow_maps;
float directional_visibility(int i, vec3 p, vec3 ng) {
    if (!u_shadows) return 1.0f;
    vec3 w = u_directional_direction[i];
    float c = dot(ng, w);
    vec3 towards = c >= 0.0f ? ng : -ng;
    float cos_l = clamp(abs(c), 0.05f, 1.0f);
    vec4 s = u_shadow_matrix[i] * vec4(p + towards * (1.5f * u_shadow_texel), 1.0f);
    if (any(lessThan(s.xyz, vec3(0.0f))) || any(greaterThan(s.xyz, vec3(1.0f)))) return 1.0f;
    float tan_l = sqrt(1.0f - cos_l * cos_l) / cos_l;
    float bias = u_shadow_texel * (1.0f + min(tan_l, 10.0f)) / u_shadow_depth_range;
    return texture(u_shadow_maps, vec4(s.x, s.y, float(i), s.z - bias));
}
#endif

// render/light_sampling.cpp orthonormal_basis (Duff et al. 2017).
void orthonormal_basis(vec3 n, out vec3 t, out vec3 b) {
    float s = n.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (s + n.z);
    float c = n.x * n.y * a;
    t = vec3(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
    b = vec3(c, s + n.y * n.y * a, -n.y);
}

// The material of the shape being drawn, from the uniforms (the CPU's
// MaterialDesc / GlintDesc, scene.h).
SurfaceMaterial surface_material() {
    SurfaceMaterial s;
    s.type = u_material_type;
    s.albedo = u_albedo;
    s.metallic = u_metallic;
    s.ndf = u_ndf;
    s.alpha_x = u_alpha.x;
    s.alpha_y = u_alpha.y;
    s.eta = u_eta;
    s.k = u_k;
    s.glint.color = u_glint_color;
    s.glint.base_albedo = u_glint_base_albedo;
    s.glint.fresnel_mode = u_fresnel_mode;
    s.glint.fresnel_f0 = u_fresnel_f0;
    s.glint.fresnel_eta = u_fresnel_eta;
    s.glint.fresnel_k = u_fresnel_k;
    s.glint.ndf = u_glint_ndf;
    s.glint.alpha_x = u_glint_alpha.x;
    s.glint.alpha_y = u_glint_alpha.y;
    s.glint.rho = g_glint_slope_correlation;
    s.glint.g2 = u_glint_g2;
    return s;
}

#if GLINTLAB_ENVIRONMENT
// Environment light reflected towards wo: a deterministic multi-sample MIS
// estimate (balance heuristic, Veach 1997 Eq. 9.13) over visible-normal
// samples of the lobe's NDF and cosine samples (64 for materials with a
// diffuse part, 16 defensive ones for a lobe alone: forward_shaders.h);
// every sample reads the environment prefiltered over its solid
// angle, so the estimate is smooth instead of noisy. Mirrors (alpha below
// kSmoothAlpha) reflect one filtered direction.
// `horizon`: the geometric normal on wo's side in the local frame where the
// surface is closed (directions below it are occluded: the CPU's shadow rays
// hit the surface itself, which a normal map's tilted frame would otherwise
// light from below), else 0.
vec3 environment_lighting(SurfaceMaterial mat, vec3 wo, vec3 t, vec3 b, vec3 n, Footprint fp,
                          vec3 horizon) {
    bool glint = u_material_type == 4;
    int ndf = glint ? u_glint_ndf : u_ndf;
    vec2 alpha = glint ? u_glint_alpha : u_alpha;
    bool has_diffuse = u_material_type == 0 || u_material_type == 3 ||
                       (u_material_type == 5 && mat.metallic < 1.0f) ||
                       (glint && glint_has_base(mat.glint));
    bool has_lobe = u_material_type != 0;
    bool mirror = max(alpha.x, alpha.y) < 1e-3f;
    vec3 sum = vec3(0.0f);
    if (has_lobe && mirror) {
        vec3 wi = vec3(-wo.x, -wo.y, wo.z);
        vec3 f = u_material_type == 1 ? F_Conductor(wo.z, u_eta, u_k)
                                      : vec3(F_Dielectric(wo.z, glint ? u_fresnel_eta.x : u_eta.x));
        if (glint) f = u_glint_color * glint_fresnel(mat.glint, wo.z);
        if (u_material_type == 5)
            f = mix(vec3(F_Dielectric(wo.z, u_eta.x)), F_Schlick(mat.albedo, wo.z), mat.metallic);
        if (dot(wi, horizon) >= 0.0f)
            sum += f * environment_radiance(wi.x * t + wi.y * b + wi.z * n, 0.0f);
        if (!has_diffuse) return sum;
    }
    int ns = has_lobe && !mirror ? GLINTLAB_ENV_SPECULAR_SAMPLES : 0;
    int nd = has_diffuse ? GLINTLAB_ENV_DIFFUSE_SAMPLES : GLINTLAB_ENV_DEFENSIVE_SAMPLES;
    for (int s = 0; s < ns + nd; ++s) {
        vec3 wi;
        if (s < ns) {
            vec3 m = sample_vndf(ndf, wo, alpha.x, alpha.y, hammersley(s, ns));
            wi = reflect(-wo, m);
        } else {
            vec2 u = hammersley(s - ns, nd);
            float r = sqrt(u.x);
            float phi = TWO_PI * u.y;
            wi = vec3(r * cos(phi), r * sin(phi), sqrt(max(1.0f - u.x, 0.0f)));
        }
        if (wi.z <= 0.0f || dot(wi, horizon) < 0.0f) continue;
        vec3 h = normalize(wo + wi);
        float p_lobe = ns > 0 ? pdf_vndf(ndf, wo, h, alpha.x, alpha.y) / (4.0f * abs(dot(wo, h))) : 0.0f;
        float p_cos = nd > 0 ? wi.z * INV_PI : 0.0f;
        float p_mix = float(ns) * p_lobe + float(nd) * p_cos;  // sum_k N_k p_k
        if (!(p_mix > 0.0f)) continue;
        vec3 f = eval_bsdf(mat, wo, wi, fp);
        vec3 world = wi.x * t + wi.y * b + wi.z * n;
        sum += f * wi.z / p_mix * environment_residual_radiance(world, 1.0f / p_mix);
    }
    // The sources: a quadrature of each, sum_k f(wi_k) cos(theta_k) Phi_k.
    for (int k = 0; k < u_environment_source_count; ++k) {
        vec3 d = environment_source_direction(k);
        vec3 wi = vec3(dot(d, t), dot(d, b), dot(d, n));
        if (wi.z <= 0.0f || dot(wi, horizon) < 0.0f) continue;
        vec3 power = u_environment_scale * u_environment_source_power[k];
        sum += eval_bsdf(mat, wo, wi, fp) * wi.z * power;
    }
    return sum;
}
#endif

void main() {
    vec3 p = v_position;
    vec3 wo_world = u_orthographic ? -u_view_forward : normalize(u_eye - p);
    vec3 radiance = vec3(0.0f);
    vec3 glint_layer = vec3(0.0f);

    vec3 ng;
    vec3 dpdu;
    if (u_per_triangle_frame) {
        TriangleFrame tri = u_triangles[gl_PrimitiveID];
        ng = tri.ng.xyz;
        dpdu = tri.dpdu.xyz;
    } else {
        ng = normalize(v_normal);
        dpdu = v_dpdu.xyz;
    }
#ifdef GLINTLAB_NORMAL_MAP
    // A normal map's tangent space: the mesh's vertex tangent, smooth
    // across triangles (shading_frame with vertex_tangent).
    if (dot(v_dpdu.xyz, v_dpdu.xyz) > 0.0f) dpdu = v_dpdu.xyz;
#endif
    vec3 n = u_has_normals ? normalize(v_normal) : ng;
    if (u_has_normals && dot(ng, n) < 0.0f) ng = -ng;
#if defined(GLINTLAB_GLINT_CURVATURE) || defined(GLINTLAB_GLINT_VIEW_DIFFERENTIALS)
    // The unit normal's change per pixel step (x right, y down the image, as
    // the footprint's): here, in uniform control flow.
    vec3 dndx = dFdxFine(n), dndy = -dFdyFine(n);
#endif
#ifdef GLINTLAB_GLINT_VIEW_DIFFERENTIALS
    vec3 dwodx = dFdxFine(wo_world), dwody = -dFdyFine(wo_world);
#endif
    // Emitters: sphere lights shine from their outer side (integrators.cpp emitted()).
    if (dot(ng, wo_world) > 0.0f) radiance += u_emission;

    // Footprint (ARCHITECTURE.md §3): uv derivatives per pixel step. The image
    // is read back with row 0 at the top, so +y on the CPU film is -y in
    // window coordinates. Fine derivatives: per-pixel differences, not one
    // per 2x2 quad.
    Footprint fp;
    fp.uv = v_uv;
    fp.duvdx = dFdxFine(v_uv);
    fp.duvdy = -dFdyFine(v_uv);
#ifdef GLINTLAB_MATERIAL_TEXTURES
    resolve_material_textures(fp);
#endif

    if (u_material_type >= 0) {
        SurfaceMaterial mat = surface_material();
        // Shading frame (render/surface_bsdf.cpp): tangent along dp/du,
        // two-sided (flipped towards wo).
        vec3 t = dpdu - n * dot(n, dpdu);
        float len = length(t);
        vec3 b;
        if (len > 1e-12f && !isinf(len) && !isnan(len)) {
            t = t / len;
            b = cross(n, t);
        } else {
            orthonormal_basis(n, t, b);
        }
        bool back_side = u_material_type != 2 && dot(wo_world, n) < 0.0f;
        if (back_side) {
            n = -n;
            b = -b;
        }
#ifdef GLINTLAB_MATERIAL_TEXTURES
        float glint_cov_xy = 0.0f;  // the footprint's Σ_xy (render/surface_bsdf.cpp)
#endif
#ifdef GLINTLAB_GLINT_CURVATURE
        if (mat.type == MATERIAL_GLINT) {
            // render/surface_bsdf.cpp footprint_slope_covariance: the slope
            // changes per pixel step are −(t·∂n, b·∂n), linear over the
            // pixel's footprint (the sign drops out of the covariance).
            vec3 cov = linear_slope_covariance(vec2(dot(t, dndx), dot(b, dndx)),
                                               vec2(dot(t, dndy), dot(b, dndy)));
            glint_cov_xy += cov.z;
            mat.glint.alpha_x = slope_widened_alpha(mat.glint.alpha_x, cov.x, 1.0f);
            mat.glint.alpha_y = slope_widened_alpha(mat.glint.alpha_y, cov.y, 1.0f);
            g_glint_alpha = vec2(mat.glint.alpha_x, mat.glint.alpha_y);
        }
#endif
#ifdef GLINTLAB_NORMAL_MAP_MIXTURE
        // "lean_mixture" (core/normal_map.h): each of the k × k sub-footprints
        // shades the pixel with its own lobe and the pixel is their mean (the
        // CPU draws one per pixel sample). The lights and the glint model
        // keep the whole footprint. The loop's body, left unindented, runs to
        // the end of the light loops.
        // k as a uniform: a trip count no compiler can unroll (the loop's body
        // is the whole light shading).
        const int kMixtureCells = u_normal_map_mixture * u_normal_map_mixture;
        vec3 unshaded_radiance = radiance;
        radiance = vec3(0.0f);
        SurfaceMaterial mixture_mat = mat;
        vec3 mixture_t = t, mixture_b = b, mixture_n = n;
        float mixture_cov_xy = glint_cov_xy;
        vec2 mixture_glint_alpha = g_glint_alpha, mixture_alpha = g_alpha;
        float mixture_correlation = g_glint_slope_correlation;
        for (int cell = 0; cell < kMixtureCells; ++cell) {
        mat = mixture_mat;
        t = mixture_t;
        b = mixture_b;
        n = mixture_n;
        glint_cov_xy = mixture_cov_xy;
        g_glint_alpha = mixture_glint_alpha;
        g_alpha = mixture_alpha;
        g_glint_slope_correlation = mixture_correlation;
        normal_map_shade(footprint_cell(fp, cell, u_normal_map_mixture), back_side,
                         v_dpdu.w < 0.0f ? -1.0f : 1.0f, wo_world, t, b, n, mat, glint_cov_xy);
#elif defined(GLINTLAB_NORMAL_MAP)
        normal_map_shade(fp, back_side, v_dpdu.w < 0.0f ? -1.0f : 1.0f, wo_world, t, b, n,
                         mat, glint_cov_xy);
#endif
#ifdef GLINTLAB_MATERIAL_TEXTURES
        if (mat.type == MATERIAL_GLINT && u_glint_reads_correlation != 0 && glint_cov_xy != 0.0f) {
            g_glint_slope_correlation =
                slope_correlation(glint_cov_xy, mat.glint.alpha_x, mat.glint.alpha_y);
            mat.glint.rho = g_glint_slope_correlation;
        }
#endif
        vec3 wo = vec3(dot(wo_world, t), dot(wo_world, b), dot(wo_world, n));
        vec3 horizon = vec3(0.0f);
        if (u_closed_surface) {
            vec3 ng_side = dot(ng, wo_world) < 0.0f ? -ng : ng;
            horizon = vec3(dot(ng_side, t), dot(ng_side, b), dot(ng_side, n));
        }
#ifdef GLINTLAB_GLINT_VIEW_DIFFERENTIALS
        g_glint_view = view_differentials_in_frame(wo, dwodx, dwody, dndx, dndy, t, b, n,
                                                   back_side ? -1.0f : 1.0f);
#endif
#if GLINTLAB_POINT_LIGHTS > 0
        for (int i = 0; i < u_point_light_count; ++i) {
            vec3 d = u_point_position[i] - p;
#ifdef GLINTLAB_GLINT_SHADES_AREA_LIGHTS
            if (u_material_type == 4 && u_point_radius[i] > 0.0f) {
                // A sphere light as the cone it subtends (kneiphof2025.cpp
                // light_radiance), shadowed by its centre's cube map.
                float dist = length(d);
                if (!(dist > u_point_radius[i])) continue;
                float sin_max = u_point_radius[i] / dist;
                float cos_max = sqrt(max(0.0f, 1.0f - sin_max * sin_max));
                float area_visible = point_visibility(i, p, ng, -d);
                if (area_visible <= 0.0f) continue;
                radiance += area_visible * glint_area_light(d / dist, cos_max, u_point_radiance[i],
                                                            t, b, n, wo, u_glint_color, fp);
                continue;
            }
#endif
            float r2 = dot(d, d);
            vec3 w = d * inversesqrt(r2);
            vec3 wi = vec3(dot(w, t), dot(w, b), dot(w, n));
            if (wi.z <= 0.0f) continue;
            float visible = point_visibility(i, p, ng, -d);
            if (visible <= 0.0f) continue;
#ifdef GLINTLAB_GLINT_OWN_LIGHTS
            // Models that shade their lights themselves (glint_lighting.h;
            // wang2020 Eq. 21, wang2020_gpu.h), untinted, in batches.
            if (u_material_type == 4) {
                radiance += u_glint_color *
                            glint_own_light_add(wo, wi, u_point_intensity[i] * (visible / r2), fp);
                continue;
            }
#endif
            radiance += eval_bsdf(mat, wo, wi, fp) * u_point_intensity[i] * (wi.z * visible / r2);
        }
#endif
#if GLINTLAB_ENVIRONMENT && defined(GLINTLAB_GLINT_OWN_LIGHTS)
        // wang2020 (wang2020_gpu.h): Eqs. 18-20, untinted.
        if (u_material_type == 4) {
            vec3 env = u_glint_color * glint_own_environment(n, wo_world, fp);
            if (u_glint_layer)
                glint_layer += env;
            else
                radiance += env;
        } else
            radiance += environment_lighting(mat, wo, t, b, n, fp, horizon);
#elif GLINTLAB_ENVIRONMENT && defined(GLINTLAB_GLINT_SHADES_ENVIRONMENT)
        // The model's own image-based lighting (kneiphof2025: Eq. 17) instead
        // of the smooth filtered-importance-sampling estimate.
        if (u_material_type == 4)
            radiance += glint_environment(wo, t, b, n, u_glint_color, fp);
        else
            radiance += environment_lighting(mat, wo, t, b, n, fp, horizon);
#elif GLINTLAB_ENVIRONMENT
        radiance += environment_lighting(mat, wo, t, b, n, fp, horizon);
#endif
#if GLINTLAB_DIRECTIONAL_LIGHTS > 0
        for (int i = 0; i < u_directional_light_count; ++i) {
            vec3 w = u_directional_direction[i];
#ifdef GLINTLAB_GLINT_SHADES_AREA_LIGHTS
            if (u_material_type == 4 && u_directional_solid_angle[i] > 0.0f) {
                // A sun cone as an area light (kneiphof2025.cpp light_radiance).
                float area_visible = directional_visibility(i, p, ng);
                if (area_visible <= 0.0f) continue;
                radiance += area_visible * glint_area_light(normalize(w), u_directional_cos_max[i],
                                                            u_directional_radiance[i], t, b, n,
                                                            wo, u_glint_color, fp);
                continue;
            }
#endif
            vec3 wi = vec3(dot(w, t), dot(w, b), dot(w, n));
            if (wi.z <= 0.0f) continue;
            float visible = directional_visibility(i, p, ng);
            if (visible <= 0.0f) continue;
#ifdef GLINTLAB_GLINT_OWN_LIGHTS
            if (u_material_type == 4) {
                radiance += u_glint_color *
                            glint_own_light_add(wo, wi, u_directional_irradiance[i] * visible, fp);
                continue;
            }
#endif
            radiance += eval_bsdf(mat, wo, wi, fp) * u_directional_irradiance[i] * (wi.z * visible);
        }
#endif
#ifdef GLINTLAB_GLINT_OWN_LIGHTS
        if (u_material_type == 4) radiance += u_glint_color * glint_own_lights_flush(wo, fp);
#endif
#ifdef GLINTLAB_NORMAL_MAP_MIXTURE
        }
        radiance = unshaded_radiance + radiance / float(kMixtureCells);
        glint_layer /= float(kMixtureCells);
#endif
    }
    int probe = 0;
    for (int i = 0; i < u_loop_probe; ++i) ++probe;
    if (probe < u_loop_probe) atomicAdd(u_cut_fragments, 1u);
    // Non-finite results are dropped as the CPU integrators do.
    if (any(isnan(radiance)) || any(isinf(radiance))) radiance = vec3(0.0f);
    if (any(isnan(glint_layer)) || any(isinf(glint_layer))) glint_layer = vec3(0.0f);
    o_radiance = vec4(radiance, 1.0f);
    o_glint_layer = vec4(glint_layer, 1.0f);
}
