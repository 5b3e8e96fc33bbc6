// Experiments behind `glintlab validate jakob2014` and the unit tests: count
// statistics against the binomial law, convergence of D_P to the smooth NDF,
// and the 002 Table 1 query statistics.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "glintlab/glints/jakob2014/query.h"

namespace glintlab::jakob2014 {

// One fixed query geometry (directions in the local frame).
struct QueryGeometry {
    std::string name;
    int ndf = 0;
    float alpha_x = 0.3f, alpha_y = 0.3f;
    double gamma_deg = 1.0;
    glm::dvec3 wi{0, 0, 1}, wo{0, 0, 1};
    double log_density = 12.0;
    glm::dvec2 e1{1e-2, 0.0}, e2{0.0, 1e-2};  // footprint edges (uv)
    bool at_tile_corner = false;              // centre every footprint on uv (0, 0)
};

struct CountChi2 {
    double expected_mean = 0.0;  // N · p_space · p_dir
    double observed_mean = 0.0;
    double chi2 = 0.0;
    int dof = 0;
    double p_value = 1.0;
    int non_integer = 0;  // counts that were not integers (must be 0 with ε = 0)
};

// Counts of `footprints` independent queries (material seed k and a uniform
// random position for footprint k) against Binomial(N, p_space · p_dir),
// Pearson χ² with bins pooled to >= 5 expected. ε = 0 (exact traversal).
CountChi2 count_chi2(const QueryGeometry& g, int footprints, uint64_t seed);

struct ConvergenceResult {
    double expected_count = 0.0;  // particles per query
    double mean_ndf = 0.0;        // mean D_P over footprints
    double smooth_ndf = 0.0;      // D(h)
    double cone_ndf = 0.0;        // exact E[D_P] for this γ (D smoothed by the cone)
    double rel_err_smooth = 0.0;  // |mean / D(h) - 1|
    double rel_err_cone = 0.0;    // |mean / cone_ndf - 1|
    double std_err = 0.0;         // standard error of the mean, relative
};

// Mean D_P over `footprints` random square footprints sized so that the
// expected count per query is `expected_count` (ε = 0.1, the paper's value).
ConvergenceResult convergence(const QueryGeometry& g, double expected_count, int footprints,
                              uint64_t seed, double epsilon = 0.1);

struct Table1Row {
    std::string scene;
    double paper_nodes = 0.0, paper_count = 0.0;  // 002 Table 1
    double nodes = 0.0, count = 0.0;              // ours, per query
    int64_t queries = 0;
    int64_t over_budget = 0;  // tile traversals that hit Model::kNodeBudget
    int nan_count = 0;
};

// Queries of a plane seen by a 768 x 768 camera (002 Table 1 settings:
// SPHERE LIGHTS N = 1e9, γ = 0.5°, α = 0.1; TWISTED TORUS N = 1e5..1e8,
// γ = 1°, α = 0.03..0.81), light directions drawn around the mirror
// direction as a sphere light or environment would. `pixels` sets how many
// pixels of the image are queried.
std::vector<Table1Row> table1_statistics(int pixels, uint64_t seed);

}  // namespace glintlab::jakob2014

namespace glintlab::jakob2014 {

// jakob2014 against the `explicit` ground truth (glints/explicit/explicit.h:
// N facets per unit uv area, uniform positions, normals D(m)(m·n)), both on
// the same material and seeded per realization. A plane of `pixels`² square
// footprints tiling the uv square (z = 0) is seen by a camera at finite
// distance; per-pixel values are compared by their first and second moments
// over the pixels and `realizations` seeds, with standard errors from the
// spread over realizations.
struct ExplicitComparison {
    double mean_explicit = 0.0, mean_jakob = 0.0;
    double m2_explicit = 0.0, m2_jakob = 0.0;
    double mean_rel_err = 0.0, m2_rel_err = 0.0;
    double mean_std_err = 0.0, m2_std_err = 0.0;  // relative standard errors of the difference
    // Per-pixel variance m2 - mean² (the glint statistics proper: m2 alone
    // is dominated by mean² when footprints hold many particles).
    double var_explicit = 0.0, var_jakob = 0.0, var_rel_err = 0.0;
};
// Under a point light at finite distance: per-pixel D_P
// (explicit_footprint_ndf vs jakob2014_footprint_ndf).
ExplicitComparison compare_with_explicit_particles(int ndf, float alpha, double gamma_deg,
                                                   double log_density, int pixels, int realizations,
                                                   uint64_t seed);

// The environment of the comparison below (radiance of a local direction):
// smooth at the scale of γ, so jakob2014's cone average of each particle's
// reflection leaves the per-pixel law unchanged to O(γ²).
float smooth_test_environment(glm::vec3 d);

// Under that environment: per-pixel reflected radiance (F = 1). explicit:
// explicit_environment_radiance (exact sum over the footprint's facets);
// jakob2014: Monte Carlo with its own importance sampling (002 §4),
// `samples` per estimate and two independent estimates per pixel whose
// product is an unbiased estimate of the squared radiance.
ExplicitComparison compare_with_explicit_environment(int ndf, float alpha, double gamma_deg,
                                                     double log_density, int pixels,
                                                     int realizations, int samples, uint64_t seed);

}  // namespace glintlab::jakob2014
