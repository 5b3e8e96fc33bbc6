// chermain2020 (Chermain et al. 2020, 004): a P-SDF built from a dictionary of multiscale
// marginal slope distributions over a MIP hierarchy of surface cells.
//   Eq. 5-7   separable, even, multiscale SDF per cell: P_i(x, l) P_j(y, l)
//   Eq. 8     coherent cell index s0 = floor(s / 2^l) 2^l (seeds the cell)
//   Eq. 9-11  random rotation and anisotropic roughness scaling
//   Eq. 12-13 Gaussian-weighted sum over the footprint's cells at the two
//             LODs around l_P, then slope → normal (Algorithms 1-3)
// With Chermain et al. 2021 ("Real-Time Geometric Glint Anti-Aliasing with
// Normal Map Filtering", I3D 2021): the slope correlation of their Eq. 18
// and their geometric glint anti-aliasing (§4, Chermain2020Filter below).
// The dictionary (dictionary.h) is reached through the fetch function
// `float chermain2020_dict_fetch(int row, int bin)`, row = dist * n_levels +
// level: the C++ back end defines it over the in-memory table before
// including this file, GLSL reads a texture bound by the GPU back end.
#ifndef GLINTLAB_GLINTS_CHERMAIN2020_GLSL
#define GLINTLAB_GLINTS_CHERMAIN2020_GLSL

#include "glintlab/core/constants.glsl"
#include "glintlab/core/footprint.glsl"
#include "glintlab/core/hash.glsl"
#include "glintlab/counting/normal_quantile.glsl"

#ifndef GLINTLAB_CPP
#ifdef GLINTLAB_CHERMAIN2020_DICT_PAIRS
// RG32F texture, width table_size, height n_dists * n_levels: texel `bin`
// holds the samples bin and bin + 1 of its row (0 past the row's end), so the
// linear interpolation of chermain2020_marginal reads one texel instead of
// two (the dictionary fetch is a large share of a cell's time on llvmpipe:
// docs/BENCHMARKS.md); the same values, so the same results. Set by the
// forward pass's glue (chermain2020_gpu.glsl).
uniform sampler2D chermain2020_dictionary;
float chermain2020_dict_fetch(int row, int bin) {
    return texelFetch(chermain2020_dictionary, ivec2(bin, row), 0).r;
}
vec2 chermain2020_dict_fetch_pair(int row, int bin, int table_size) {
    return texelFetch(chermain2020_dictionary, ivec2(bin, row), 0).rg;
}
#else
// R32F texture, width table_size, height n_dists * n_levels.
uniform sampler2D chermain2020_dictionary;
float chermain2020_dict_fetch(int row, int bin) {
    return texelFetch(chermain2020_dictionary, ivec2(bin, row), 0).r;
}
#endif
#endif

// Geometric glint anti-aliasing reads the table with its running integral
// (chermain2020_marginal_box): the C++ back end, and the GPU passes that
// know the half vector's sweep over the pixel (GLINTLAB_GLINT_VIEW_DIFFERENTIALS:
// the forward pass and `glintlab export`).
#ifdef GLINTLAB_CPP
#define GLINTLAB_CHERMAIN2020_FILTERED 1
#else
#ifdef GLINTLAB_GLINT_VIEW_DIFFERENTIALS
#define GLINTLAB_CHERMAIN2020_FILTERED 1
// RGB32F texture of the dictionary's shape: texel `bin` of a row holds the
// samples bin and bin + 1 and the row's integral from 0 to the sample bin
// (dictionary.h chermain2020_dictionary_filter_texels).
#ifdef GLINTLAB_CHERMAIN2020_ONE_TABLE
// `glintlab export`: chermain2020_dictionary is this table (its .rg are the
// pairs): one sampler and one resource, whether the filter is on or not.
vec3 chermain2020_dict_fetch_filter(int row, int bin) {
    return texelFetch(chermain2020_dictionary, ivec2(bin, row), 0).rgb;
}
#else
// The forward pass binds it only where the filter is on (chermain2020_gpu.cpp).
uniform sampler2D chermain2020_dictionary_filter;
vec3 chermain2020_dict_fetch_filter(int row, int bin) {
    return texelFetch(chermain2020_dictionary_filter, ivec2(bin, row), 0).rgb;
}
#endif
#endif
#endif

#ifndef GLINTLAB_CHERMAIN2020_DICT_PAIRS
// The samples bin and bin + 1 of a row, 0 past the row's end (the C++ back
// end and single-sample textures).
vec2 chermain2020_dict_fetch_pair(int row, int bin, int table_size) {
    float a = chermain2020_dict_fetch(row, bin);
    float b = bin + 1 < table_size ? chermain2020_dict_fetch(row, bin + 1) : 0.0f;
    return vec2(a, b);
}
#endif

// The dictionary's shape (DictionaryParams of the table behind the fetch).
struct Chermain2020Dict {
    int n_levels;
    int n_dists;
    int table_size;
    float alpha_dict;
    float slope_max;  // the tables cover |x| in [0, slope_max)
};

// The user colour table of coloured glints (004 §7.1 "2 CV", Alg. 3 lines
// 11-12, 19): each cell multiplies its SDF by table[floor(count * U_c)].
// count = 0 means no table (white, the scalar model).
#define CHERMAIN2020_MAX_COLOURS 8
struct Chermain2020Colours {
    int count;
    vec3 table[CHERMAIN2020_MAX_COLOURS];
};

// Chermain et al. 2021's geometric glint anti-aliasing (GGAA, their §4): a
// cell's marginals are filtered over the slopes the half vector sweeps
// across the pixel, so a glint that a pixel's centre misses but its area
// holds is not lost, and one does not pop as the view moves by less than a
// pixel. Their kernel is the hardware's mip-mapped lookup of the 1-D
// marginal at the derivative of the slope transformed into the cell's frame
// (textureGrad); here the same width, kernel × max(|∂x'/∂x|, |∂x'/∂y|) per
// axis of the cell's frame, is an exact box over the piecewise-linear
// marginal (chermain2020_marginal_box), the same on every back end.
struct Chermain2020Filter {
    vec2 slope_dx;  // the half vector's slope change per pixel step in x (local frame)
    vec2 slope_dy;  // ... in y
    float kernel;   // their KernelSize; 0: unfiltered (004)
};

Chermain2020Filter chermain2020_unfiltered() {
    Chermain2020Filter f;
    f.slope_dx = vec2(0.0f);
    f.slope_dy = vec2(0.0f);
    f.kernel = 0.0f;
    return f;
}

// The random choices of one cell of the hierarchy (Algorithm 3).
struct Chermain2020Cell {
    bool kept;       // kept by the relative area test (line 4)
    int dist_level;  // l_dist in [0, n_levels]; n_levels means the analytic target (line 10)
    int dist_x;      // marginal i for x (line 18)
    int dist_y;      // marginal j for y
    float theta;     // rotation angle (Eq. 9, line 14)
    float colour_u;  // U_c of the colour table (line 11)
};

// The dictionary level l_dist of a cell of hierarchy level `level`, from
// its density-randomisation uniform u_zeta (Algorithm 3 lines 5-9).
int chermain2020_dist_level(int level, Chermain2020Dict d, float log_density,
                            float density_randomization, float u_zeta) {
    // Lines 5-6: n = 4^l / 4^(nLevels-1) rho facets in the cell, l_dist = log(n) / (2 log 2).
    float l_dist = 0.5f * (log_density * 1.44269504f + 2.0f * float(level) - 2.0f * float(d.n_levels - 1));
    // Line 8: density randomisation, l_dist ~ N(l_dist, zeta^2). The uniform
    // is drawn in any case (the stream stays the same); without randomisation
    // the quantile is not evaluated (it is finite, so zeta z would add 0).
    if (density_randomization != 0.0f) l_dist += density_randomization * normal_quantile(u_zeta);
    // Line 9: round (half up, identical in GLSL and C++) and clamp.
    return int(clamp(floor(l_dist + 0.5f), 0.0f, float(d.n_levels)));
}

// Cell at integer coordinates `cell` of hierarchy level `level`: seeded by
// its coherent index (Eq. 8) only, so the parent at level + 1 draws the same
// numbers as one of its four children (Fig. 7) and keeps its marginals and
// rotation, with one more dictionary level (four times the facets).
Chermain2020Cell chermain2020_cell(ivec2 cell, int level, Chermain2020Dict d, float log_density,
                                   float relative_area, float density_randomization, uint seed) {
    uint sx = uint(cell.x) << uint(level);  // Eq. 8: s0 = floor(s / 2^l) 2^l
    uint sy = uint(cell.y) << uint(level);
    uint state = hash_combine(hash_combine(seed, sx), sy);
    Chermain2020Cell c;
    c.kept = hash_random(state) < relative_area;  // line 3-4: discard if U_beta > beta
    c.dist_level = chermain2020_dist_level(level, d, log_density, density_randomization,
                                           hash_random(state));
    c.colour_u = hash_random(state);
    c.theta = TWO_PI * hash_random(state);
    c.dist_x = min(int(float(d.n_dists) * hash_random(state)), d.n_dists - 1);
    c.dist_y = min(int(float(d.n_dists) * hash_random(state)), d.n_dists - 1);
    return c;
}

// P_i(x, l): even, linear between the table samples, zero from slope_max on.
float chermain2020_marginal(Chermain2020Dict d, int dist, int level, float x) {
    float t = abs(x) / d.slope_max * float(d.table_size);
    if (t >= float(d.table_size)) return 0.0f;
    int k = int(t);
    vec2 ab = chermain2020_dict_fetch_pair(dist * d.n_levels + level, k, d.table_size);
    return mix(ab.x, ab.y, t - float(k));
}

#ifdef GLINTLAB_CHERMAIN2020_FILTERED
// C(x) = ∫_0^x P_i(t, l) dt for x ≥ 0, exact for the piecewise-linear
// marginal (constant from slope_max on).
float chermain2020_cumulative(Chermain2020Dict d, int row, float x) {
    float step = d.slope_max / float(d.table_size);
    float t = min(x, d.slope_max) / step;
    int k = min(int(t), d.table_size - 1);
    float f = t - float(k);
    vec3 c = chermain2020_dict_fetch_filter(row, k);
    return c.z + step * f * (c.x + 0.5f * (c.y - c.x) * f);
}
#endif

// P_i(x, l) averaged over the box [a, b] = [x − w/2, x + w/2]: (C(b) − C(a))
// / w with C extended as an odd function (P is even). A box inside one
// linear piece of P (between two samples, on one side of 0) averages to
// P(x) exactly: that point value is read instead, one fetch rather than
// two (most boxes, where the sweep is narrower than a table step). So is a
// box narrower than a hundredth of a step across a sample (the box's limit;
// C(b) − C(a) would lose its precision there).
float chermain2020_marginal_box(Chermain2020Dict d, int dist, int level, float x, float w) {
#ifdef GLINTLAB_CHERMAIN2020_FILTERED
    float a = x - 0.5f * w;
    float b = x + 0.5f * w;
    float per_step = float(d.table_size) / d.slope_max;
    bool one_piece =
        (a >= 0.0f || b <= 0.0f) && floor(abs(a) * per_step) == floor(abs(b) * per_step);
    if (w * per_step > 0.01f && !one_piece) {
        int row = dist * d.n_levels + level;
        float ca = sign(a) * chermain2020_cumulative(d, row, abs(a));
        float cb = sign(b) * chermain2020_cumulative(d, row, abs(b));
        return max((cb - ca) / w, 0.0f);
    }
#endif
    return chermain2020_marginal(d, dist, level, x);
}

// The anisotropic Beckmann SDF the hierarchy converges to (004 §4.3).
// With a slope correlation rho (Chermain et al. 2021, their Eq. 17's
// non-axis-aligned Beckmann in our α = √2 σ): the bivariate Gaussian of
// correlation rho; rho = 0 is 004's target, the same operations.
float chermain2020_target_p22(vec2 slope, float alpha_x, float alpha_y, float rho) {
    float x = slope.x / alpha_x;
    float y = slope.y / alpha_y;
    if (rho == 0.0f) return exp(-(x * x + y * y)) / (PI * alpha_x * alpha_y);
    float one_minus_rho2 = 1.0f - rho * rho;
    return exp(-(x * x - 2.0f * rho * x * y + y * y) / one_minus_rho2) /
           (PI * alpha_x * alpha_y * sqrt(one_minus_rho2));
}

// S^-1 s in the dictionary's scale (Eq. 9-11's scale), or with a slope
// correlation rho Chermain et al. 2021's Eq. 18: the upper-triangular
// M^-1 = alpha_dict [[1/(alpha_x c), -rho/(alpha_y c)], [0, 1/alpha_y]],
// c = sqrt(1 - rho^2), which maps the correlated Gaussian of
// chermain2020_target_p22 onto the dictionary's isotropic one.
vec2 chermain2020_unscaled_slope(vec2 slope, float alpha_dict, float alpha_x, float alpha_y,
                                 float rho) {
    if (rho == 0.0f) return vec2(slope.x * alpha_dict / alpha_x, slope.y * alpha_dict / alpha_y);
    float c = sqrt(1.0f - rho * rho);
    return vec2((slope.x / alpha_x - rho * slope.y / alpha_y) * alpha_dict / c,
                slope.y * alpha_dict / alpha_y);
}

// |det M^-1|: the Jacobian of the slope transform.
float chermain2020_unscaled_jacobian(float alpha_dict, float alpha_x, float alpha_y, float rho) {
    float jac = alpha_dict * alpha_dict / (alpha_x * alpha_y);
    if (rho == 0.0f) return jac;
    return jac / sqrt(1.0f - rho * rho);
}

// Slope-space coordinates of `slope` in the dictionary frame of cell c:
// s' = R^-1 S^-1 s (Eq. 9-11, scale undone first, then the rotation; see
// docs/MODELS.md: this order keeps anisotropic alpha converging to the
// anisotropic target, the printed S^-1 R^-1 only does for alpha_x = alpha_y).
vec2 chermain2020_dict_slope(Chermain2020Cell c, vec2 slope, Chermain2020Dict d, float alpha_x,
                             float alpha_y, float rho) {
    vec2 q = chermain2020_unscaled_slope(slope, d.alpha_dict, alpha_x, alpha_y, rho);
    float cs = cos(c.theta);
    float sn = sin(c.theta);
    return vec2(cs * q.x + sn * q.y, -sn * q.x + cs * q.y);
}

// P^22_theta,alpha(slope, l, s0) of one cell (Eq. 11, Algorithm 3).
float chermain2020_cell_p22(Chermain2020Cell c, vec2 slope, Chermain2020Dict d, float alpha_x,
                            float alpha_y, float rho) {
    if (!c.kept) return 0.0f;
    if (c.dist_level >= d.n_levels) return chermain2020_target_p22(slope, alpha_x, alpha_y, rho);
    vec2 q = chermain2020_dict_slope(c, slope, d, alpha_x, alpha_y, rho);
    float jac = chermain2020_unscaled_jacobian(d.alpha_dict, alpha_x, alpha_y, rho);
    return chermain2020_marginal(d, c.dist_x, c.dist_level, q.x) *
           chermain2020_marginal(d, c.dist_y, c.dist_level, q.y) * jac;
}

// The clamped footprint ellipse in uv: (major, minor, angle of the major
// axis). Semi-axes are the square roots of the eigenvalues of
// J J^T, J = [duvdx duvdy]; the minor axis is widened to major / gamma
// (Algorithm 1 line 4: eccentricity clamp).
vec3 chermain2020_footprint_ellipse(vec2 duvdx, vec2 duvdy, float max_anisotropy) {
    float A = duvdx.x * duvdx.x + duvdy.x * duvdy.x;
    float B = duvdx.x * duvdx.y + duvdy.x * duvdy.y;
    float C = duvdx.y * duvdx.y + duvdy.y * duvdy.y;
    float mid = 0.5f * (A + C);
    float rad = sqrt(0.25f * (A - C) * (A - C) + B * B);
    float major = sqrt(max(mid + rad, 0.0f));
    float minor = sqrt(max(mid - rad, 0.0f));
    major = max(major, 1e-20f);
    minor = max(minor, major / max_anisotropy);
    float angle = 0.5f * atan(2.0f * B, A - C);
    return vec3(major, minor, angle);
}

// Colour C of cell c (Alg. 3 lines 11-12).
vec3 chermain2020_colour(float colour_u, Chermain2020Colours colours) {
    if (colours.count <= 0) return vec3(1.0f);
    int k = min(int(float(colours.count) * colour_u), colours.count - 1);
    return colours.table[k];
}
vec3 chermain2020_cell_colour(Chermain2020Cell c, Chermain2020Colours colours) {
    return chermain2020_colour(c.colour_u, colours);
}

// What every cell of one lookup shares (hoisted out of the cell loop of
// chermain2020_level_p22 with the expressions of chermain2020_cell_p22 and
// chermain2020_dict_slope, so the values are the same).
struct Chermain2020Lookup {
    vec2 q;            // S^-1 slope in the dictionary's scale, before the cell's rotation
    float jac;         // Jacobian of S_alpha
    float target_p22;  // the analytic target of cells past the last level (Alg. 3 line 10)
    // GGAA: q's change per pixel step (the same linear map of the slope's)
    // and the kernel; kernel 0 reads the marginals unfiltered.
    vec2 dq_dx;
    vec2 dq_dy;
    float kernel;
    // The rotation R^-1 keeps |q|; a cell's SDF is non-zero only where both
    // rotated coordinates lie within slope_max (plus half the widest box a
    // cell can draw), i.e. |q|^2 < 2 reach^2 at least. Outside (with 0.1 %
    // margin against rounding of the rotation) every dictionary cell's SDF
    // is 0 and its rotation and fetches are skipped.
    bool in_support;
};
Chermain2020Lookup chermain2020_lookup(vec2 slope, Chermain2020Dict d, float alpha_x, float alpha_y,
                                       float rho, Chermain2020Filter ggaa) {
    Chermain2020Lookup k;
    k.q = chermain2020_unscaled_slope(slope, d.alpha_dict, alpha_x, alpha_y, rho);
    k.jac = chermain2020_unscaled_jacobian(d.alpha_dict, alpha_x, alpha_y, rho);
    k.target_p22 = chermain2020_target_p22(slope, alpha_x, alpha_y, rho);
    k.kernel = ggaa.kernel;
    k.dq_dx = vec2(0.0f);
    k.dq_dy = vec2(0.0f);
    float reach = d.slope_max;
    if (ggaa.kernel > 0.0f) {
        k.dq_dx = chermain2020_unscaled_slope(ggaa.slope_dx, d.alpha_dict, alpha_x, alpha_y, rho);
        k.dq_dy = chermain2020_unscaled_slope(ggaa.slope_dy, d.alpha_dict, alpha_x, alpha_y, rho);
        // A rotated component is at most the vector's length.
        reach += 0.5f * ggaa.kernel * max(length(k.dq_dx), length(k.dq_dy));
        if (isnan(reach) || isinf(reach)) {  // no finite sweep: unfiltered
            k.kernel = 0.0f;
            reach = d.slope_max;
        }
    }
    k.in_support = dot(k.q, k.q) < 2.002f * reach * reach;
    return k;
}

// One cell's (P^22, U_c) in the cell loop: chermain2020_cell followed by
// chermain2020_cell_p22, drawing the same stream in the same order, but
// evaluated lazily: a discarded cell stops after its first
// number, a cell outside the dictionary's support before its rotation, and
// the second marginal is not fetched where the first is 0. The same
// operations on the same values, so the sums are those of the eager form
// bit for bit; only the work on cells that contribute 0 is skipped.
vec2 chermain2020_cell_sdf(ivec2 cell, int level, Chermain2020Dict d, float log_density,
                           float relative_area, float density_randomization, uint seed,
                           Chermain2020Lookup k) {
    uint sx = uint(cell.x) << uint(level);  // Eq. 8
    uint sy = uint(cell.y) << uint(level);
    uint state = hash_combine(hash_combine(seed, sx), sy);
    if (!(hash_random(state) < relative_area)) return vec2(0.0f);  // line 3-4
    int dist_level = chermain2020_dist_level(level, d, log_density, density_randomization,
                                             hash_random(state));
    float colour_u = hash_random(state);
    if (dist_level >= d.n_levels) return vec2(k.target_p22, colour_u);
    if (!k.in_support) return vec2(0.0f);
    float theta = TWO_PI * hash_random(state);
    int dist_x = min(int(float(d.n_dists) * hash_random(state)), d.n_dists - 1);
    float cs = cos(theta);
    float sn = sin(theta);
    vec2 width = vec2(0.0f);
    if (k.kernel > 0.0f) {  // GGAA: the sweep in the cell's frame, R^-1 dq
        vec2 rx = vec2(cs * k.dq_dx.x + sn * k.dq_dx.y, -sn * k.dq_dx.x + cs * k.dq_dx.y);
        vec2 ry = vec2(cs * k.dq_dy.x + sn * k.dq_dy.y, -sn * k.dq_dy.x + cs * k.dq_dy.y);
        width = k.kernel * max(abs(rx), abs(ry));
    }
    float mx = chermain2020_marginal_box(d, dist_x, dist_level, cs * k.q.x + sn * k.q.y, width.x);
    if (mx == 0.0f) return vec2(0.0f);
    int dist_y = min(int(float(d.n_dists) * hash_random(state)), d.n_dists - 1);
    float my = chermain2020_marginal_box(d, dist_y, dist_level, -sn * k.q.x + cs * k.q.y, width.y);
    return vec2(mx * my * k.jac, colour_u);
}

// The footprint ellipse of one level in cell units (Algorithm 2's walk).
struct Chermain2020Ellipse {
    vec2 centre;
    float ca, sa;        // cos and sin of the major axis' angle
    float major, minor;  // semi-axes
    // The same ellipse as a quadratic form: q2 px^2 + q1 px py + q0 py^2 < 1
    // for the offset p from the centre.
    float q2, q1, q0;
    int x0, x1;  // the bounding box's columns
};

// r^2 of the centre of cell (x, y) in the ellipse: the cell is in the
// footprint where r^2 < 1 (Algorithm 2). The one expression of the walk
// below, so every test of a cell gives the same answer.
float chermain2020_cell_r2(Chermain2020Ellipse e, int x, int y) {
    vec2 p = vec2(float(x) + 0.5f, float(y) + 0.5f) - e.centre;
    float a = (p.x * e.ca + p.y * e.sa) / e.major;
    float b = (-p.x * e.sa + p.y * e.ca) / e.minor;
    return a * a + b * b;
}

// [first, last] column of row y whose cell centres can be in the ellipse:
// the row's roots, an end moved out by one cell where the loop's own r^2
// test puts the next cell inside (rounding of the roots); non-finite roots
// or roots outside the box keep the box's columns.
ivec2 chermain2020_row_range(Chermain2020Ellipse e, int y) {
    float py = float(y) + 0.5f - e.centre.y;
    float half_b = 0.5f * e.q1 * py;
    float disc = sqrt(max(half_b * half_b - e.q2 * (e.q0 * py * py - 1.0f), 0.0f));
    float lo = e.centre.x + (-half_b - disc) / e.q2 - 0.5f;
    float hi = e.centre.x + (-half_b + disc) / e.q2 - 0.5f;
    int xa = lo > float(e.x0) && lo < float(e.x1) ? int(ceil(lo)) : e.x0;
    int xb = hi > float(e.x0) && hi < float(e.x1) ? int(floor(hi)) : e.x1;
    if (xa > e.x0 && chermain2020_cell_r2(e, xa - 1, y) < 1.0f) --xa;
    if (xb < e.x1 && chermain2020_cell_r2(e, xb + 1, y) < 1.0f) ++xb;
    return ivec2(xa, xb);
}

// Algorithm 2: sum over the cells of level `level` whose centres fall in the
// ellipse, weighted by the truncated Gaussian exp(-2 r^2) - exp(-2) and
// normalised (sum of W_P = 1, Eq. 12). Each cell's SDF is tinted by its
// colour (Alg. 3 line 19); decision (docs/MODELS.md): cells that fall back to
// the analytic target (line 10) keep their colour too, so the tint does not
// vanish when the density passes the dictionary's last level.
vec3 chermain2020_level_p22(vec2 slope, vec2 uv, vec3 ellipse, int level, Chermain2020Dict d,
                            float alpha_x, float alpha_y, float rho, float log_density,
                            float relative_area, float density_randomization, uint seed,
                            Chermain2020Colours colours, Chermain2020Filter ggaa) {
    float scale = exp2(float(d.n_levels - 1 - level));  // cells per uv unit at this level
    vec2 centre = uv * scale;
    float major = ellipse.x * scale;
    float minor = ellipse.y * scale;
    float ca = cos(ellipse.z);
    float sa = sin(ellipse.z);
    float ex = sqrt(major * major * ca * ca + minor * minor * sa * sa);
    float ey = sqrt(major * major * sa * sa + minor * minor * ca * ca);
    // At most 64 cells per axis (gamma = 32 at 2 cells of minor axis).
    ex = min(ex, 32.0f);
    ey = min(ey, 32.0f);
    int x0 = int(floor(centre.x - ex));
    int x1 = int(floor(centre.x + ex));
    int y0 = int(floor(centre.y - ey));
    int y1 = int(floor(centre.y + ey));
    // The cells are walked as one flat loop, a cell per step, row after row,
    // each row over the range of x whose centres can fall in the ellipse:
    // with p = (px, py) the centre's offset, the ellipse is q2 px^2 + q1 px
    // py + q0 py^2 < 1, and the row's roots bound x up to rounding, which one
    // test of the loop's own r^2 at each end settles (non-finite roots keep
    // the bounding box). The r^2 < 1 test still decides every cell, so the
    // sums are those of the whole bounding box, bit for bit, in the same
    // order. Why flat: SIMD back ends such as llvmpipe run a
    // block of pixels through the loop until its last pixel is done, so a
    // loop over rows with one over each row's cells costs, per row, the
    // widest row of the block; one loop costs the block's largest number
    // of cells (and empty rows). The cell under the footprint's centre, the
    // fallback of footprints that hold no cell centre, is one more step of
    // the same loop, taken only by the pixels that need it.
    float im2 = 1.0f / (major * major);
    float in2 = 1.0f / (minor * minor);
    Chermain2020Ellipse e;
    e.centre = centre;
    e.ca = ca;
    e.sa = sa;
    e.major = major;
    e.minor = minor;
    e.q2 = ca * ca * im2 + sa * sa * in2;
    e.q1 = 2.0f * ca * sa * (im2 - in2);
    e.q0 = sa * sa * im2 + ca * ca * in2;
    e.x0 = x0;
    e.x1 = x1;
    Chermain2020Lookup lookup = chermain2020_lookup(slope, d, alpha_x, alpha_y, rho, ggaa);
    vec3 sum_p = vec3(0.0f);
    float sum_w = 0.0f;
    int y = y0;
    ivec2 range = chermain2020_row_range(e, y);
    int x = range.x;
    bool under_centre = false;  // the fallback step
    while (true) {
        float r2 = chermain2020_cell_r2(e, x, y);
        bool in_ellipse = x <= range.y && r2 < 1.0f;
        if (in_ellipse || under_centre) {
            ivec2 cell = under_centre ? ivec2(floor(centre)) : ivec2(x, y);
            float w = under_centre ? 1.0f : exp(-2.0f * r2) - 0.13533528f;  // exp(-2)
            vec2 sdf = chermain2020_cell_sdf(cell, level, d, log_density, relative_area,
                                             density_randomization, seed, lookup);
            if (sdf.x > 0.0f) sum_p += (w * sdf.x) * chermain2020_colour(sdf.y, colours);
            sum_w += w;
        }
        if (under_centre) break;
        ++x;
        if (x > range.y) {  // the next row
            ++y;
            range = chermain2020_row_range(e, y);
            x = range.x;
        }
        if (y > y1) {
            if (sum_w > 0.0f) break;
            under_centre = true;  // no cell centre in the footprint (only at level 0)
        }
    }
    // The fallback's weight 1 returns its SDF as it is.
    return sum_p / sum_w;
}

// RGB D_P(h) of Eq. 13 over the footprint (Algorithm 1) with coloured glints,
// h in the local frame.
vec3 chermain2020_ndf_rgb(vec3 h, Footprint fp, Chermain2020Dict d, float alpha_x, float alpha_y,
                          float rho, float log_density, uint seed, float relative_area,
                          float max_anisotropy, float density_randomization,
                          Chermain2020Colours colours, Chermain2020Filter ggaa) {
    if (h.z <= 0.0f) return vec3(0.0f);
    vec2 slope = vec2(-h.x / h.z, -h.y / h.z);  // normalToSlope (Eq. 1)
    vec3 ellipse = chermain2020_footprint_ellipse(fp.duvdx, fp.duvdy, max_anisotropy);
    // Line 6: l = max(0, nLevels - 1 + log2(minor)); levels above 28 would
    // overflow the coherent index and hold far more facets than any density.
    float lod = clamp(float(d.n_levels - 1) + log2(ellipse.y), 0.0f, 28.0f);
    int l0 = int(floor(lod));
    float w = lod - float(l0);
    vec3 p = chermain2020_level_p22(slope, fp.uv, ellipse, l0, d, alpha_x, alpha_y, rho,
                                    log_density, relative_area, density_randomization, seed,
                                    colours, ggaa);
    if (w > 0.0f) {  // line 8: lerp of the two discrete P-SDFs (Eq. 12)
        vec3 p1 = chermain2020_level_p22(slope, fp.uv, ellipse, l0 + 1, d, alpha_x, alpha_y, rho,
                                         log_density, relative_area, density_randomization, seed,
                                         colours, ggaa);
        p = mix(p, p1, w);
    }
    float c2 = h.z * h.z;
    return p / (c2 * c2);  // Eq. 13
}

// Scalar D_P(h) of Eq. 13 (no colour table), h in the local frame.
float chermain2020_ndf(vec3 h, Footprint fp, Chermain2020Dict d, float alpha_x, float alpha_y,
                       float rho, float log_density, uint seed, float relative_area,
                       float max_anisotropy, float density_randomization,
                       Chermain2020Filter ggaa) {
    Chermain2020Colours none;
    none.count = 0;
    for (int i = 0; i < CHERMAIN2020_MAX_COLOURS; ++i) none.table[i] = vec3(1.0f);
    return chermain2020_ndf_rgb(h, fp, d, alpha_x, alpha_y, rho, log_density, seed, relative_area,
                                max_anisotropy, density_randomization, none, ggaa)
        .x;
}

#endif
