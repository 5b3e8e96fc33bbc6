// The part of wang2020's GPU glue that does not depend on how the tables are
// stored: the model's uniforms, the Wang2020Tables they fill and the
// functions the forward pass calls (GLINTLAB_GLINT_OWN_LIGHTS). Included by
// wang2020_gpu.glsl (tables in SSBOs, the renderer) and
// wang2020_export_textures.glsl (tables in textures, `glintlab export` for
// GLSL ES / WebGL2), after they define the four table reads.
#ifndef GLINTLAB_GLINTS_WANG2020_GLUE_COMMON_GLSL
#define GLINTLAB_GLINTS_WANG2020_GLUE_COMMON_GLSL

#include "glintlab/glints/glint_uniforms.glsl"
#include "glintlab/glints/wang2020/wang2020_tables.glsl"
#define GLINTLAB_GLINT_OWN_LIGHTS 1
uniform ivec3 u_wang2020_dpf_res;
uniform ivec4 u_wang2020_prefilter_res;
uniform int u_wang2020_depth;
uniform uint u_wang2020_seed;
uniform float u_wang2020_particles;
uniform float u_wang2020_sigma;
uniform int u_wang2020_micro;
uniform ivec2 u_wang2020_cone_res;
uniform float u_wang2020_cos_gamma;
Wang2020Tables wang2020_tables() {
    Wang2020Tables t;
    t.dpf_res = u_wang2020_dpf_res;
    t.prefilter_res = u_wang2020_prefilter_res;
    t.depth = u_wang2020_depth;
    t.seed = u_wang2020_seed;
    t.particles = u_wang2020_particles;
    t.sigma = u_wang2020_sigma;
    t.alpha = u_glint_alpha.x;
    t.micro = u_wang2020_micro;
    t.cone_res = u_wang2020_cone_res;
    t.cos_gamma = u_wang2020_cos_gamma;
    t.fresnel_mode = u_fresnel_mode;  // glint_uniforms.glsl
    t.fresnel_f0 = u_fresnel_f0;
    t.fresnel_eta = u_fresnel_eta;
    t.fresnel_k = u_fresnel_k;
    return t;
}
// Eq. 21 (the CPU's wang2020_light_radiance, untinted) for the lights the
// forward pass hands over one at a time: glint_own_light_add returns what
// it shades at once, glint_own_lights_flush (called once after the last
// light) the rest. Where the glue knows its light count
// (GLINTLAB_WANG2020_LIGHTS, the renderer's several lights) they are
// collected and shaded in batches from one traversal each, from one call
// site (each inlined copy of the traversal lengthens llvmpipe's frame);
// else each light on its own.
#ifdef GLINTLAB_WANG2020_LIGHTS
vec3 g_wang2020_wi[GLINTLAB_WANG2020_LIGHTS];
vec3 g_wang2020_li[GLINTLAB_WANG2020_LIGHTS];
int g_wang2020_pending = 0;
vec3 glint_own_light_add(vec3 wo, vec3 wi, vec3 li, Footprint fp) {
    g_wang2020_wi[g_wang2020_pending] = wi;
    g_wang2020_li[g_wang2020_pending] = li;
    ++g_wang2020_pending;
    return vec3(0.0f);
}
vec3 glint_own_lights_flush(vec3 wo, Footprint fp) {
    Wang2020Tables tb = wang2020_tables();
    Wang2020Footprint A = wang2020_footprint(fp);
    vec3 sum = vec3(0.0f);
    for (int first = 0; first < g_wang2020_pending; first += WANG2020_LIGHT_BATCH) {
        Wang2020LightBatch batch = wang2020_light_batch();
        batch.lights = min(WANG2020_LIGHT_BATCH, g_wang2020_pending - first);
        for (int j = 0; j < WANG2020_LIGHT_BATCH; ++j) {
            if (j >= batch.lights) continue;
            batch.wi[j] = g_wang2020_wi[first + j];
            batch.li[j] = g_wang2020_li[first + j];
        }
        sum += wang2020_lights(tb, A, batch, wo);
    }
    g_wang2020_pending = 0;
    return sum;
}
#else
vec3 glint_own_light_add(vec3 wo, vec3 wi, vec3 li, Footprint fp) {
    return wang2020_light(wang2020_tables(), wang2020_footprint(fp), wi, wo, li);
}
vec3 glint_own_lights_flush(vec3 wo, Footprint fp) { return vec3(0.0f); }
#endif
// Eqs. 18-20 (untinted; no directional occlusion on the GPU).
vec3 glint_own_environment(vec3 n, vec3 o_world, Footprint fp) {
    return wang2020_environment(wang2020_tables(), wang2020_footprint(fp), n, o_world);
}
// The smooth Beckmann limit (the CPU GlintBxdf's wang2020 case): eval_bsdf
// needs glint_ndf, but every light of the forward pass (point, sphere as
// point, directional, environment) goes through the functions above.
#include "glintlab/glints/smooth_gpu.glsl"

#endif
