#include "glintlab/glints/deliot2023/deliot2023_experiments.h"

#include <atomic>
#include <cmath>
#include <cstring>

#include "glintlab/core/rng.h"
#include "glintlab/validate/random_queries.h"
#include "glintlab/validate/robustness_loop.h"

namespace glintlab {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kBeckmann = 0;  // shader::NDF_BECKMANN
constexpr int kGgx = 1;       // shader::NDF_GGX

}  // namespace

std::vector<ConvergenceCase> deliot2023_convergence(int footprints_per_case, uint64_t seed,
                                                    bool original_defects) {
    std::vector<ConvergenceCase> cases;
    for (int ndf : {kBeckmann, kGgx})
        for (float alpha : {0.1f, 0.3f, 0.7f})
            for (float t : {0.0f, 0.5f, 1.0f, 2.0f}) cases.push_back({ndf, alpha, t * alpha});
    Deliot2023Params params;
    params.original_defects = original_defects;
    for (size_t c = 0; c < cases.size(); ++c) {
        ConvergenceCase& k = cases[c];
        Deliot2023Target target;
        target.ndf = k.ndf;
        target.alpha_x = target.alpha_y = k.alpha;
        // Footprints of minor width 1e-3 uv hold ~1e7 facets at ln density 30.
        target.log_density = 30.0f;
        Pcg32 rng(c, seed);
        const glm::vec3 h = half_vector_at(k.tan_theta, 0.7);
        k.mean_dp = mean_over_random_footprints(rng, footprints_per_case,
                                                [&](const Footprint& fp, uint32_t seed) {
                                                    target.seed = seed;
                                                    return deliot2023_ndf(h, fp, target, params);
                                                });
        k.target = deliot2023_target_ndf(h, target);
        k.rel_err = std::abs(k.mean_dp / k.target - 1.0);
    }
    return cases;
}

std::vector<LodTransitionStep> deliot2023_lod_transition(int steps, int footprints_per_step,
                                                         uint64_t seed) {
    // Isotropic footprints around LOD l = -10 (cells of 2^-10 uv), h = n so
    // that p = R; density chosen for 1000 expected facets per footprint at
    // LOD l: e^ld 4^l p = 1000.
    const int l = -10;
    Deliot2023Params params;
    Deliot2023Target target;
    target.ndf = kBeckmann;
    target.alpha_x = target.alpha_y = 0.3f;
    const double p = params.microfacet_roughness;
    target.log_density = static_cast<float>(std::log(1000.0 / p) - 2.0 * l * std::log(2.0));
    const glm::vec3 h(0.0f, 0.0f, 1.0f);
    const double d_h = deliot2023_target_ndf(h, target);
    std::vector<LodTransitionStep> out;
    for (int s = 0; s < steps; ++s) {
        LodTransitionStep st;
        st.lod = l - 0.5 + (steps > 1 ? static_cast<double>(s) / (steps - 1) : 0.5);
        // LOD = log2(minor S / 2) (deliot2023.glsl).
        const double minor = std::exp2(st.lod + 1.0) / params.screen_space_scale;
        // With no density jitter, T = e^ld x sum_i w_i A_i = e^ld 4^LOD for
        // isotropic footprints (area-linear LOD weights, Eq. 10).
        st.mean_trials =
            std::exp(static_cast<double>(target.log_density)) * std::exp2(2.0 * st.lod);
        Pcg32 rng(static_cast<uint64_t>(s), seed);
        double sum = 0.0, sum2 = 0.0;
        for (int i = 0; i < footprints_per_step; ++i) {
            target.seed = rng.next_uint();
            const glm::vec2 uv(rng.next_float() * 4.0f, rng.next_float() * 4.0f);
            const double ratio =
                deliot2023_ndf(h, oriented_footprint(uv, minor, 1.0, 0.0), target, params) / d_h;
            sum += ratio;
            sum2 += ratio * ratio;
        }
        st.mean_ratio = sum / footprints_per_step;
        // C = T p x ratio: Var(C) relative to the binomial variance T p (1 - p).
        const double var_ratio =
            std::max(0.0, sum2 / footprints_per_step - st.mean_ratio * st.mean_ratio);
        st.count_variance_ratio = var_ratio * st.mean_trials * p / (1.0 - p);
        out.push_back(st);
    }
    return out;
}

RobustnessResult deliot2023_robustness(int64_t evaluations, uint64_t seed) {
    std::atomic<int64_t> bad_fixed{0}, bad_original{0};
    for_each_robustness_query(evaluations, seed,
                              [&](Pcg32& rng, int64_t i, const RobustnessQuery& q) {
                                  const auto t = robustness_target<Deliot2023Target>(q);
                                  Deliot2023Params p;
                                  p.microfacet_roughness = draw_log_with_ends(rng, -4, 0);
                                  p.screen_space_scale = draw_with_ends(rng, 0.5f, 8.0f);
                                  p.density_randomization = draw_with_ends(rng, 0.0f, 50.0f);
                                  const float d = deliot2023_ndf(q.h, q.footprint, t, p);
                                  if (!std::isfinite(d) || d < 0.0f) ++bad_fixed;
                                  // The original variant on every 8th sample (cost).
                                  if ((i & 7) == 0) {
                                      p.original_defects = true;
                                      const float o = deliot2023_ndf(q.h, q.footprint, t, p);
                                      if (!std::isfinite(o) || o < 0.0f) ++bad_original;
                                  }
                              });
    return {evaluations, bad_fixed.load(), bad_original.load()};
}

CoherenceResult deliot2023_coherence(int pairs, double uv_step, double footprint_step,
                                     uint64_t seed) {
    Pcg32 rng(0, seed);
    CoherenceResult r;
    int64_t jumps = 0;
    for (int i = 0; i < pairs; ++i) {
        Deliot2023Target t;
        t.ndf = static_cast<int>(rng.next_uint(2));
        t.alpha_x = t.alpha_y = 0.1f + 0.5f * rng.next_float();
        t.seed = rng.next_uint();
        Deliot2023Params p;
        const glm::vec3 h =
            half_vector_at(t.alpha_x * rng.next_double(), 2.0 * kPi * rng.next_double());
        const double minor = pow10_uniform(rng, -4, -2);
        // Density for 10-1000 expected facets per simplex vertex (cell area
        // ~(minor S/2)^2): sparser vertices make D_P's relative change under
        // a uv move unbounded near a zero barycentric weight, though continuous.
        const double pr = p.microfacet_roughness * deliot2023_target_ndf(h, t) /
                          deliot2023_target_ndf(glm::vec3(0.0f, 0.0f, 1.0f), t);
        const double cell = minor * p.screen_space_scale * 0.5;
        t.log_density = static_cast<float>(std::log(pow10_uniform(rng, 1, 3) / (pr * cell * cell)));
        const double angle = rng.next_double() * kPi;
        const double ratio = pow10_uniform(rng, 0, 1.5);
        const glm::vec2 uv(rng.next_float(), rng.next_float());
        const Footprint fp = oriented_footprint(uv, minor, ratio, angle);
        const float a = deliot2023_ndf(h, fp, t, p);
        const float a2 = deliot2023_ndf(h, fp, t, p);
        if (std::memcmp(&a, &a2, sizeof a) != 0) ++r.mismatches;
        const double d_h = deliot2023_target_ndf(h, t);
        const double dir = 2.0 * kPi * rng.next_double();
        Footprint moved = fp;
        moved.uv +=
            glm::vec2(static_cast<float>(std::cos(dir)), static_cast<float>(std::sin(dir))) *
            static_cast<float>(uv_step * minor);
        const float b = deliot2023_ndf(h, moved, t, p);
        r.uv_max_rel_change = std::max(r.uv_max_rel_change, std::abs(a - b) / (a + b + d_h));
        Footprint scaled = fp;
        scaled.duvdx *= static_cast<float>(1.0 + footprint_step);
        scaled.duvdy *= static_cast<float>(1.0 + footprint_step);
        const float c = deliot2023_ndf(h, scaled, t, p);
        if (std::abs(a - c) / (a + c + d_h) > 0.1) ++jumps;
    }
    r.footprint_jump_fraction = static_cast<double>(jumps) / pairs;
    return r;
}

}  // namespace glintlab
