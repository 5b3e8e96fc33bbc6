// wang2020 (Wang et al. 2020, 001) table and quadtree reads for the GPU, in the shared
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
//   vec4  wang2020_cone_value(int index);       ParticleRadianceTable::data() (point
//                                               values or L_γ, per_particle)
// Precision: float instead of the CPU's double; particle tests are done in
// leaf-local coordinates, where the box edges are exact, so counts agree
// with the CPU for boxes given in float.
#ifndef GLINTLAB_GLINTS_WANG2020_TABLES_GLSL
#define GLINTLAB_GLINTS_WANG2020_TABLES_GLSL

#include "glintlab/core/constants.glsl"
#include "glintlab/core/footprint.glsl"
#include "glintlab/core/frame.glsl"
#include "glintlab/glints/glint_fresnel.glsl"
#include "glintlab/glints/wang2020/wang2020.glsl"
#include "glintlab/microfacet/masking.glsl"

float wang2020_dpf_value(int index);
vec4 wang2020_prefilter_value(int index);
uvec2 wang2020_node(int index);
vec4 wang2020_cone_value(int index);

const float WANG2020_HALF_PI = 1.57079632679489661923f;
// DFS stack of the traversal: each pop pushes at most 4 children, so it
// holds at most 3 depth + 1 <= 49 items for depth <= 16.
const int WANG2020_STACK = 64;

// Wang2020Tables::micro: "micro": "as_published"; "per_particle" with
// "scale_count": "particles"; "per_particle" with "effective" (the
// prefiltered table's w is then the effective fraction r, not P̂).
const int WANG2020_MICRO_MODE_AS_PUBLISHED = 0;
const int WANG2020_MICRO_MODE_PER_PARTICLE = 1;
const int WANG2020_MICRO_MODE_PER_PARTICLE_EFFECTIVE = 2;

// What the shader needs of one material's tables (Wang2020Model).
struct Wang2020Tables {
    ivec3 dpf_res;        // θi, θo, Δφ
    ivec4 prefilter_res;  // θn, φn, θo, φo
    int depth;            // quadtree depth
    uint seed;            // quadtree seed
    float particles;      // N per uv tile
    float sigma;          // σ(Ωo) = 2π(1 − cos γ)
    float alpha;          // Beckmann roughness
    int micro;            // WANG2020_MICRO_MODE_* (wang2020_micro_mode_index)
    ivec2 cone_res;       // L_γ table width, height (per_particle with an environment)
    float cos_gamma;      // cos γ
    int fresnel_mode;     // F of M (Eq. 11): GLINT_FRESNEL_* (glint_fresnel.glsl)
    vec3 fresnel_f0;
    vec3 fresnel_eta;
    vec3 fresnel_k;
};

// F(cos) of M (Eq. 11), the material's Fresnel (Wang2020Material::fresnel).
vec3 wang2020_fresnel(Wang2020Tables tb, float cos_ih) {
    return glint_fresnel_mode(tb.fresnel_mode, tb.fresnel_f0, tb.fresnel_eta, tb.fresnel_k,
                              cos_ih);
}

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

// Bilinear in (θo, φo) at one normal texel, φo in [0, 2π) cells (po in
// radians, any real: the cell search wraps it).
vec4 wang2020_prefilter_o(ivec4 res, int tn, int pn, int c0, int c1, float fc, float po) {
    int d0, d1;
    float fd;
    wang2020_cell(po / TWO_PI * float(res.w) - 0.5f, res.w, true, d0, d1, fd);
    vec4 v0 = mix(wang2020_prefilter_texel(res, tn, pn, c0, d0),
                  wang2020_prefilter_texel(res, tn, pn, c0, d1), fd);
    vec4 v1 = mix(wang2020_prefilter_texel(res, tn, pn, c1, d0),
                  wang2020_prefilter_texel(res, tn, pn, c1, d1), fd);
    return mix(v0, v1, fc);
}

// PrefilterTable::frame_turn: the azimuth, in the tangent frame of the
// normal texel m, of the query frame's tangent t (frame of n) carried to m by
// the shortest-arc rotation from n to m.
float wang2020_frame_turn(vec3 n, vec3 t, vec3 m) {
    float c = dot(n, m);
    vec3 k = cross(n, m);
    vec3 tm = t * c + cross(k, t) + k * (dot(k, t) / (1.0f + c));
    vec3 tt, bb;
    tangent_frame(m, tt, bb);
    return atan(dot(tm, bb), dot(tm, tt));
}

// PrefilterTable::texel_normal.
vec3 wang2020_prefilter_normal(ivec4 res, int tn, int pn) {
    float th = (float(tn) + 0.5f) / float(res.x) * PI;
    float ph = (float(pn) + 0.5f) / float(res.y) * TWO_PI;
    return vec3(sin(th) * cos(ph), sin(th) * sin(ph), cos(th));
}

// PrefilterTable::lookup: rgb = L̂o(n, o) (Eq. 16), w = P̂(n, o) (Eq. 17),
// quadrilinear; o is expressed once in the query normal's tangent frame and
// read at those local coordinates from the four neighbouring normal texels,
// the azimuth turned by each texel's frame_turn.
vec4 wang2020_prefilter_lookup(ivec4 res, vec3 n, vec3 o_world) {
    if (!wang2020_finite(n.x + n.y + n.z + o_world.x + o_world.y + o_world.z)) return vec4(0.0f);
    float tn = acos(clamp(n.z, -1.0f, 1.0f));
    float pn = atan(n.y, n.x);
    int a0, a1, b0, b1, c0, c1;
    float fa, fb, fc;
    wang2020_cell(tn / PI * float(res.x) - 0.5f, res.x, false, a0, a1, fa);
    wang2020_cell(pn / TWO_PI * float(res.y) - 0.5f, res.y, true, b0, b1, fb);
    vec3 t, b;
    tangent_frame(n, t, b);  // wang2020_prefilter.cpp's tangent_frame
    vec3 ol = vec3(dot(o_world, t), dot(o_world, b), max(dot(o_world, n), 0.0f));
    float to = acos(clamp(ol.z / max(length(ol), 1e-12f), 0.0f, 1.0f));
    float po = atan(ol.y, ol.x);
    wang2020_cell(to / WANG2020_HALF_PI * float(res.z) - 0.5f, res.z, false, c0, c1, fc);
    vec4 v00 = wang2020_prefilter_o(res, a0, b0, c0, c1, fc,
                                    po + wang2020_frame_turn(n, t, wang2020_prefilter_normal(res, a0, b0)));
    vec4 v01 = wang2020_prefilter_o(res, a0, b1, c0, c1, fc,
                                    po + wang2020_frame_turn(n, t, wang2020_prefilter_normal(res, a0, b1)));
    vec4 v10 = wang2020_prefilter_o(res, a1, b0, c0, c1, fc,
                                    po + wang2020_frame_turn(n, t, wang2020_prefilter_normal(res, a1, b0)));
    vec4 v11 = wang2020_prefilter_o(res, a1, b1, c0, c1, fc,
                                    po + wang2020_frame_turn(n, t, wang2020_prefilter_normal(res, a1, b1)));
    return mix(mix(v00, v01, fb), mix(v10, v11, fb), fa);
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

// ParticleRadianceTable::lookup: bilinear point value or L_γ at a world direction (cell
// centred; clamped in θ from +z, periodic in φ = atan2(y, x)).
vec3 wang2020_cone_lookup(ivec2 res, vec3 d) {
    float len = length(d);
    if (!(len > 0.0f) || !wang2020_finite(len)) return vec3(0.0f);
    float t = acos(clamp(d.z / len, -1.0f, 1.0f));
    float p = atan(d.y, d.x);
    int a0, a1, b0, b1;
    float fa, fb;
    wang2020_cell(t / PI * float(res.y) - 0.5f, res.y, false, a0, a1, fa);
    wang2020_cell(p / TWO_PI * float(res.x) - 0.5f, res.x, true, b0, b1, fb);
    vec3 v0 = mix(vec3(wang2020_cone_value(a0 * res.x + b0)),
                  vec3(wang2020_cone_value(a0 * res.x + b1)), fb);
    vec3 v1 = mix(vec3(wang2020_cone_value(a1 * res.x + b0)),
                  vec3(wang2020_cone_value(a1 * res.x + b1)), fb);
    return mix(v0, v1, fa);
}

// Particle normal ~ D(m)(m·n) from its hashes 4 and 5 (wang2020_beckmann.h
// beckmann_sample_normal): tan²θ = −α² ln(1 − u1), φ = 2π u2.
vec3 wang2020_particle_normal(float u1, float u2, float alpha) {
    float tan2 = -alpha * alpha * log(1.0f - u1);
    float c = 1.0f / sqrt(1.0f + tan2);
    float s = sqrt(max(0.0f, 1.0f - c * c));
    float phi = TWO_PI * u2;
    return vec3(s * cos(phi), s * sin(phi), c);
}

float wang2020_m_term(vec3 wi, vec3 wo, float alpha);

// What the traversal does per particle of A.
const int WANG2020_VISIT_COUNT = 0;   // Σ 1_A
const int WANG2020_VISIT_ACCEPT = 1;  // per light j: Σ 1_A H(p_j − λ_k) (Eq. 20)
const int WANG2020_VISIT_ENV = 2;     // sum += L_γ(reflect(o, m_k)) M (per_particle)
const int WANG2020_VISIT_LIT = 3;     // per light j: Σ 1_A [reflect(i_j, m_k) in the γ cone of o]
// Lights one traversal serves (wang2020_lights). Each traversal enumerates
// up to WANG2020_MICRO_ENUMERATION_MAX particles, and Mesa llvmpipe ends
// every loop of a fragment once their iterations together pass 65535, so a
// traversal per light darkened scenes of a few lights. The per-light loop
// inside the per-particle one has a constant trip count and is unrolled,
// but every slot costs: where the including glue knows its light count
// (GLINTLAB_WANG2020_LIGHTS, the renderer), the fewest traversals of at
// most four lights, their slots shared out evenly (9 lights: 3 × 3); else
// (exports) one.
#ifdef GLINTLAB_WANG2020_LIGHTS
const int WANG2020_LIGHT_TRAVERSALS = (GLINTLAB_WANG2020_LIGHTS + 3) / 4;
const int WANG2020_LIGHT_BATCH =
    (GLINTLAB_WANG2020_LIGHTS + WANG2020_LIGHT_TRAVERSALS - 1) / WANG2020_LIGHT_TRAVERSALS;
#else
const int WANG2020_LIGHT_BATCH = 1;
#endif
struct Wang2020Visit {
    int mode;
    int lights;                        // ACCEPT, LIT: lights of the batch in use
    vec4 p;                            // ACCEPT: each light's acceptance probability
    mat4x3 wi;                         // LIT: each light's local direction
    vec3 o;                            // local view direction (ENV, LIT)
    vec3 t, b, n;                      // local -> world frame (ENV)
};
// What a traversal found.
struct Wang2020Tally {
    uint in_a;                         // Σ 1_A (every mode)
    uvec4 hits;                        // ACCEPT, LIT: per light
    vec3 sum;                          // ENV
};

// Footprint A of a query (Wang2020Model's UvBox): the uv box [lo, hi] the
// quadtree is queried with and, when `parallelogram`, the pixel's
// parallelogram centre + s du + t dv, s, t ∈ [-½, ½), whose AABB the box is.
// The per_particle modes count and sum only the parallelogram's particles.
struct Wang2020Footprint {
    vec2 lo;
    vec2 hi;
    vec2 centre;
    vec2 du;
    vec2 dv;
    bool parallelogram;
};

Wang2020Footprint wang2020_box_footprint(vec2 lo, vec2 hi) {
    Wang2020Footprint a;
    a.lo = lo;
    a.hi = hi;
    a.centre = vec2(0.0f);
    a.du = vec2(0.0f);
    a.dv = vec2(0.0f);
    a.parallelogram = false;
    return a;
}

// UvBox::contains: p (uv) in the parallelogram (true without one).
bool wang2020_in_parallelogram(Wang2020Footprint a, vec2 p) {
    if (!a.parallelogram) return true;
    float det = a.du.x * a.dv.y - a.du.y * a.dv.x;
    if (!(det != 0.0f)) return false;
    vec2 d = p - a.centre;
    float s = (d.x * a.dv.y - d.y * a.dv.x) / det;
    float t = (a.du.x * d.y - a.du.y * d.x) / det;
    return s >= -0.5f && s < 0.5f && t >= -0.5f && t < 0.5f;
}

// UvBox::footprint_area: the parallelogram's area, else the box's.
float wang2020_footprint_area(Wang2020Footprint a) {
    if (a.parallelogram) return abs(a.du.x * a.dv.y - a.du.y * a.dv.x);
    return max(0.0f, a.hi.x - a.lo.x) * max(0.0f, a.hi.y - a.lo.y);
}

Wang2020Tally wang2020_tally() {
    Wang2020Tally r;
    r.in_a = 0u;
    r.hits = uvec4(0u);
    r.sum = vec3(0.0f);
    return r;
}

// The particles of the uv box [A.lo, A.hi] (tiles repeat), of its
// parallelogram only when `clip`, visited as v.mode says, into `tally`.
// ParticleQuadtree::traverse: nodes wholly inside A add their count (COUNT
// only), leaves cut by A's border are resolved particle by particle;
// particle k of leaf (x, y) sits at ((x, y) + hash(leaf, k, seed, 1|2)) /
// 2^depth with λ = hash(leaf, k, seed, 3) and normal hashes 4, 5. Boxes
// over more than 64 tiles visit nothing (the caller uses the macro scale).
void wang2020_quadtree_visit(Wang2020Tables tb, Wang2020Footprint A, bool clip, Wang2020Visit v,
                             OUT(Wang2020Tally) tally) {
    tally = wang2020_tally();
    vec2 lo = A.lo, hi = A.hi;
    clip = clip && A.parallelogram;
    if (!(lo.x <= hi.x && lo.y <= hi.y)) return;
    float tx0 = floor(lo.x), tx1 = floor(hi.x), ty0 = floor(lo.y), ty1 = floor(hi.y);
    if (!((tx1 - tx0 + 1.0f) * (ty1 - ty0 + 1.0f) <= 64.0f)) return;
    bool per_particle = v.mode != WANG2020_VISIT_COUNT;
    float leaves = exp2(float(tb.depth));
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
                if (inside && !per_particle && !clip) {
                    tally.in_a += count;
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
                        if (clip && !wang2020_in_parallelogram(
                                        A, vec2(tx + (float(it.z) + hx) / leaves,
                                                ty + (float(it.w) + hy) / leaves)))
                            continue;
                        tally.in_a += 1u;
                        if (v.mode == WANG2020_VISIT_ACCEPT) {
                            float lambda = wang2020_hash_unit(leaf, k, tb.seed, 3u);
                            for (int j = 0; j < WANG2020_LIGHT_BATCH; ++j)
                                if (j < v.lights && lambda < v.p[j]) tally.hits[j] += 1u;
                        } else if (v.mode != WANG2020_VISIT_COUNT) {
                            vec3 m = wang2020_particle_normal(
                                wang2020_hash_unit(leaf, k, tb.seed, 4u),
                                wang2020_hash_unit(leaf, k, tb.seed, 5u), tb.alpha);
                            if (v.mode == WANG2020_VISIT_ENV) {
                                float om = dot(v.o, m);
                                if (!(om > 0.0f)) continue;
                                vec3 i = 2.0f * om * m - v.o;  // reflect(o, m_k)
                                if (!(i.z > 0.0f)) continue;
                                vec3 i_world = i.x * v.t + i.y * v.b + i.z * v.n;
                                tally.sum += wang2020_cone_lookup(tb.cone_res, i_world) *
                                             wang2020_fresnel(tb, om) *
                                             wang2020_m_term(i, v.o, tb.alpha);
                            } else {
                                for (int j = 0; j < WANG2020_LIGHT_BATCH; ++j) {
                                    float im = dot(v.wi[j], m);
                                    if (j < v.lights && im > 0.0f &&
                                        dot(2.0f * im * m - v.wi[j], v.o) >= tb.cos_gamma)
                                        tally.hits[j] += 1u;
                                }
                            }
                        }
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
}

Wang2020Visit wang2020_visit(int mode) {
    Wang2020Visit v;
    v.mode = mode;
    v.lights = 0;
    v.p = vec4(0.0f);
    v.wi = mat4x3(0.0f);
    v.o = vec3(0.0f);
    v.t = vec3(0.0f);
    v.b = vec3(0.0f);
    v.n = vec3(0.0f);
    return v;
}

// Σ_k 1_A(x_k) over the particles of the uv box of A (of its parallelogram
// when `clip`), or, when `per_particle`, Σ_k 1_A(x_k) H(p − λ_k) (micro
// scale, Eq. 20: a particle is accepted iff λ(x_k) < p).
uint wang2020_quadtree_count(Wang2020Tables tb, Wang2020Footprint A, bool clip, bool per_particle,
                             float p) {
    Wang2020Visit v = wang2020_visit(per_particle ? WANG2020_VISIT_ACCEPT : WANG2020_VISIT_COUNT);
    v.lights = 1;
    v.p[0] = p;
    Wang2020Tally tally;
    wang2020_quadtree_visit(tb, A, clip, v, tally);
    return per_particle ? tally.hits[0] : tally.in_a;
}

// The footprint parallelogram uv + s duvdx + t duvdy, s, t ∈ [-½, ½) and its
// AABB (wang2020_model.cpp box_of).
Wang2020Footprint wang2020_footprint(Footprint fp) {
    vec2 half_extent = 0.5f * (abs(fp.duvdx) + abs(fp.duvdy));
    Wang2020Footprint a = wang2020_box_footprint(fp.uv - half_extent, fp.uv + half_extent);
    a.centre = fp.uv;
    a.du = fp.duvdx;
    a.dv = fp.duvdy;
    a.parallelogram = any(notEqual(fp.duvdx, vec2(0.0f))) || any(notEqual(fp.duvdy, vec2(0.0f)));
    return a;
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

// Blend weights of the per_particle mode (Wang2020Model blend_weights):
// "effective" (wang2020_effective_weights of the fraction) or the particle
// count's bands, counts of the parallelogram (the enumeration bound: of the
// box); degenerate footprints and boxes over more than 64 tiles are pure
// macro.
vec3 wang2020_weights_for(Wang2020Footprint A, float particles, bool effective, float fraction) {
    vec2 lo = A.lo, hi = A.hi;
    float area = max(0.0f, hi.x - lo.x) * max(0.0f, hi.y - lo.y);
    if (!(area > 0.0f) || !wang2020_finite(area)) return vec3(0.0f, 0.0f, 1.0f);
    float tiles = (floor(hi.x) - floor(lo.x) + 1.0f) * (floor(hi.y) - floor(lo.y) + 1.0f);
    if (!(tiles <= 64.0f)) return vec3(0.0f, 0.0f, 1.0f);
    float footprint = wang2020_footprint_area(A);
    if (!(footprint > 0.0f)) return vec3(0.0f, 0.0f, 1.0f);
    if (effective)
        return wang2020_effective_weights(particles * footprint, particles * area, fraction);
    return wang2020_scale_weights(particles * footprint);
}

// Environment radiance towards o (world), before the tint: Eqs. 18-20
// (Wang2020Model::environment_radiance).
vec3 wang2020_environment(Wang2020Tables tb, Wang2020Footprint A, vec3 n_world, vec3 o_world) {
    vec2 lo = A.lo, hi = A.hi;
    if (!(dot(n_world, o_world) > 0.0f)) return vec3(0.0f);
    vec4 t = wang2020_prefilter_lookup(tb.prefilter_res, n_world, o_world);
    vec3 lhat = vec3(t.x, t.y, t.z);
    float phat = t.w;
    if (tb.micro != WANG2020_MICRO_MODE_AS_PUBLISHED) {
        // The table's w is the effective fraction r under "effective".
        bool effective = tb.micro == WANG2020_MICRO_MODE_PER_PARTICLE_EFFECTIVE;
        vec3 w = wang2020_weights_for(A, tb.particles, effective, phat);
        // The reflections' traversal counts A's as well; each call site with
        // its own constant mode (as wang2020_batch_tally's).
        float count = 0.0f;
        vec3 sum = vec3(0.0f);
        if (w.x > 0.0f) {
            Wang2020Visit v = wang2020_visit(WANG2020_VISIT_ENV);
            tangent_frame(n_world, v.t, v.b);
            v.n = n_world;
            vec3 ol = vec3(dot(o_world, v.t), dot(o_world, v.b), dot(o_world, n_world));
            v.o = ol / length(ol);
            Wang2020Tally tally;
            wang2020_quadtree_visit(tb, A, true, v, tally);
            sum = tally.sum;
            count = float(tally.in_a);
        } else if (w.y > 0.0f) {
            count = float(wang2020_quadtree_count(tb, A, true, false, 0.0f));
        }
        return wang2020_environment_blend(w, lhat, sum, count, wang2020_footprint_area(A),
                                          tb.particles, tb.sigma);
    }
    int scale = wang2020_scale_for(lo, hi, tb.particles);
    float count = 0.0f;
    float accepted = 0.0f;
    if (scale == WANG2020_MESO) count = float(wang2020_quadtree_count(tb, A, false, false, 0.0f));
    if (scale == WANG2020_MICRO && phat > 0.0f)
        accepted = float(wang2020_quadtree_count(tb, A, false, true, min(phat, 1.0f)));
    float area = max(0.0f, hi.x - lo.x) * max(0.0f, hi.y - lo.y);
    return wang2020_environment_combine(scale, lhat, phat, count, accepted, area, tb.particles,
                                        tb.sigma);
}

// Up to WANG2020_LIGHT_BATCH lights shaded from one traversal of A.
struct Wang2020LightBatch {
    int lights;  // in use
    mat4x3 wi;   // columns: local directions towards the lights
    mat4x3 li;   // columns: irradiance normal to wi
};

Wang2020LightBatch wang2020_light_batch() {
    Wang2020LightBatch batch;
    batch.lights = 0;
    batch.wi = mat4x3(0.0f);
    batch.li = mat4x3(0.0f);
    return batch;
}

// The counts D̂' (Eq. 21) of a batch's lights take, from one traversal of A:
// the particles in A and, per light j (p[j] >= 0: in use and above the
// horizon), those lit (per_particle, weights w[j]) or accepted (as
// published, micro scale).
Wang2020Tally wang2020_batch_tally(Wang2020Tables tb, Wang2020Footprint A,
                                   Wang2020LightBatch batch, vec3 wo, mat4x3 w, vec4 p,
                                   int scale) {
    Wang2020Tally tally = wang2020_tally();
    if (tb.micro != WANG2020_MICRO_MODE_AS_PUBLISHED) {
        bool enumerate = false, count = false;
        for (int j = 0; j < WANG2020_LIGHT_BATCH; ++j) {
            bool used = j < batch.lights && p[j] >= 0.0f;
            enumerate = enumerate || (used && w[j].x > 0.0f);
            count = count || (used && w[j].y > 0.0f);
        }
        // The lit particles' traversal counts A's as well. Each call site
        // with its own constant mode: the shader compiler folds the modes'
        // branches out of the per-particle loop.
        if (enumerate) {
            Wang2020Visit v = wang2020_visit(WANG2020_VISIT_LIT);
            v.lights = batch.lights;
            v.o = wo;
            v.wi = batch.wi;
            wang2020_quadtree_visit(tb, A, true, v, tally);
        } else if (count) {
            tally.in_a = wang2020_quadtree_count(tb, A, true, false, 0.0f);
        }
    } else if (scale == WANG2020_MESO) {
        tally.in_a = wang2020_quadtree_count(tb, A, false, false, 0.0f);
    } else if (scale == WANG2020_MICRO) {
        Wang2020Visit v = wang2020_visit(WANG2020_VISIT_ACCEPT);
        v.lights = batch.lights;
        v.p = min(p, vec4(1.0f));
        wang2020_quadtree_visit(tb, A, false, v, tally);
    }
    return tally;
}

// Eq. 21 summed over a batch of lights: Σ_j li_j D̂'(A, o, i_j) M(i_j, o),
// before the tint; M's F at i·h (m_fresnel).
vec3 wang2020_lights(Wang2020Tables tb, Wang2020Footprint A, Wang2020LightBatch batch, vec3 wo) {
    vec2 lo = A.lo, hi = A.hi;
    if (!(wo.z > 0.0f)) return vec3(0.0f);
    // Vectors and matrices, not arrays: Mesa keeps arrays in scratch memory.
    vec4 p = vec4(-1.0f);  // P(i, o, γ), §5; -1: light unused
    mat4x3 w = mat4x3(0.0f);  // columns: per_particle blend weights (r = p)
    bool effective = tb.micro == WANG2020_MICRO_MODE_PER_PARTICLE_EFFECTIVE;
    bool any_lit = false;
    for (int j = 0; j < WANG2020_LIGHT_BATCH; ++j) {
        if (j < batch.lights && batch.wi[j].z > 0.0f) {
            p[j] = wang2020_dpf_lookup(tb.dpf_res, batch.wi[j], wo);
            w[j] = wang2020_weights_for(A, tb.particles, effective, p[j]);
            any_lit = true;
        }
    }
    if (!any_lit) return vec3(0.0f);
    int scale = wang2020_scale_for(lo, hi, tb.particles);
    Wang2020Tally tally = wang2020_batch_tally(tb, A, batch, wo, w, p, scale);
    float area = max(0.0f, hi.x - lo.x) * max(0.0f, hi.y - lo.y);
    vec3 radiance = vec3(0.0f);
    for (int j = 0; j < WANG2020_LIGHT_BATCH; ++j) {
        if (!(p[j] >= 0.0f)) continue;
        float dprime;
        if (tb.micro != WANG2020_MICRO_MODE_AS_PUBLISHED)
            dprime = wang2020_point_dprime_blend(w[j], p[j], float(tally.in_a),
                                                 float(tally.hits[j]), wang2020_footprint_area(A),
                                                 tb.particles, tb.sigma);
        else
            dprime = wang2020_point_dprime(scale, p[j], float(tally.in_a), float(tally.hits[j]),
                                           area, tb.particles, tb.sigma);
        vec3 wi = batch.wi[j];
        vec3 f = vec3(1.0f);
        if (tb.fresnel_mode != GLINT_FRESNEL_NONE)
            f = wang2020_fresnel(tb, dot(wi, normalize(wi + wo)));
        radiance += batch.li[j] * f * (dprime * wang2020_m_term(wi, wo, tb.alpha));
    }
    return radiance;
}

// M(i, o) of Eq. 11 in wang2020_prefilter.h's form (i·h) G2 / ((h·n)(o·n))
// without its F (wang2020_fresnel), height-correlated Beckmann G2 (erf_approx: |error| < 1.2e-7).
float wang2020_m_term(vec3 wi, vec3 wo, float alpha) {
    if (!(wi.z > 0.0f) || !(wo.z > 0.0f)) return 0.0f;
    vec3 h = normalize(wi + wo);
    if (h.z <= 0.0f) return 0.0f;
    return dot(wi, h) * G2_SmithCorrelated(NDF_BECKMANN, wo, wi, alpha, alpha) / (h.z * wo.z);
}

// Eq. 21 for one light of irradiance li normal to wi (local directions).
vec3 wang2020_light(Wang2020Tables tb, Wang2020Footprint A, vec3 wi, vec3 wo, vec3 li) {
    Wang2020LightBatch batch = wang2020_light_batch();
    batch.lights = 1;
    batch.wi[0] = wi;
    batch.li[0] = li;
    return wang2020_lights(tb, A, batch, wo);
}

#endif  // GLINTLAB_GLINTS_WANG2020_TABLES_GLSL
