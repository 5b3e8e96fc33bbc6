// deliot2023 footprint NDF D_P(h): Deliot & Belcour, "Real-Time Rendering of
// Glinty Appearances using Distributed Binomial Laws on Anisotropic Grids",
// HPG/CGF 2023 (000). Equation numbers below are that paper's.
//
// Pipeline for one half vector h and one pixel footprint:
//  1. footprint ellipse (§5.1): minor/major axis lengths and orientation;
//  2. the (LOD, ratio, orientation) lattice of anisotropic virtual grids
//     (Eq. 11-13, Fig. 5-6), split into tetrahedra (§6.1): 4 weighted grids,
//     whose weights distribute the footprint's trials (Eq. 10);
//  3. per grid, a simplex (triangle) spatial lattice (§6.2): 3 vertices blended
//     barycentrically, each holding N = cell area x density x grid weight trials;
//  4. per vertex, an angular grid over h.xy / R with a random offset, blended
//     bilinearly (Eq. 14): 4 counts from the gated Gaussian law (§6.3);
//  5. D_P = D(n) / R x (blended count) / (blended trials) (Eq. 3-4), whose
//     mean is D(h) (Eq. 5-6).
// 4 x 3 x 4 = 48 binomial evaluations, constant for every footprint.
//
// `original_defects` reproduces the authors' HLSL's defects as
// docs/MODELS.md, "Known defects of the original HLSL", lists (cancelling
// ellipse eigenvalue, Gaussian clamped to N, gate 1-(1-p)^N for N < 1,
// naive fp32 (1-p)^N, LOD truncated toward zero, no anisotropy clamp);
// otherwise each of these is fixed.
#ifndef GLINTLAB_GLINTS_DELIOT2023_GLSL
#define GLINTLAB_GLINTS_DELIOT2023_GLSL

#include "glintlab/core/constants.glsl"
#include "glintlab/core/footprint.glsl"
#include "glintlab/core/hash.glsl"
#include "glintlab/counting/binomial_laws.glsl"
#include "glintlab/microfacet/ndf.glsl"

// LOD range: cells from 2^-24 (fp32 resolution of uv in [0, 1]) to 2^24 uv units.
const float DELIOT2023_MAX_ABS_LOD = 24.0f;
// Fixed mode: anisotropy ratio clamped to 2^6 = 64 (previous work clamps at 16,
// 000 Fig. 11); beyond it the orientation bins (180 deg / 2^(k+1)) are finer
// than the direction of a fp32 footprint at grazing angles.
const int DELIOT2023_MAX_RATIO_LEVEL = 6;
// Original mode has no clamp; 2^20 only keeps the integer bin arithmetic finite.
const int DELIOT2023_MAX_RATIO_LEVEL_ORIGINAL = 20;
// ln of the largest trial count (e^80 ~ 5.5e34 < FLT_MAX with room for sums).
const float DELIOT2023_MAX_LOG_TRIALS = 80.0f;
// Lattice cell indices wrap with this mask (period 2^20 cells) so that float to
// int conversions stay in range for any uv and LOD.
const int DELIOT2023_LATTICE_MASK = 1048575;
const float DELIOT2023_LATTICE_PERIOD = 1048576.0f;
const float DELIOT2023_LN2 = 0.69314718f;

// DELIOT2023 loops. The hot loops (over the 4 grids, a grid's distinct laws
// and trials, a vertex's open corners) are do-while loops, and work that is
// needed only in some cases sits in a loop whose trip count says so, not
// behind a branch. SIMD back ends that run a block of pixels in lock-step,
// such as llvmpipe, run both sides of every branch for the whole block, and
// leave a loop only after a pass in which no lane is left in it: a for loop
// of n iterations costs n + 1 passes there, a do-while loop n. The results
// are bit for bit those of the plain loops; GPUs branch over code no lane
// runs either way.

// The 4 grids of one lookup: id = (LOD, ratio level k, orientation bin j), and
// each grid's share of the footprint's trials (barycentric, sums to 1).
// Vectors, not arrays: the loops over the 4 grids are too large to be
// unrolled, and Mesa's compiler keeps a local array read at a non-constant
// index in scratch memory (a gather per read), where a vector read so becomes
// selects. Grid i is id (lod[i], ratio_level[i], bin[i]) (deliot2023_grid_id).
struct Deliot2023Grids {
    ivec4 lod;
    ivec4 ratio_level;
    ivec4 bin;
    vec4 weight;
};
ivec3 deliot2023_grid_id(Deliot2023Grids g, int i) {
    return ivec3(g.lod[i], g.ratio_level[i], g.bin[i]);
}
void deliot2023_set_grid(INOUT(Deliot2023Grids) g, int i, int lod, ivec2 ratio_bin) {
    g.lod[i] = lod;
    g.ratio_level[i] = ratio_bin.x;
    g.bin[i] = ratio_bin.y;
}

// §5.1: axes of the footprint ellipse. The pixel's uv Jacobian J = (dx dy)
// maps the unit disk to an ellipse with matrix M = J J^T = [a b; b c]; its
// axis lengths are the square roots of M's eigenvalues. Returns
// (minor length, major length, major-axis angle in [0, pi)).
// Fixed: lambda_min = det(J)^2 / lambda_max, no cancellation; inputs are
// rescaled so the squares neither overflow nor underflow. Original:
// lambda_min = (a + c) / 2 - sqrt(...), which cancels to 0 (or below) for
// elongated footprints (floored at 0 here instead of producing NaN).
vec3 deliot2023_footprint_ellipse(vec2 dx, vec2 dy, bool original_defects) {
    float m = max(max(abs(dx.x), abs(dx.y)), max(abs(dy.x), abs(dy.y)));
    if (!(m > 0.0f)) return vec3(0.0f);
    dx = dx / m;
    dy = dy / m;
    float a = dx.x * dx.x + dy.x * dy.x;
    float b = dx.x * dx.y + dy.x * dy.y;
    float c = dx.y * dx.y + dy.y * dy.y;
    float half_sum = 0.5f * (a + c);
    float half_diff = 0.5f * (a - c);
    float root = sqrt(half_diff * half_diff + b * b);
    float lambda_max = half_sum + root;
    float major = sqrt(lambda_max);
    float minor;
    if (original_defects) {
        minor = sqrt(max(half_sum - root, 0.0f));
    } else {
        minor = abs(dx.x * dy.y - dx.y * dy.x) / major;
    }
    float angle = (b != 0.0f || half_diff != 0.0f) ? 0.5f * atan(2.0f * b, a - c) : 0.0f;
    if (angle < 0.0f) angle += PI;
    if (angle >= PI) angle -= PI;
    return vec3(minor * m, major * m, angle);
}

// Number of orientation bins over 180 deg at ratio level k (ratio 2^k): bin
// width 90 deg / max(2^k, 2), and a single orientation-free grid at k = 0
// (Fig. 6: one more orientation per ratio level).
int deliot2023_orientation_bins(int k) {
    return k == 0 ? 1 : (2 << k);
}

// §5.2 + §6.1: the 4 grids around (LOD l, ratio r, angle) and their weights.
// Ratio-orientation plane (Fig. 6-7): between ratio levels k and k+1 (k >= 1),
// orientation bin b has 2 vertices at level k and 3 at level k+1 (bins halve),
// a pentagon split into 3 triangles; for k = 0 it is one triangle. Along the
// LOD axis each triangle becomes a prism split into 3 tetrahedra. Triangle
// vertices are ordered (lower level first, then by angle) consistently for
// neighbouring cells, so the weights are continuous everywhere.
// LOD and ratio coordinates are linear in cell AREA, as Eq. 10 distributes the
// footprint area P between P_bottom and P_top = 4 P_bottom (Eq. 13): t = (P/P_bottom - 1)/3.
Deliot2023Grids deliot2023_select_grids(float lod, float ratio, float angle,
                                        bool original_defects) {
    int l0;
    float f;
    if (original_defects) {
        l0 = int(lod);  // truncates toward zero: disagrees with fract() for lod < 0
        f = fract(lod);
    } else {
        l0 = int(floor(lod));
        f = lod - floor(lod);
    }
    float t_lod = (exp2(2.0f * f) - 1.0f) / 3.0f;

    int max_level =
        original_defects ? DELIOT2023_MAX_RATIO_LEVEL_ORIGINAL : DELIOT2023_MAX_RATIO_LEVEL;
    float r = clamp(ratio, 1.0f, exp2(float(max_level)));
    int k = min(int(floor(log2(r))), max_level);
    float t_r = k >= max_level ? 0.0f : clamp(r / exp2(float(k)) - 1.0f, 0.0f, 1.0f);

    // Triangle vertices (ratio level, orientation bin) and barycentrics.
    ivec2 va;
    ivec2 vb;
    ivec2 vc;
    float la;
    float lb;
    float lc;
    if (k == 0) {
        float x = angle / (PI / 4.0f);
        int b = min(int(floor(x)), 3);
        float u = clamp(x - float(b), 0.0f, 1.0f);
        va = ivec2(0, 0);
        vb = ivec2(1, b);
        vc = ivec2(1, b + 1);
        la = 1.0f - t_r;
        lb = t_r * (1.0f - u);
        lc = t_r * u;
    } else {
        int bins = deliot2023_orientation_bins(k);
        float x = angle / (PI / float(bins));
        int b = min(int(floor(x)), bins - 1);
        float u = clamp(x - float(b), 0.0f, 1.0f);
        if (u < 0.5f * t_r) {  // lower-left, upper-left, upper-middle
            va = ivec2(k, b);
            vb = ivec2(k + 1, 2 * b);
            vc = ivec2(k + 1, 2 * b + 1);
            la = 1.0f - t_r;
            lb = t_r - 2.0f * u;
            lc = 2.0f * u;
        } else if (u > 1.0f - 0.5f * t_r) {  // lower-right, upper-middle, upper-right
            va = ivec2(k, b + 1);
            vb = ivec2(k + 1, 2 * b + 1);
            vc = ivec2(k + 1, 2 * b + 2);
            la = 1.0f - t_r;
            lb = 2.0f * (1.0f - u);
            lc = t_r - 2.0f * (1.0f - u);
        } else {  // lower-left, lower-right, upper-middle
            va = ivec2(k, b);
            vb = ivec2(k, b + 1);
            vc = ivec2(k + 1, 2 * b + 1);
            la = 1.0f - u - 0.5f * t_r;
            lb = u - 0.5f * t_r;
            lc = t_r;
        }
    }
    // Orientation bins are periodic over 180 deg.
    va.y = va.y % deliot2023_orientation_bins(va.x);
    vb.y = vb.y % deliot2023_orientation_bins(vb.x);
    vc.y = vc.y % deliot2023_orientation_bins(vc.x);

    // Prism (triangle x [l0, l0 + 1]) split into 3 tetrahedra.
    Deliot2023Grids g;
    if (t_lod <= la) {
        deliot2023_set_grid(g, 0, l0, va);
        deliot2023_set_grid(g, 1, l0, vb);
        deliot2023_set_grid(g, 2, l0, vc);
        deliot2023_set_grid(g, 3, l0 + 1, va);
        g.weight[0] = la - t_lod;
        g.weight[1] = lb;
        g.weight[2] = lc;
        g.weight[3] = t_lod;
    } else if (t_lod <= la + lb) {
        deliot2023_set_grid(g, 0, l0, vb);
        deliot2023_set_grid(g, 1, l0, vc);
        deliot2023_set_grid(g, 2, l0 + 1, va);
        deliot2023_set_grid(g, 3, l0 + 1, vb);
        g.weight[0] = la + lb - t_lod;
        g.weight[1] = lc;
        g.weight[2] = la;
        g.weight[3] = t_lod - la;
    } else {
        deliot2023_set_grid(g, 0, l0, vc);
        deliot2023_set_grid(g, 1, l0 + 1, va);
        deliot2023_set_grid(g, 2, l0 + 1, vb);
        deliot2023_set_grid(g, 3, l0 + 1, vc);
        g.weight[0] = 1.0f - t_lod;
        g.weight[1] = la;
        g.weight[2] = lb;
        g.weight[3] = t_lod - la - lb;
    }
    return g;
}

// The two uniforms of one gated-Gaussian evaluation (§6.3) of the angular
// cell `corner` of a vertex whose stream is at `vs`: the first two outputs
// of one pcg3d (Jarzynski & Olano 2020) of (corner, vs), or, when the back
// end defines GLINTLAB_DELIOT2023_NOISE_TEXTURE, a precomputed noise texture
// read through its fetch function `vec2 deliot2023_noise_fetch(uint
// cell_hash)` at hash_cell(corner, vs). 000 leaves the source of these
// numbers open (hash or texture). Why pcg3d: the corners' hashing is the
// largest part of a GPU frame, and hash_cell (two xxHash32 rounds) with two
// pcg_hash rounds costs 28 % of deliot2023's pass on an H200 against 0.3 %
// for pcg3d (docs/BENCHMARKS.md); the uniforms' independence is tested in
// Deliot2023.CornerUniformsAreUniformAndIndependent.
vec2 deliot2023_corner_uniforms(ivec2 corner, uint vs) {
#ifdef GLINTLAB_DELIOT2023_NOISE_TEXTURE
    // The texture holds 4096 pairs: their empirical CDF misses N p by a
    // relative few / sqrt(4096 p) at the small gate probabilities that decide
    // sparse glints (renders were 3.5-5 % dark). Each cell's pair is rotated
    // (Cranley-Patterson) by offsets from its hash: the 20 bits the texel
    // index leaves unused, and the whole hash remixed, so that every uniform
    // is uniform over cells whatever the table holds.
    uint c = hash_cell(corner, vs);
    vec2 offset = vec2(float(c >> 12u), float((c * 0x9E3779B9u) >> 12u)) * (1.0f / 1048576.0f);
    vec2 u = deliot2023_noise_fetch(c) + offset;
    return u - floor(u);
#else
    uvec3 h = pcg3d(uvec3(uint(corner.x), uint(corner.y), vs));
    return vec2(uint_to_unit_float(h.x), uint_to_unit_float(h.y));
#endif
}

// The spatial part of one grid (§6.2), shared with kneiphof2025 (003 §3.3:
// the same grid, without the half-vector dimension under image-based
// lighting): the 3 simplex vertices around uv, as their cell seeds and
// barycentric weights, and ln of the trials a vertex holds before the
// per-cell density jitter.
struct Deliot2023Simplex {
    uvec3 vertex_seed;
    vec3 beta;
    float log_trials;
};

Deliot2023Simplex deliot2023_simplex(ivec3 id, float weight, vec2 uv, float log_density,
                                     uint seed) {
    int l = id.x;
    int k = id.y;
    float phi = float(id.z) * PI / float(deliot2023_orientation_bins(k));
    uint grid_seed = hash_combine(hash_combine(hash_combine(seed, uint(l)), uint(k)), uint(id.z));
    // Eq. 12: uv' = R_phi(S_(1,r)(S_s(uv))): rotate into the grid's frame, then
    // scale the major axis by 1 / (2^k 2^l) and the minor axis by 1 / 2^l.
    float inv_s = exp2(-float(l));
    float inv_r = exp2(-float(k));
    vec2 major_dir = vec2(cos(phi), sin(phi));
    vec2 q =
        vec2(dot(uv, major_dir) * inv_r * inv_s, (uv.y * major_dir.x - uv.x * major_dir.y) * inv_s);
    // §6.2: unit-area triangular lattice with basis (a, 0), (a/2, a sqrt(3)/2),
    // a = sqrt(2/sqrt(3)); g = lattice coordinates, plus a per-grid offset so
    // that vertices of different grids do not line up.
    uint st = grid_seed;
    vec2 g;
    g.y = q.y / 0.93060486f;  // q.y / (a sqrt(3)/2)
    g.x = q.x / 1.07456993f - 0.5f * g.y;
    // Two statements, not vec2(hash_random(st), hash_random(st)): C++ leaves
    // the order of constructor arguments unspecified (GCC: right to left),
    // GLSL evaluates left to right; the CPU and GPU must draw the same offset.
    float offset_x = hash_random(st);
    float offset_y = hash_random(st);
    g = g + vec2(offset_x, offset_y);
    g = mod(g, DELIOT2023_LATTICE_PERIOD);
    vec2 gf = floor(g);
    ivec2 cell = ivec2(gf);
    vec2 fr = clamp(g - gf, 0.0f, 1.0f);
    ivec2 v0;
    ivec2 v1;
    ivec2 v2;
    Deliot2023Simplex s;
    if (fr.x + fr.y < 1.0f) {
        v0 = cell;
        v1 = cell + ivec2(1, 0);
        v2 = cell + ivec2(0, 1);
        s.beta[0] = 1.0f - fr.x - fr.y;
        s.beta[1] = fr.x;
        s.beta[2] = fr.y;
    } else {
        v0 = cell + ivec2(1, 1);
        v1 = cell + ivec2(0, 1);
        v2 = cell + ivec2(1, 0);
        s.beta[0] = fr.x + fr.y - 1.0f;
        s.beta[1] = 1.0f - fr.x;
        s.beta[2] = 1.0f - fr.y;
    }
    s.vertex_seed[0] = hash_cell(v0 & ivec2(DELIOT2023_LATTICE_MASK), grid_seed);
    s.vertex_seed[1] = hash_cell(v1 & ivec2(DELIOT2023_LATTICE_MASK), grid_seed);
    s.vertex_seed[2] = hash_cell(v2 & ivec2(DELIOT2023_LATTICE_MASK), grid_seed);
    // Trials per vertex: each lattice vertex owns one cell of area 2^(2l) 2^k uv
    // units; the grid holds `weight` of the footprint's trials (Eq. 10).
    s.log_trials = log_density + log(weight) + float(2 * l + k) * DELIOT2023_LN2;
    return s;
}

// Trials of one vertex: the per-cell jitter of the log density (std-dev
// density_randomization) draws the first number of the vertex's stream `vs`.
// Without jitter (the default) the quantile is skipped: log_trials + 0 z is
// log_trials for any finite z, so the trials are the same bits, and the
// stream advances as with jitter.
float deliot2023_vertex_trials(float log_trials, float density_randomization, INOUT(uint) vs) {
    float xi = hash_random(vs);
    float jitter =
        density_randomization != 0.0f ? density_randomization * normal_quantile(xi) : 0.0f;
    return exp(clamp(log_trials + jitter, -DELIOT2023_MAX_LOG_TRIALS, DELIOT2023_MAX_LOG_TRIALS));
}

// The half-vector-free draws of one vertex from its stream `vs`: its trials
// N (first number) and the offset of its angular grid (Eq. 14; second and
// third), returned as (N, offset x, offset y); `vs` is left where the
// corners' uniforms start.
vec3 deliot2023_vertex_draws(float log_trials, float density_randomization, INOUT(uint) vs) {
    float N = deliot2023_vertex_trials(log_trials, density_randomization, vs);
    // Three statements: see the lattice offset (argument order).
    float angular_offset_x = hash_random(vs);
    float angular_offset_y = hash_random(vs);
    return vec3(N, angular_offset_x, angular_offset_y);
}

// The gated law of a vertex's N trials of probability p, shared by its 4
// corners (the gate's power, and the conditional law's moments and mean
// correction): in the original HLSL's terms when original_defects.
SingleGatedLaw deliot2023_vertex_law(float N, float p, bool original_defects, bool conditional) {
    SingleGatedLaw law = binomial_single_gated_law_of(N, p, conditional);
    // The original HLSL's gated Gaussian (Eq. 16-18 as shipped) in the same
    // terms: the gate 1 - (1 - p)^N with the naive fp32 power (Eq. 16), also
    // for N < 1, and the Gaussian of the N - 1 other trials (Eq. 17) clamped
    // to [0, N] instead of N - 1, floored after the gate's success (Eq. 18).
    if (original_defects) {
        float rest = max(N - 1.0f, 0.0f);
        law.p_gate = 1.0f - pow_one_minus_naive(p, N);
        law.mean = rest * p;
        law.sd = sqrt(max(rest * p * (1.0f - p), 0.0f));
        law.top = N;
    }
    return law;
}

// deliot2023_vertex_count with the vertex's law given (deliot2023_vertex_law).
float deliot2023_vertex_count_of_law(SingleGatedLaw law, vec2 angular_offset, uint vs, vec2 slope,
                                     bool original_defects) {
    vec2 a = slope + angular_offset;
    a = mod(a, DELIOT2023_LATTICE_PERIOD);
    vec2 af = floor(a);
    ivec2 ac = ivec2(af);
    vec2 at = clamp(a - af, 0.0f, 1.0f);
    // Both laws draw their Gaussian from one normal quantile of the corner's
    // second uniform, so a corner evaluates one quantile, not one per law
    // (SIMD back ends such as llvmpipe run both sides of a choice between
    // two law functions for a block of pixels); the counts are bit
    // for bit those of the laws as written
    // (Deliot2023CornerLaw.OneQuantilePerCornerGivesTheLawsCounts).
    float lo = original_defects ? 0.0f : 1.0f;
    vec4 weight;
    vec4 gate_xi;
    vec4 gauss_xi;
    for (int c = 0; c < 4; ++c) {
        ivec2 corner = ac + ivec2(c & 1, c >> 1);
        weight[c] = ((c & 1) == 1 ? at.x : 1.0f - at.x) * ((c >> 1) == 1 ? at.y : 1.0f - at.y);
        vec2 xi = deliot2023_corner_uniforms(corner & ivec2(DELIOT2023_LATTICE_MASK), vs);
        gate_xi[c] = xi.x;
        gauss_xi[c] = xi.y;
    }
    // The gates first, then a quantile for each open gate only: one pass of
    // a do-while loop per open corner (at least one; see DELIOT2023 loops),
    // so a block of pixels pays for as many quantiles as its lane with the
    // most open corners, not 4 (sparse footprints and the NDF's tails open
    // few). Back ends that branch skip the closed corners' quantiles either
    // way (the CPU: -16 % of a deliot2023 render, CHANGELOG.md).
    int open = (gate_xi.x < law.p_gate ? 1 : 0) | (gate_xi.y < law.p_gate ? 2 : 0) |
               (gate_xi.z < law.p_gate ? 4 : 0) | (gate_xi.w < law.p_gate ? 8 : 0);
    // Summed in corner order, as the counts always were (a closed corner
    // added 0).
    float count = 0.0f;
    do {
        int c = (open & 1) != 0 ? 0 : ((open & 2) != 0 ? 1 : ((open & 4) != 0 ? 2 : 3));
        if (open != 0) {
            float g = clamp(law.mean + law.sd * normal_quantile(gauss_xi[c]), lo, law.top);
            count += weight[c] * (original_defects ? floor(1.0f + g) : g * law.scale);
        }
        open &= open - 1;
    } while (open != 0);
    return count;
}

// The blended count of one vertex (Eq. 14): the angular grid over the
// projected half vector `slope` (units of R), offset per vertex so that
// angular cells do not align across space, its 4 corners' counts from the
// gated law of (N, p) blended bilinearly. `vs`: the vertex's stream after
// deliot2023_vertex_draws.
float deliot2023_vertex_count(float N, vec2 angular_offset, uint vs, vec2 slope, float p,
                              bool original_defects, bool conditional) {
    return deliot2023_vertex_count_of_law(
        deliot2023_vertex_law(N, p, original_defects, conditional), angular_offset, vs, slope,
        original_defects);
}

// Counts of one grid (Eq. 14 per simplex vertex), accumulated into
// acc = (sum of blended counts, sum of blended trials).
vec2 deliot2023_grid_counts(ivec3 id, float weight, vec2 uv, vec2 slope, float p, float log_density,
                            uint seed, float density_randomization, bool original_defects,
                            bool conditional) {
    Deliot2023Simplex s = deliot2023_simplex(id, weight, uv, log_density, seed);
    vec2 acc = vec2(0.0f);
    for (int v = 0; v < 3; ++v) {
        float bv = s.beta[v];
        if (bv <= 0.0f) continue;
        uint vs = s.vertex_seed[v];
        vec3 d = deliot2023_vertex_draws(s.log_trials, density_randomization, vs);
        float count = deliot2023_vertex_count(d.x, vec2(d.y, d.z), vs, slope, p, original_defects,
                                              conditional);
        acc += bv * vec2(count, d.x);
    }
    return acc;
}

// The part of D_P that does not depend on the half vector: the
// footprint's 4 grids and, for each, its 3 simplex vertices' barycentric
// weights, trials, angular offsets and streams. A pixel lit by several
// lights needs it once: the GPU glue keeps it per footprint
// (GLINTLAB_DELIOT2023_PIXEL_CACHE), and each light's counts follow from it,
// the light's p and its slope (deliot2023_counts_of_part). Vertex v of grid
// i is component i of the v-th vector (vectors, not arrays: see
// Deliot2023Grids); a vertex of barycentric weight 0, or of a grid of weight
// 0, holds beta 0 and is skipped, as in deliot2023_grid_counts.
struct Deliot2023PixelPart {
    Deliot2023Grids grids;
    vec4 beta0;
    vec4 beta1;
    vec4 beta2;
    vec4 trials0;
    vec4 trials1;
    vec4 trials2;
    vec4 offset_x0;
    vec4 offset_x1;
    vec4 offset_x2;
    vec4 offset_y0;
    vec4 offset_y1;
    vec4 offset_y2;
    uvec4 stream0;
    uvec4 stream1;
    uvec4 stream2;
};

Deliot2023PixelPart deliot2023_pixel_part(Deliot2023Grids grids, vec2 uv, float log_density,
                                          uint seed, float density_randomization) {
    Deliot2023PixelPart px;
    px.grids = grids;
    px.beta0 = vec4(0.0f);
    px.beta1 = vec4(0.0f);
    px.beta2 = vec4(0.0f);
    px.trials0 = vec4(0.0f);
    px.trials1 = vec4(0.0f);
    px.trials2 = vec4(0.0f);
    px.offset_x0 = vec4(0.0f);
    px.offset_x1 = vec4(0.0f);
    px.offset_x2 = vec4(0.0f);
    px.offset_y0 = vec4(0.0f);
    px.offset_y1 = vec4(0.0f);
    px.offset_y2 = vec4(0.0f);
    px.stream0 = uvec4(0u);
    px.stream1 = uvec4(0u);
    px.stream2 = uvec4(0u);
    // Without density jitter the 3 vertices of a grid hold the same trials:
    // one pass of the loop below draws them for all 3 (see
    // deliot2023_counts_of_part for why a loop and not a branch).
    int distinct_trials = density_randomization != 0.0f ? 3 : 1;
    int i = 0;
    do {  // over the 4 grids (see DELIOT2023 loops)
        if (!(grids.weight[i] > 0.0f)) {
            ++i;
            continue;
        }
        Deliot2023Simplex s = deliot2023_simplex(deliot2023_grid_id(grids, i), grids.weight[i], uv,
                                                 log_density, seed);
        // Each vertex's stream: its trials' number first (deliot2023_vertex_trials),
        // then its angular offset (deliot2023_vertex_draws).
        uint vs0 = s.vertex_seed[0];
        uint vs1 = s.vertex_seed[1];
        uint vs2 = s.vertex_seed[2];
        vec3 trials = vec3(0.0f);
        int v = 0;
        do {
            uint vs = v == 0 ? vs0 : (v == 1 ? vs1 : vs2);
            trials[v] = deliot2023_vertex_trials(s.log_trials, density_randomization, vs);
            ++v;
        } while (v < distinct_trials);
        if (distinct_trials == 1) trials = vec3(trials.x);
        hash_random(vs0);
        hash_random(vs1);
        hash_random(vs2);
        if (s.beta[0] > 0.0f) {
            px.beta0[i] = s.beta[0];
            px.trials0[i] = trials.x;
            px.offset_x0[i] = hash_random(vs0);
            px.offset_y0[i] = hash_random(vs0);
            px.stream0[i] = vs0;
        }
        if (s.beta[1] > 0.0f) {
            px.beta1[i] = s.beta[1];
            px.trials1[i] = trials.y;
            px.offset_x1[i] = hash_random(vs1);
            px.offset_y1[i] = hash_random(vs1);
            px.stream1[i] = vs1;
        }
        if (s.beta[2] > 0.0f) {
            px.beta2[i] = s.beta[2];
            px.trials2[i] = trials.z;
            px.offset_x2[i] = hash_random(vs2);
            px.offset_y2[i] = hash_random(vs2);
            px.stream2[i] = vs2;
        }
        ++i;
    } while (i < 4);
    return px;
}

// The counts of every grid for one half vector, from the pixel's part:
// (sum of blended counts, sum of blended trials), the same operations in the
// same order as deliot2023_grid_counts over the 4 grids.
vec2 deliot2023_counts_of_part(Deliot2023PixelPart px, vec2 slope, float p, bool original_defects,
                               bool conditional) {
    vec2 acc = vec2(0.0f);
    int i = 0;
    do {  // over the 4 grids (see DELIOT2023 loops)
        if (!(px.grids.weight[i] > 0.0f)) {
            ++i;
            continue;
        }
        // A vertex's law depends on its trials and p only. Without density
        // jitter the 3 vertices of a grid hold the same trials (a vertex of
        // barycentric weight 0 holds 0 and is not counted), so one law serves
        // them: 4 laws per pixel instead of 12 (the conditional law's mean
        // correction, with its erf and exp, is most of a law's cost). A loop
        // whose trip count is the number of laws, not a branch (see
        // DELIOT2023 loops above).
        float t0 = px.beta0[i] > 0.0f ? px.trials0[i] : -1.0f;
        float t1 = px.beta1[i] > 0.0f ? px.trials1[i] : t0;
        float t2 = px.beta2[i] > 0.0f ? px.trials2[i] : t0;
        if (t0 < 0.0f) t0 = t1 >= 0.0f ? t1 : t2;
        int laws = (t1 == t0 && t2 == t0) ? 1 : 3;
        SingleGatedLaw law0;
        SingleGatedLaw law1;
        SingleGatedLaw law2;
        int v = 0;
        do {
            float t = v == 0 ? t0 : (v == 1 ? t1 : t2);
            SingleGatedLaw law = deliot2023_vertex_law(t, p, original_defects, conditional);
            if (v == 0) law0 = law;
            if (v == 1) law1 = law;
            if (v == 2) law2 = law;
            ++v;
        } while (v < laws);
        if (laws == 1) {
            law1 = law0;
            law2 = law0;
        }
        vec2 grid = vec2(0.0f);  // one grid's sum first, as deliot2023_grid_counts
        if (px.beta0[i] > 0.0f)
            grid += px.beta0[i] * vec2(deliot2023_vertex_count_of_law(
                                           law0, vec2(px.offset_x0[i], px.offset_y0[i]),
                                           px.stream0[i], slope, original_defects),
                                       px.trials0[i]);
        if (px.beta1[i] > 0.0f)
            grid += px.beta1[i] * vec2(deliot2023_vertex_count_of_law(
                                           law1, vec2(px.offset_x1[i], px.offset_y1[i]),
                                           px.stream1[i], slope, original_defects),
                                       px.trials1[i]);
        if (px.beta2[i] > 0.0f)
            grid += px.beta2[i] * vec2(deliot2023_vertex_count_of_law(
                                           law2, vec2(px.offset_x2[i], px.offset_y2[i]),
                                           px.stream2[i], slope, original_defects),
                                       px.trials2[i]);
        acc += grid;
        ++i;
    } while (i < 4);
    return acc;
}

// The 4 grids of a pixel footprint (§5.1-5.2): ellipse axes, anisotropy
// ratio and LOD, then deliot2023_select_grids. Shared with kneiphof2025.
Deliot2023Grids deliot2023_footprint_grids(Footprint fp, float screen_space_scale,
                                           bool original_defects) {
    vec3 ellipse = deliot2023_footprint_ellipse(fp.duvdx, fp.duvdy, original_defects);
    float major = max(ellipse.y, 1e-30f);
    float minor = max(ellipse.x, major * 1e-30f);
    if (!original_defects) minor = max(minor, major * exp2(-float(DELIOT2023_MAX_RATIO_LEVEL)));
    float ratio = major / minor;
    // LOD = log2(minor * S / 2): with barycentric blending a glint spans two
    // cells, so cells of half the minor width times S give glints S pixels wide.
    float lod = clamp(log2(max(minor * screen_space_scale * 0.5f, 1e-30f)), -DELIOT2023_MAX_ABS_LOD,
                      DELIOT2023_MAX_ABS_LOD);
    return deliot2023_select_grids(lod, ratio, ellipse.z, original_defects);
}

// Early exits of the GPU glue, compiled in where the back end
// defines GLINTLAB_DELIOT2023_EXPECTATION_EXITS (the GPU glues; the CPU
// keeps the plain evaluation, so its renders are unchanged): D_P is replaced
// by the value the counts take but with a probability below fp32's
// resolution, from bounds on the 12 vertices' trials of the 4 grids (the
// density jitter z of deliot2023_vertex_trials is at most
// DELIOT2023_MAX_JITTER_Z in magnitude, normal_quantile clamping its argument
// to [2^-24, 1 - 2^-24]):
//  (a) sum of the vertices' N p < 2^-24: every gate probability min(N p, .)
//      is below the 2^-24 resolution of the gate's uniform, so the counts are
//      all 0 except with probability <= 48 x 2^-24 ~ 3e-6 per pixel: D_P = 0,
//      as the CPU draws it. (It once returned the mean D(h): at densities
//      below one facet per unit uv area, where this exit covers the whole
//      highlight, the GPU drew a smooth highlight where the CPU, drawing the
//      counts, had black with at most a rare glint.)
//  (b) every vertex's N p > 2^48: every gate passes (P(>=1) = 1 in fp32) and
//      each count is N p within 5.3 sqrt(N p (1 - p)) / (N p) < 3.2e-7
//      relative, so D_P = D(n) / R x count / trials is D(h) to a few ulps.
// Whole blocks of pixels that exit skip the 48 binomials: GPUs branch over
// code no lane runs; llvmpipe runs the straight-line code of both sides of a
// branch, but leaves a loop after one masked pass when no lane is in it, and
// the binomials sit in the loop over the 4 grids.
const float DELIOT2023_MAX_JITTER_Z = 5.3f;  // normal_quantile(1 - 2^-24) = 5.29
// (bound above of the sum of the vertices' trials, bound below of one
// vertex's trials): the half-vector-free part of the exit test.
vec2 deliot2023_trial_bounds(Deliot2023Grids grids, float log_density,
                             float density_randomization) {
    float jitter = abs(density_randomization) * DELIOT2023_MAX_JITTER_Z;
    float most = 0.0f;
    float least = 3.4e38f;
    int i = 0;
    do {  // over the 4 grids (see DELIOT2023 loops)
        if (!(grids.weight[i] > 0.0f)) {
            ++i;
            continue;
        }
        float lt = log_density + log(grids.weight[i]) +
                   float(2 * deliot2023_grid_id(grids, i).x + deliot2023_grid_id(grids, i).y) *
                       DELIOT2023_LN2;
        most +=
            3.0f * exp(clamp(lt + jitter, -DELIOT2023_MAX_LOG_TRIALS, DELIOT2023_MAX_LOG_TRIALS));
        least = min(least,
                    exp(clamp(lt - jitter, -DELIOT2023_MAX_LOG_TRIALS, DELIOT2023_MAX_LOG_TRIALS)));
        ++i;
    } while (i < 4);
    return vec2(most, least);
}
// 0: no exit; 1: exit (a), D_P = 0; 2: exit (b), D_P = D(h).
const int DELIOT2023_NO_EXIT = 0;
const int DELIOT2023_EXIT_ZERO = 1;
const int DELIOT2023_EXIT_MEAN = 2;
int deliot2023_bounds_exit(vec2 bounds, float p) {
    if (bounds.x * p < 5.9604645e-8f) return DELIOT2023_EXIT_ZERO;  // 2^-24
    if (bounds.y * p > 2.8147498e14f) return DELIOT2023_EXIT_MEAN;  // 2^48
    return DELIOT2023_NO_EXIT;
}
int deliot2023_expectation_exit(Deliot2023Grids grids, float p, float log_density,
                                float density_randomization) {
    return deliot2023_bounds_exit(
        deliot2023_trial_bounds(grids, log_density, density_randomization), p);
}
// D_P at an exit.
float deliot2023_exit_value(int exit_kind, float d_h) {
    return exit_kind == DELIOT2023_EXIT_MEAN ? d_h : 0.0f;
}

// The GPU glues' cache of the half-vector-free part of D_P
// (GLINTLAB_DELIOT2023_PIXEL_CACHE; never on the CPU, whose BxDF has no
// per-pixel state). A fragment of the forward pass evaluates D_P for one
// footprint under every light, so the footprint's grids and the exit test's
// trial bounds are built by the first light, and the 12 vertices
// (deliot2023_pixel_part) by the first light that does not take an
// expectation exit; the other lights reuse them. The key is everything
// they depend on: the footprint, the log density, jitter, seed,
// screen-space scale and defects flag (uniform per draw in the glues).
#ifdef GLINTLAB_DELIOT2023_PIXEL_CACHE
Deliot2023PixelPart g_deliot2023_pixel_part;  // grids, then vertices
vec2 g_deliot2023_trial_bounds;
Footprint g_deliot2023_cache_fp;
vec4 g_deliot2023_cache_params;
uint g_deliot2023_cache_seed;
bool g_deliot2023_cache_valid = false;
bool g_deliot2023_cache_vertices_valid = false;
void deliot2023_cache_footprint(Footprint fp, float log_density, uint seed,
                                float screen_space_scale, float density_randomization,
                                bool original_defects) {
    vec4 params = vec4(log_density, density_randomization, screen_space_scale,
                       original_defects ? 1.0f : 0.0f);
    if (g_deliot2023_cache_valid && fp == g_deliot2023_cache_fp &&
        params == g_deliot2023_cache_params && seed == g_deliot2023_cache_seed)
        return;
    g_deliot2023_pixel_part.grids =
        deliot2023_footprint_grids(fp, screen_space_scale, original_defects);
    g_deliot2023_trial_bounds =
        deliot2023_trial_bounds(g_deliot2023_pixel_part.grids, log_density, density_randomization);
    g_deliot2023_cache_fp = fp;
    g_deliot2023_cache_params = params;
    g_deliot2023_cache_seed = seed;
    g_deliot2023_cache_valid = true;
    g_deliot2023_cache_vertices_valid = false;
}
// After deliot2023_cache_footprint for the same arguments.
Deliot2023PixelPart deliot2023_cached_pixel_part(vec2 uv, float log_density, uint seed,
                                                 float density_randomization) {
    if (!g_deliot2023_cache_vertices_valid) {
        g_deliot2023_pixel_part = deliot2023_pixel_part(g_deliot2023_pixel_part.grids, uv,
                                                        log_density, seed, density_randomization);
        g_deliot2023_cache_vertices_valid = true;
    }
    return g_deliot2023_pixel_part;
}
#endif

// D_P(h) of Eq. 3-4 for a local half vector h (z = normal) and a uv footprint.
// ndf, alpha_x, alpha_y, rho: target NDF D (rho: its slopes' correlation, a
// footprint's sheared lobe; the angular grid stays on the frame's axes);
// log_density: ln(facets per unit uv area); seed: the material's seed.
// microfacet_roughness = R in (0, 1]; screen_space_scale: minimum glint size
// in pixels.
float deliot2023_ndf(vec3 h, Footprint fp, int ndf, float alpha_x, float alpha_y, float rho,
                     float log_density, uint seed, float microfacet_roughness,
                     float screen_space_scale, float density_randomization, bool original_defects,
                     bool conditional) {
    float d_h = D_Microfacet_correlated(ndf, h, alpha_x, alpha_y, rho);
    if (!(d_h > 0.0f)) return 0.0f;
    // max of D
    float d_n = D_Microfacet_correlated(ndf, vec3(0.0f, 0.0f, 1.0f), alpha_x, alpha_y, rho);
    float R = microfacet_roughness;
    float p = clamp(R * d_h / d_n, 0.0f, 1.0f);  // Eq. 4 success probability

    // The half-vector-free part (grids, exit bounds, vertices): once per
    // footprint where the back end keeps it (GLINTLAB_DELIOT2023_PIXEL_CACHE,
    // the GPU glues), else here.
#ifdef GLINTLAB_DELIOT2023_PIXEL_CACHE
    deliot2023_cache_footprint(fp, log_density, seed, screen_space_scale, density_randomization,
                               original_defects);
#ifdef GLINTLAB_DELIOT2023_EXPECTATION_EXITS
    int exit_kind = original_defects ? DELIOT2023_NO_EXIT
                                     : deliot2023_bounds_exit(g_deliot2023_trial_bounds, p);
    if (exit_kind != DELIOT2023_NO_EXIT) return deliot2023_exit_value(exit_kind, d_h);
#endif
    Deliot2023PixelPart px =
        deliot2023_cached_pixel_part(fp.uv, log_density, seed, density_randomization);
#else
    Deliot2023Grids grids = deliot2023_footprint_grids(fp, screen_space_scale, original_defects);
#ifdef GLINTLAB_DELIOT2023_EXPECTATION_EXITS
    int exit_kind = original_defects
                        ? DELIOT2023_NO_EXIT
                        : deliot2023_expectation_exit(grids, p, log_density, density_randomization);
    if (exit_kind != DELIOT2023_NO_EXIT) return deliot2023_exit_value(exit_kind, d_h);
#endif
    Deliot2023PixelPart px =
        deliot2023_pixel_part(grids, fp.uv, log_density, seed, density_randomization);
#endif
    vec2 acc = deliot2023_counts_of_part(px, vec2(h.x, h.y) / R, p, original_defects, conditional);
    // Eq. 4 with the footprint's trial count: D(n)/R x count/N, E = D(h) (Eq. 5-6).
    // (count/trials first: both reach 1e35 at the largest densities.)
    return acc.y > 0.0f ? d_n / R * (acc.x / acc.y) : d_h;
}

// Stochastic grid selection (the GPU option "stochastic_grid"; a
// separate option for renderers with temporal accumulation, never the
// model's default): of the 4 grids of the footprint, ONE is evaluated, grid
// i with probability weight_i, drawn with the pixel's uniform u in [0, 1),
// with the trials it holds in the blend (weight_i of the footprint's), so
// every vertex draws its counts from the same law as in the blend (the
// gated law's small-N bias included; with all the trials in the chosen grid
// the image mean was 4 % lower on the test's plane). Each grid's D(n) / R x
// count / trials has mean D(h) (Eq. 5-6), so the mixture has the blend's
// mean: averaged over frames (a new u per frame) it converges to the same
// expectation, at a quarter of the binomials per frame. Single frames are
// noisier (one grid's counts over a share of the trials).
float deliot2023_ndf_stochastic(vec3 h, Footprint fp, int ndf, float alpha_x, float alpha_y,
                                float rho, float log_density, uint seed,
                                float microfacet_roughness, float screen_space_scale,
                                float density_randomization, bool conditional, float u) {
    float d_h = D_Microfacet_correlated(ndf, h, alpha_x, alpha_y, rho);
    if (!(d_h > 0.0f)) return 0.0f;
    float d_n = D_Microfacet_correlated(ndf, vec3(0.0f, 0.0f, 1.0f), alpha_x, alpha_y, rho);
    float R = microfacet_roughness;
    float p = clamp(R * d_h / d_n, 0.0f, 1.0f);
    Deliot2023Grids grids = deliot2023_footprint_grids(fp, screen_space_scale, false);
#ifdef GLINTLAB_DELIOT2023_EXPECTATION_EXITS
    int exit_kind = deliot2023_expectation_exit(grids, p, log_density, density_randomization);
    if (exit_kind != DELIOT2023_NO_EXIT) return deliot2023_exit_value(exit_kind, d_h);
#endif
    // Inverse CDF over the weights; rounding that leaves u above their sum
    // picks the last grid of positive weight.
    ivec3 id = deliot2023_grid_id(grids, 0);
    float weight = grids.weight[0];
    float below = 0.0f;
    bool found = false;
    for (int i = 0; i < 4; ++i) {
        if (grids.weight[i] <= 0.0f) continue;
        if (!found) {
            id = deliot2023_grid_id(grids, i);
            weight = grids.weight[i];
        }
        below += grids.weight[i];
        if (u < below) found = true;
    }
    vec2 acc = deliot2023_grid_counts(id, weight, fp.uv, vec2(h.x, h.y) / R, p, log_density, seed,
                                      density_randomization, false, conditional);
    return acc.y > 0.0f ? d_n / R * (acc.x / acc.y) : d_h;
}

#endif
