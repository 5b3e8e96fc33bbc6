#include "glintlab/glints/zirr2016/validate_zirr2016.h"

#include <algorithm>
#include <chrono>

#include <fmt/format.h>

#include "glintlab/glints/validation_suites.h"
#include "glintlab/glints/zirr2016/zirr2016_experiments.h"

namespace glintlab {

ValidationReport validate_zirr2016(const Zirr2016ValidationOptions& o) {
    ValidationReport report;
    report.suite = "zirr2016";
    const auto t0 = std::chrono::steady_clock::now();

    // 000 Eq. 5-6 vs 004 §2 / Fig. 2: the mean of D_P against D(h) as the
    // density grows. Eq. 15's floored Gaussian has mean N p - 1/2, a relative
    // bias -1/(2 N p) in texels with N p > 5, which vanishes as N grows; every
    // other step (Eq. 4, bilinear and Eq. 7 blends, Bernoulli sums) keeps the mean.
    report.text += "convergence to the smooth NDF (R = 0.025, footprints of minor width 1e-3 uv)\n";
    report.text += fmt::format("{:>6} {:>8} {:>6} {:>9} {:>12} {:>12} {:>9}\n", "ln rho", "ndf",
                               "alpha", "tan(h)", "mean D_P", "D(h)", "rel err");
    nlohmann::json conv = nlohmann::json::array();
    nlohmann::json sweep = nlohmann::json::array();
    double conv_max = 0.0;
    const float densities[] = {16.0f, 20.0f, 24.0f, 30.0f};
    for (float ld : densities) {
        double worst = 0.0;
        for (const Zirr2016ConvergenceCase& c :
             zirr2016_convergence(ld, o.convergence_footprints, o.seed)) {
            worst = std::max(worst, c.rel_err);
            report.text +=
                fmt::format("{:>6.0f} {:>8} {:>6.2f} {:>9.3f} {:>12.5g} {:>12.5g} {:>9.2e}\n", ld,
                            c.ndf == 0 ? "beckmann" : "ggx", c.alpha, c.tan_theta, c.mean_dp,
                            c.target, c.rel_err);
            conv.push_back({{"log_density", ld},
                            {"ndf", c.ndf == 0 ? "beckmann" : "ggx"},
                            {"alpha", c.alpha},
                            {"tan_theta", c.tan_theta},
                            {"mean_dp", c.mean_dp},
                            {"target", c.target},
                            {"rel_err", c.rel_err}});
        }
        sweep.push_back({{"log_density", ld}, {"rel_err_max", worst}});
        if (ld == densities[3]) conv_max = worst;
    }
    report.details["convergence"] = conv;
    report.details["convergence_density_sweep"] = sweep;
    // Finding (docs/VALIDATION.md): as restated by 000 the process converges;
    // at ln density 30 (~1e7 facets per texel) the floor bias is < 1e-4 and the
    // estimate's noise ~0.1 %, so the same 2 % limit as the other models holds.
    report.check("convergence_rel_err_max", conv_max, "<=", 0.02);

    // 000 Fig. 4b: output blending (Eq. 7) keeps the mean count but lowers its
    // variance mid-transition (about half at w = 1/2 for P_top = 4 P_bottom).
    report.text += "\nLOD transition (isotropic, 400 trials per bottom texel, p = 0.1)\n";
    report.text += fmt::format("{:>8} {:>12} {:>14}\n", "LOD", "mean C/Np", "Var(C)/E[C]");
    nlohmann::json lod = nlohmann::json::array();
    double lod_mean_max = 0.0, var_min = 1e30, var_max = 0.0;
    for (int i = 0; i < o.lod_steps; ++i) {
        const double l = -10.0 + (i + 0.01) / o.lod_steps;
        const Zirr2016CountStats s =
            zirr2016_count_stats(l, 400.0, 0.1f, o.lod_footprints, o.seed + i);
        lod_mean_max = std::max(lod_mean_max, std::abs(s.mean_ratio - 1.0));
        var_min = std::min(var_min, s.variance_over_mean);
        var_max = std::max(var_max, s.variance_over_mean);
        report.text += fmt::format("{:>8.3f} {:>12.4f} {:>14.4f}\n", s.lod, s.mean_ratio,
                                   s.variance_over_mean);
        lod.push_back({{"lod", s.lod},
                       {"mean_ratio", s.mean_ratio},
                       {"variance_over_mean", s.variance_over_mean}});
    }
    report.details["lod_transition"] = lod;
    report.details["lod_transition_count_rel_err_max"] = lod_mean_max;
    report.details["lod_transition_variance_ratio_spread"] = var_max / var_min;

    const Zirr2016RobustnessResult rob = zirr2016_robustness(o.robustness_evaluations, o.seed);
    report.text += fmt::format("\nrobustness: {} evaluations, {} not finite or negative\n",
                               rob.evaluations, rob.bad);
    report.details["robustness_evaluations"] = rob.evaluations;
    report.check("nan_count", static_cast<double>(rob.bad), "==", 0.0);

    report.details["seconds"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return report;
}

// `glintlab validate zirr2016` (model_list.h).
ValidationSuiteRunner zirr2016_validation_suite() {
    return seeded_validation_suite<Zirr2016ValidationOptions, validate_zirr2016>();
}

}  // namespace glintlab
