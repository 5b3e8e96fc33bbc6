#include "glintlab/glints/kneiphof2025/validate_kneiphof2025.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "glintlab/glints/kneiphof2025/kneiphof2025_experiments.h"
#include "glintlab/glints/validation_suites.h"

namespace glintlab {
namespace {

// Blender's CC0 studio lights (Debian package blender-data): three
// environments of different dynamic range, as 003 Fig. 6 uses three.
const char* const kEnvironmentDir = "/usr/share/blender/datafiles/studiolights/world";
const char* const kEnvironments[] = {"forest.exr", "city.exr", "interior.exr"};

}  // namespace

ValidationReport validate_kneiphof2025(const Kneiphof2025ValidationOptions& o) {
    ValidationReport report;
    report.suite = "kneiphof2025";
    const auto t0 = std::chrono::steady_clock::now();
    const uint32_t seed = static_cast<uint32_t>(o.seed);

    // 003 Fig. 6: sphere x 3 environments x sqrt(alpha) x rho_N x K against
    // explicitly instantiated facets (our own reference, see docs).
    SphereComparisonOptions so;
    for (const char* e : kEnvironments)
        so.environments.push_back(std::filesystem::path(kEnvironmentDir) / e);
    so.resolution = o.resolution;
    so.seed = seed;
    so.grid_png = o.grid_png;
    if (!o.grid_png.empty() && o.grid_png.has_parent_path())
        std::filesystem::create_directories(o.grid_png.parent_path());
    const std::vector<SphereComparison> cmp = kneiphof2025_sphere_comparison(so);
    report.text += "ground truth comparison (003 Fig. 6 protocol; sphere " +
                   fmt::format("{0}x{0}", o.resolution) + ", mean luminance)\n";
    report.text += fmt::format(
        "{:>10} {:>6} {:>6} {:>3} {:>5} {:>9} {:>4} {:>11} {:>8} {:>11} {:>11} {:>9} {:>10} "
        "{:>9} {:>11} {:>9}\n",
        "env", "sqrt_a", "ln_rho", "K", "law", "N_P(ctr)", "R", "ours", "ours SE", "gt exact",
        "gt realized", "rel err", "smooth err", "var ratio", "explicit", "var/expl");
    // Cells whose mean is known to 2 % (standard error of the realizations'
    // image means): at rho_N = e^-4 the suns of city / interior (luminance
    // 3e4) make both the realized ground truth and ours rare-event estimates
    // (0.3 facets per pixel), so those cells are reported but not checked.
    double err_max = 0.0, err_max_algorithm1 = 0.0;
    int imprecise = 0;
    int nan = 0;
    for (const SphereComparison& c : cmp) {
        nan += c.nan_count;
        const bool precise = c.mean_ours_se <= 0.02 * c.mean_gt;
        if (!precise) {
            if (c.conditional) ++imprecise;
            continue;
        }
        double& m = c.conditional ? err_max : err_max_algorithm1;
        m = std::max(m, c.mean_rel_err);
    }
    nlohmann::json rows = nlohmann::json::array();
    for (const SphereComparison& c : cmp) {
        report.text += fmt::format(
            "{:>10} {:>6.2f} {:>6.1f} {:>3} {:>5} {:>9.3g} {:>4} {:>11.5g} {:>8.2g} {:>11.5g} "
            "{:>11.5g} "
            "{:>9.4f} {:>10.4f} {:>9.3f} {:>11.5g} {:>9.3f}\n",
            c.environment, c.sqrt_alpha, c.log_rho, c.levels, c.conditional ? "cond" : "alg1",
            c.facets_per_pixel, c.realizations, c.mean_ours, c.mean_ours_se, c.mean_gt,
            c.mean_gt_realized, c.mean_rel_err, c.smooth_rel_err, c.variance_ratio, c.mean_explicit,
            c.variance_ratio_explicit);
        rows.push_back({{"environment", c.environment},
                        {"sqrt_alpha", c.sqrt_alpha},
                        {"log_rho", c.log_rho},
                        {"levels", c.levels},
                        {"gaussian", c.conditional ? "conditional" : "algorithm1"},
                        {"facets_per_centre_pixel", c.facets_per_pixel},
                        {"realizations", c.realizations},
                        {"mean_ours", c.mean_ours},
                        {"mean_ours_se", c.mean_ours_se},
                        {"mean_gt", c.mean_gt},
                        {"mean_gt_realized", c.mean_gt_realized},
                        {"mean_rel_err", c.mean_rel_err},
                        {"mean_smooth", c.mean_smooth},
                        {"smooth_rel_err", c.smooth_rel_err},
                        {"variance_ratio", c.variance_ratio},
                        {"mean_explicit", c.mean_explicit},
                        {"variance_ratio_explicit", c.variance_ratio_explicit}});
    }
    report.details["ground_truth"] = rows;
    report.details["gt_mean_rel_err_max_algorithm1"] = err_max_algorithm1;
    report.details["gt_cells_not_checked"] = imprecise;
    if (!o.grid_png.empty()) report.details["grid_png"] = o.grid_png.string();
    // The glint factor has mean ~1 (Eq. 33; the conditional law's residual
    // bias is a few percent for K = 4), so the mean differs from the ground
    // truth by the split-sum approximation (Eq. 11) and that bias. Checked
    // for the default law over the precise cells (see above).
    report.text += fmt::format(
        "max rel err over cells with SE <= 2 %: {:.4f} (conditional, default), {:.4f} "
        "(algorithm1); {} conditional cells not checked\n",
        err_max, err_max_algorithm1, imprecise);
    report.check("gt_mean_rel_err_max", err_max, "<=", 0.1);

    // 003 Fig. 7: white furnace, sqrt(alpha) = 0.4, rho_N in {e^-2, 1, e^2}.
    // With ~2 facets per centre pixel at e^-2 the factor's std-dev is ~0.7 per
    // pixel; 256 realizations x ~3000 pixels give a standard error < 0.1 % of
    // the image mean: the 2 % limit tests the model's bias (LUT included).
    report.text += fmt::format("\nwhite furnace (sqrt(alpha) = 0.4, K = 8, {} realizations)\n",
                               o.furnace_realizations);
    report.text +=
        fmt::format("{:>8} {:>12} {:>12} {:>9}\n", "ln_rho", "mean glints", "smooth", "rel err");
    double furnace_max = 0.0;
    nlohmann::json fur = nlohmann::json::array();
    for (const SphereFurnace& f : kneiphof2025_sphere_furnace(
             o.resolution, 0.4f, {-2.0f, 0.0f, 2.0f}, 16.0, o.furnace_realizations, seed)) {
        furnace_max = std::max(furnace_max, f.rel_err);
        nan += f.nan_count;
        report.text += fmt::format("{:>8.1f} {:>12.6g} {:>12.6g} {:>9.5f}\n", f.log_rho,
                                   f.mean_glints, f.mean_smooth, f.rel_err);
        fur.push_back({{"log_rho", f.log_rho},
                       {"mean_glints", f.mean_glints},
                       {"mean_smooth", f.mean_smooth},
                       {"rel_err", f.rel_err}});
    }
    report.details["furnace"] = fur;
    report.check("furnace_rel_err", furnace_max, "<=", 0.02);

    // 003 Fig. 13 (a large area light: p = 0.5, N_P < 1) and Fig. 14 (the sun
    // off-specular: p = 1e-8, N_P p ~ 1). Mean of b / (E[N_P] p) over random
    // footprints: 1 for an unbiased law. Footprint counts give standard errors
    // <= 1.05 % (Fig. 13: std-dev sqrt(1 / (N p))) and <= 0.5 % (Fig. 14).
    report.text += "\ngate regressions: mean of b / (E[N_P] p), 1 = unbiased\n";
    report.text += fmt::format("{:>8} {:>10} {:>10} {:>10} {:>10}\n", "figure", "p", "N_P", "fixed",
                               "original");
    struct GateCase {
        const char* figure;
        float p, n;
        int footprints;
    };
    const GateCase cases[] = {{"13", 0.5f, std::exp(-4.0f), 1000000},
                              {"13", 0.5f, 1.0f, 40000},
                              {"13", 0.5f, std::exp(4.0f), 20000},
                              {"14", 1e-8f, 1e8f, 20000},
                              {"14", 1e-8f, 1e11f, 20000},
                              {"14", 1e-8f, 1e12f, 20000}};
    double fig13 = 0.0, fig14 = 0.0, fig13_orig = 0.0, fig14_orig = 0.0;
    nlohmann::json gates = nlohmann::json::array();
    for (const GateCase& g : cases) {
        const GateBias b = kneiphof2025_gate_bias(g.p, g.n, g.footprints, seed + 11u);
        const bool is13 = g.figure[1] == '3';
        // Fig. 14 asserts convergence: N_P p >= 1e3, where the single-gated
        // law's own bias (~1 / (N_v p) per grid vertex) is < 1.5 %; the
        // N_P p = 1 row shows that bias (+27 %) next to the published law's 0.
        if (is13 || double(g.n) * g.p >= 1e3)
            (is13 ? fig13 : fig14) = std::max(is13 ? fig13 : fig14, std::abs(b.fixed_mean - 1.0));
        (is13 ? fig13_orig : fig14_orig) =
            std::max(is13 ? fig13_orig : fig14_orig, std::abs(b.original_mean - 1.0));
        report.text += fmt::format("{:>8} {:>10.3g} {:>10.3g} {:>10.4f} {:>10.4f}\n", g.figure, g.p,
                                   g.n, b.fixed_mean, b.original_mean);
        gates.push_back({{"figure", g.figure},
                         {"p", g.p},
                         {"n_expected", g.n},
                         {"fixed_mean", b.fixed_mean},
                         {"original_mean", b.original_mean}});
    }
    report.details["gates"] = gates;
    report.details["fig13_abs_err_original"] = fig13_orig;
    report.details["fig14_abs_err_original"] = fig14_orig;
    // 5-6 standard errors of the worst case (1.05 % at N_P = e^-4).
    report.check("fig13_mean_abs_err", fig13, "<=", 0.06);
    report.check("fig14_mean_abs_err", fig14, "<=", 0.03);
    report.check("nan_count", static_cast<double>(nan), "==", 0.0);

    report.details["seconds"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return report;
}

// `glintlab validate kneiphof2025` (model_list.h).
ValidationSuiteRunner kneiphof2025_validation_suite() {
    return seeded_validation_suite<Kneiphof2025ValidationOptions, validate_kneiphof2025>();
}

}  // namespace glintlab
