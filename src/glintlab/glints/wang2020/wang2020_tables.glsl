// wang2020 (papers/001) table and quadtree reads for the GPU, in the shared
// GLSL/C++ subset: the extracted DPF table P(i, o, γ) (Eq. 6, §4.4), the
// prefiltered environment tables L̂o, P̂ (Eqs. 16-17, §4.2) and the compact
// particle quadtree (§4.4 "Spatial Tree Construction"), each read exactly as
// the CPU classes read them (DpfTable::lookup, PrefilterTable::lookup,
// ParticleQuadtree::count / for_each, same hashes for particle positions and
// λ), then the three-scale shading of §4.3 on top (wang2020.glsl).
//
// The buffers are the CPU's own arrays, uploaded unchanged; the including
// back end defines their element reads (GLSL: SSBOs in realtime/; C++:
// stand-ins over the CPU vectors in wang2020_tables_test.cpp, which checks
// these functions against the CPU classes):
//   float wang2020_dpf_value(int index);        DpfTable::values()
//   vec4  wang2020_prefilter_value(int index);  PrefilterTable::data()
//   uvec2 wang2020_node(int index);             QuadtreeNode {first_child, count_mask}
// Precision: float instead of the CPU's double; particle tests are done in
// leaf-local coordinates, where the box edges are exact, so counts agree
// with the CPU for boxes given in float.
#ifndef GLINTLAB_GLINTS_WANG2020_TABLES_GLSL
#define GLINTLAB_GLINTS_WANG2020_TABLES_GLSL

#include "glintlab/core/constants.glsl"
#include "glintlab/core/footprint.glsl"
#include "glintlab/core/frame.glsl"
#include "glintlab/glints/wang2020/wang2020.glsl"
#include "glintlab/microfacet/masking.glsl"

float wang2020_dpf_value(int index);
vec4 wang2020_prefilter_value(int index);
uvec2 wang2020_node(int index);

const float WANG2020_HALF_PI = 1.57079632679489661923f;
// DFS stack of the traversal: each pop pushes at most 4 children, so it
// holds at most 3 depth + 1 <= 49 items for depth <= 16.
const int WANG2020_STACK = 64;

// What the shader needs of one material's tables (Wang2020Model).
struct Wang2020Tables {
    ivec3 dpf_res;        // θi, θo, Δφ
    ivec4 prefilter_res;  // θn, φn, θo, φo
    int depth;            // quadtree depth
    uint seed;            // quadtree seed
    float particles;      // N per uv tile
    float sigma;          // σ(Ωo) = 2π(1 − cos γ)
    float alpha;          // Beckmann roughness
};

// False for NaN and ±inf (a comparison, not isnan/isinf: the C++ side would
// see <cmath>'s overloads next to GLM's).
bool wang2020_finite(float x) {
    return abs(x) <= 3.40282347e38f;
}

// Cell-centred linear interpolation: clamped (θ) or periodic (φ), as
// wang2020_dpf.cpp / wang2020_prefilter.cpp `cell`.
void wang2020_cell(float x, int n, bool periodic, OUT(int) i0, OUT(int) i1, OUT(float) f) {
    if (periodic) {
        x -= floor(x / float(n)) * float(n);
        i0 = min(int(x), n - 1);
        i1 = (i0 + 1) % n;
    } else {
        x = clamp(x, 0.0f, float(n - 1));
        i0 = min(int(x), n - 1);
        i1 = min(i0 + 1, n - 1);
    }
    f = x - float(i0);
}

float wang2020_dpf_at(ivec3 res, int ti, int to, int p) {
    return wang2020_dpf_value((ti * res.y + to) * res.z + p);
}

// DpfTable::lookup_angles: trilinear, clamped in θ, periodic in Δφ.
float wang2020_dpf_lookup_angles(ivec3 res, float theta_i, float theta_o, float dphi) {
    if (!(theta_i < WANG2020_HALF_PI) || !(theta_o < WANG2020_HALF_PI) || !wang2020_finite(dphi))
        return 0.0f;  // below the horizon or non-finite (no NaN -> int casts)
    int a0, a1, b0, b1, p0, p1;
    float fa, fb, fp;
    wang2020_cell(theta_i / WANG2020_HALF_PI * float(res.x) - 0.5f, res.x, false, a0, a1, fa);
    wang2020_cell(theta_o / WANG2020_HALF_PI * float(res.y) - 0.5f, res.y, false, b0, b1, fb);
    wang2020_cell(dphi / TWO_PI * float(res.z) - 0.5f, res.z, true, p0, p1, fp);
    float v00 = mix(wang2020_dpf_at(res, a0, b0, p0), wang2020_dpf_at(res, a0, b0, p1), fp);
    float v01 = mix(wang2020_dpf_at(res, a0, b1, p0), wang2020_dpf_at(res, a0, b1, p1), fp);
    float v10 = mix(wang2020_dpf_at(res, a1, b0, p0), wang2020_dpf_at(res, a1, b0, p1), fp);
    float v11 = mix(wang2020_dpf_at(res, a1, b1, p0), wang2020_dpf_at(res, a1, b1, p1), fp);
    return mix(mix(v00, v01, fb), mix(v10, v11, fb), fa);
}

// P(i, o, γ) for local unit directions (z = normal); 0 below the horizon.
float wang2020_dpf_lookup(ivec3 res, vec3 wi, vec3 wo) {
    if (!(wi.z > 0.0f) || !(wo.z > 0.0f)) return 0.0f;
    float dphi = atan(wo.y, wo.x) - atan(wi.y, wi.x);
    return wang2020_dpf_lookup_angles(res, acos(min(1.0f, wi.z)), acos(min(1.0f, wo.z)), dphi);
}

vec4 wang2020_prefilter_texel(ivec4 res, int tn, int pn, int to, int po) {
    return wang2020_prefilter_value(((tn * res.y + pn) * res.z + to) * res.w + po);
}

// Bilinear in (θo, φo) at one normal texel.
vec4 wang2020_prefilter_o(ivec4 res, int tn, int pn, int c0, int c1, float fc, int d0, int d1,
                          float fd) {
    vec4 v0 = mix(wang2020_prefilter_texel(res, tn, pn, c0, d0),
                  wang2020_prefilter_texel(res, tn, pn, c0, d1), fd);
    vec4 v1 = mix(wang2020_prefilter_texel(res, tn, pn, c1, d0),
                  wang2020_prefilter_texel(res, tn, pn, c1, d1), fd);
    return mix(v0, v1, fc);
}

// PrefilterTable::lookup: rgb = L̂o(n, o) (Eq. 16), w = P̂(n, o) (Eq. 17),
// quadrilinear; o is expressed once in the query normal's tangent frame and
// read at those local coordinates from the four neighbouring normal texels.
vec4 wang2020_prefilter_lookup(ivec4 res, vec3 n, vec3 o_world) {
    if (!wang2020_finite(n.x + n.y + n.z + o_world.x + o_world.y + o_world.z)) return vec4(0.0f);
    float tn = acos(clamp(n.z, -1.0f, 1.0f));
    float pn = atan(n.y, n.x);
    int a0, a1, b0, b1, c0, c1, d0, d1;
    float fa, fb, fc, fd;
    wang2020_cell(tn / PI * float(res.x) - 0.5f, res.x, false, a0, a1, fa);
    wang2020_cell(pn / TWO_PI * float(res.y) - 0.5f, res.y, true, b0, b1, fb);
    vec3 t, b;
    tangent_frame(n, t, b);  // wang2020_prefilter.cpp's tangent_frame
    vec3 ol = vec3(dot(o_world, t), dot(o_world, b), max(dot(o_world, n), 0.0f));
    float to = acos(clamp(ol.z / max(length(ol), 1e-12f), 0.0f, 1.0f));
    float po = atan(ol.y, ol.x);
    wang2020_cell(to / WANG2020_HALF_PI * float(res.z) - 0.5f, res.z, false, c0, c1, fc);
    wang2020_cell(po / TWO_PI * float(res.w) - 0.5f, res.w, true, d0, d1, fd);
    vec4 v0 = mix(wang2020_prefilter_o(res, a0, b0, c0, c1, fc, d0, d1, fd),
                  wang2020_prefilter_o(res, a0, b1, c0, c1, fc, d0, d1, fd), fb);
    vec4 v1 = mix(wang2020_prefilter_o(res, a1, b0, c0, c1, fc, d0, d1, fd),
                  wang2020_prefilter_o(res, a1, b1, c0, c1, fc, d0, d1, fd), fb);
    return mix(v0, v1, fa);
}

// wang2020_quadtree.cpp mix32 / hash_unit: lowbias32 (Wellons), 24-bit unit.
uint wang2020_mix32(uint x) {
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

float wang2020_hash_unit(uint a, uint b, uint c, uint d) {
    uint h = wang2020_mix32(a ^ wang2020_mix32(b ^ wang2020_mix32(c ^ wang2020_mix32(d))));
    return float(h >> 8u) * 5.9604644775390625e-8f;  // 2^-24
}

// Σ_k 1_A(x_k) over the particles of the uv box [lo, hi] (tiles repeat), or,
// when `per_particle`, Σ_k 1_A(x_k) H(p − λ_k) (micro scale, Eq. 20: a
// particle is accepted iff λ(x_k) < p). ParticleQuadtree::traverse: nodes
// wholly inside A add their count (counting only), leaves cut by A's border
// are resolved particle by particle; particle k of leaf (x, y) sits at
// ((x, y) + hash(leaf, k, seed, 1|2)) / 2^depth with λ = hash(leaf, k, seed, 3).
// Boxes over more than 64 tiles return 0 (the caller uses the macro scale).
uint wang2020_quadtree_count(Wang2020Tables tb, vec2 lo, vec2 hi, bool per_particle, float p) {
    if (!(lo.x <= hi.x && lo.y <= hi.y)) return 0u;
    float tx0 = floor(lo.x), tx1 = floor(hi.x), ty0 = floor(lo.y), ty1 = floor(hi.y);
    if (!((tx1 - tx0 + 1.0f) * (ty1 - ty0 + 1.0f) <= 64.0f)) return 0u;
    float leaves = exp2(float(tb.depth));
    uint total = 0u;
    uvec4 stack[WANG2020_STACK];  // node index, depth, x, y
    for (float ty = ty0; ty <= ty1; ty += 1.0f) {
        for (float tx = tx0; tx <= tx1; tx += 1.0f) {
            vec2 a = vec2(max(lo.x - tx, 0.0f), max(lo.y - ty, 0.0f));
            vec2 b = vec2(min(hi.x - tx, 1.0f), min(hi.y - ty, 1.0f));
            int top = 0;
            stack[top++] = uvec4(0u, 0u, 0u, 0u);
            while (top > 0) {
                uvec4 it = stack[--top];
                int d = int(it.y);
                uvec2 node = wang2020_node(int(it.x));
                float size = exp2(-float(d));
                float n0x = float(it.z) * size, n0y = float(it.w) * size;
                float n1x = n0x + size, n1y = n0y + size;
                if (n1x <= a.x || n0x >= b.x || n1y <= a.y || n0y >= b.y) continue;
                bool inside = n0x >= a.x && n1x <= b.x && n0y >= a.y && n1y <= b.y;
                uint count = node.y & 0x0FFFFFFFu;
                if (inside && !per_particle) {
                    total += count;
                    continue;
                }
                if (d == tb.depth) {
                    // Leaf-local box: exact (a·2^depth − x is exact in float
                    // when the edge lies in this leaf), so the comparisons
                    // equal the CPU's double ones.
                    float ax = a.x * leaves - float(it.z), bx = b.x * leaves - float(it.z);
                    float ay = a.y * leaves - float(it.w), by = b.y * leaves - float(it.w);
                    uint leaf = (it.w << uint(tb.depth)) + it.z;
                    for (uint k = 0u; k < count; ++k) {
                        float hx = wang2020_hash_unit(leaf, k, tb.seed, 1u);
                        float hy = wang2020_hash_unit(leaf, k, tb.seed, 2u);
                        if (!(hx >= ax && hx < bx && hy >= ay && hy < by)) continue;
                        if (per_particle && !(wang2020_hash_unit(leaf, k, tb.seed, 3u) < p)) continue;
                        total += 1u;
                    }
                    continue;
                }
                uint child = node.x;
                uint mask = node.y >> 28u;
                for (uint c = 0u; c < 4u; ++c) {
                    if ((mask & (1u << c)) == 0u) continue;
                    stack[top++] = uvec4(child, uint(d + 1), 2u * it.z + (c & 1u),
                                         2u * it.w + (c >> 1u));
                    child += 1u;
                }
            }
        }
    }
    return total;
}

// AABB of the footprint parallelogram uv + s duvdx + t duvdy, s, t ∈ [-½, ½)
// (wang2020_model.cpp box_of).
void wang2020_footprint_box(Footprint fp, OUT(vec2) lo, OUT(vec2) hi) {
    vec2 half_extent = 0.5f * (abs(fp.duvdx) + abs(fp.duvdy));
    lo = fp.uv - half_extent;
    hi = fp.uv + half_extent;
}

// §4.3 scale of box A (Wang2020Model scale_for): degenerate boxes and boxes
// over more than 64 uv tiles use the macro scale.
int wang2020_scale_for(vec2 lo, vec2 hi, float particles) {
    float area = max(0.0f, hi.x - lo.x) * max(0.0f, hi.y - lo.y);
    if (!(area > 0.0f) || !wang2020_finite(area)) return WANG2020_MACRO;
    float tiles = (floor(hi.x) - floor(lo.x) + 1.0f) * (floor(hi.y) - floor(lo.y) + 1.0f);
    if (!(tiles <= 64.0f)) return WANG2020_MACRO;
    return wang2020_select_scale(particles * area);
}

// Environment radiance towards o (world), before the tint: Eqs. 18-20
// (Wang2020Model::environment_radiance).
vec3 wang2020_environment(Wang2020Tables tb, vec2 lo, vec2 hi, vec3 n_world, vec3 o_world) {
    if (!(dot(n_world, o_world) > 0.0f)) return vec3(0.0f);
    vec4 t = wang2020_prefilter_lookup(tb.prefilter_res, n_world, o_world);
    vec3 lhat = vec3(t.x, t.y, t.z);
    float phat = t.w;
    int scale = wang2020_scale_for(lo, hi, tb.particles);
    float count = 0.0f;
    float accepted = 0.0f;
    if (scale == WANG2020_MESO) count = float(wang2020_quadtree_count(tb, lo, hi, false, 0.0f));
    if (scale == WANG2020_MICRO && phat > 0.0f)
        accepted = float(wang2020_quadtree_count(tb, lo, hi, true, min(phat, 1.0f)));
    float area = max(0.0f, hi.x - lo.x) * max(0.0f, hi.y - lo.y);
    return wang2020_environment_combine(scale, lhat, phat, count, accepted, area, tb.particles,
                                        tb.sigma);
}

// D̂'(A, o, i) of Eq. 21 for a light from local direction wi towards local
// wo (Wang2020Model::light_radiance without M and the light's radiance).
float wang2020_light_dprime(Wang2020Tables tb, vec2 lo, vec2 hi, vec3 wi, vec3 wo) {
    if (!(wi.z > 0.0f) || !(wo.z > 0.0f)) return 0.0f;
    float p = wang2020_dpf_lookup(tb.dpf_res, wi, wo);  // P(i, o, γ), §5
    int scale = wang2020_scale_for(lo, hi, tb.particles);
    float count = 0.0f;
    float accepted = 0.0f;
    if (scale == WANG2020_MESO) count = float(wang2020_quadtree_count(tb, lo, hi, false, 0.0f));
    if (scale == WANG2020_MICRO)
        accepted = float(wang2020_quadtree_count(tb, lo, hi, true, min(p, 1.0f)));
    float area = max(0.0f, hi.x - lo.x) * max(0.0f, hi.y - lo.y);
    return wang2020_point_dprime(scale, p, count, accepted, area, tb.particles, tb.sigma);
}

// M(i, o) of Eq. 11 in wang2020_prefilter.h's form (i·h) G2 / ((h·n)(o·n)),
// F = 1, height-correlated Beckmann G2 (erf_approx: |error| < 1.2e-7).
float wang2020_m_term(vec3 wi, vec3 wo, float alpha) {
    if (!(wi.z > 0.0f) || !(wo.z > 0.0f)) return 0.0f;
    vec3 h = normalize(wi + wo);
    if (h.z <= 0.0f) return 0.0f;
    return dot(wi, h) * G2_SmithCorrelated(NDF_BECKMANN, wo, wi, alpha, alpha) / (h.z * wo.z);
}

// Eq. 21 for a light of irradiance li normal to wi (local directions):
// Lo = li D̂'(A, o, i) M(i, o), before the tint.
vec3 wang2020_light(Wang2020Tables tb, vec2 lo, vec2 hi, vec3 wi, vec3 wo, vec3 li) {
    return li * (wang2020_light_dprime(tb, lo, hi, wi, wo) * wang2020_m_term(wi, wo, tb.alpha));
}

#endif  // GLINTLAB_GLINTS_WANG2020_TABLES_GLSL
