#include "glintlab/glints/kneiphof2025/kneiphof2025_experiments.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include <glm/gtc/constants.hpp>

#include "glintlab/core/error.h"
#include "glintlab/core/glsl.h"
#include "glintlab/core/rng.h"
#include "glintlab/glints/explicit/explicit.h"
#include "glintlab/glints/glint_desc.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_prefilter.h"
#include "glintlab/microfacet/microfacet.h"
#include "glintlab/scene/environment.h"

// This translation unit's own copy of deliot2023.glsl: the gate experiment
// runs the full grid with both the fixed and the published law.
GLINTLAB_SHADER_FUNCTIONS_BEGIN
#include "glintlab/glints/deliot2023/deliot2023.glsl"
GLINTLAB_SHADER_FUNCTIONS_END

namespace glintlab {
namespace {

constexpr float kPi = glm::pi<float>();

// A footprint of ~`n` expected facets on the grid: with screen_space_scale S
// the grid's trials are density x minor x major x S^2 / 4 (000 §5.2, LOD =
// log2(minor S / 2), cells linear in area), so log density = ln n - ln(s^2 S^2 / 4)
// for an s x s footprint (rotated by a random angle).
Footprint random_footprint(Pcg32& rng, float s) {
    const float a = 2.0f * kPi * rng.next_float();
    return Footprint{glm::vec2(rng.next_float(), rng.next_float()),
                     s * glm::vec2(std::cos(a), std::sin(a)),
                     s * glm::vec2(-std::sin(a), std::cos(a))};
}

float log_density_for(float log_count, float s, float S) {
    return log_count - std::log(s * s * S * S * 0.25f);
}

glm::vec3 random_direction(Pcg32& rng) {
    const float z = 2.0f * rng.next_float() - 1.0f, phi = 2.0f * kPi * rng.next_float();
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), z, r * std::sin(phi)};
}

// Facet normals with density D(h) / D_H over solid angle (003 §3.2: facets
// distributed proportionally to their unprojected area), isotropic GGX, by
// inverting the closed-form CDF in s = ln(tan^2 theta) on a table:
// F(u) = alpha^2 [1/alpha^2 - X / (alpha^2 + u) + I(u)] / D_H, X = sqrt(1 + u),
// I(u) = int_1^X dx / (x^2 - b^2) = (ln((X-b)/(X+b)) - ln((1-b)/(1+b))) / (2b),
// b = sqrt(1 - alpha^2) (alpha < 1).
class GgxAreaSampler {
  public:
    explicit GgxAreaSampler(float alpha) : alpha_(alpha) {
        if (!(alpha > 0.0f && alpha < 1.0f)) fail("GgxAreaSampler: alpha must be in (0, 1)");
        const double a2 = double(alpha) * alpha, b = std::sqrt(1.0 - a2);
        const double dh = kneiphof2025_total_facet_area(alpha);
        auto F = [&](double u) {
            const double X = std::sqrt(1.0 + u);
            const double I =
                (std::log((X - b) / (X + b)) - std::log((1.0 - b) / (1.0 + b))) / (2.0 * b);
            return a2 * (1.0 / a2 - X / (a2 + u) + I) / dh;
        };
        s_.resize(kN);
        cdf_.resize(kN);
        for (int i = 0; i < kN; ++i) {
            s_[i] = kSMin + (kSMax - kSMin) * i / (kN - 1);
            cdf_[i] = F(std::exp(s_[i]));
        }
        const double c0 = cdf_.front(), c1 = cdf_.back();
        for (double& c : cdf_) c = (c - c0) / (c1 - c0);
    }
    glm::vec3 sample(float u1, float u2) const {
        const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), double(u1));
        const int i = std::clamp(static_cast<int>(it - cdf_.begin()) - 1, 0, kN - 2);
        const double t = cdf_[i + 1] > cdf_[i] ? (u1 - cdf_[i]) / (cdf_[i + 1] - cdf_[i]) : 0.0;
        const double u = std::exp(s_[i] + t * (s_[i + 1] - s_[i]));
        const float cos_t = static_cast<float>(1.0 / std::sqrt(1.0 + u));
        const float sin_t = std::sqrt(std::max(0.0f, 1.0f - cos_t * cos_t));
        const float phi = 2.0f * kPi * u2;
        return {sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t};
    }
    float alpha() const { return alpha_; }

  private:
    static constexpr int kN = 16384;
    static constexpr double kSMin = -40.0, kSMax = 30.0;
    float alpha_;
    std::vector<double> s_, cdf_;
};

// Contribution of one facet with local normal h (Eq. 3, 5 with dwi = 4 <h,wo> dh):
// G2(wo, wi) <h, wo> / cos_o L(wi), F = 1; the footprint's radiance is
// D_H / E[N_P] times the sum over its facets, whose mean is int rho~ L dwi.
glm::vec3 facet_contribution(const EnvironmentMap& env, glm::vec3 h, glm::vec3 wo, glm::vec3 t,
                             glm::vec3 b, glm::vec3 n, float alpha) {
    const float oh = glm::dot(wo, h);
    if (oh <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 wi = 2.0f * oh * h - wo;
    if (wi.z <= 0.0f) return glm::vec3(0.0f);
    const float g = shader::G2_SmithCorrelated(shader::NDF_GGX, wo, wi, alpha, alpha);
    const glm::vec3 w = wi.x * t + wi.y * b + wi.z * n;
    return env.eval(w) * (g * oh / wo.z);
}

int poisson(Pcg32& rng, double lambda) {
    if (lambda < 50.0) {
        const double l = std::exp(-lambda);
        int k = 0;
        double p = 1.0;
        do {
            ++k;
            p *= rng.next_float();
        } while (p > l);
        return k - 1;
    }
    // Normal approximation (relative error of the law's shape < 1 / sqrt(50)).
    const float u1 = std::max(rng.next_float(), 1e-7f), u2 = rng.next_float();
    const double z = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
    return std::max(0, static_cast<int>(std::lround(lambda + std::sqrt(lambda) * z)));
}

// One pixel of the 003 Fig. 6 sphere: orthographic view along -z of the
// unit sphere, res x res pixels over [-1, 1]^2.
struct SpherePixel {
    int x, y;
    glm::vec3 n, t, b, wr;
    Footprint fp;
    double area;  // uv area of the footprint parallelogram
};

std::vector<SpherePixel> sphere_pixels(int res) {
    const float delta = 2.0f / static_cast<float>(res);
    std::vector<SpherePixel> pixels;
    const glm::vec3 wo_world(0.0f, 0.0f, 1.0f);
    for (int y = 0; y < res; ++y)
        for (int x = 0; x < res; ++x) {
            const float px = -1.0f + (x + 0.5f) * delta, py = 1.0f - (y + 0.5f) * delta;
            const float r2 = px * px + py * py;
            if (r2 >= 1.0f) continue;
            const glm::vec3 n(px, py, std::sqrt(1.0f - r2));
            if (n.z < 0.05f) continue;  // silhouette: footprints degenerate
            SpherePixel p;
            p.x = x;
            p.y = y;
            p.n = n;
            const float sign = std::copysign(1.0f, n.z), a = -1.0f / (sign + n.z),
                        bb = n.x * n.y * a;
            p.t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * bb, -sign * n.x);
            p.b = glm::vec3(bb, sign + n.y * n.y * a, -n.y);
            p.wr = 2.0f * n.z * n - wo_world;
            // uv = (atan2(x, z) / 2pi + 1/2, acos(y) / pi); tangent-plane pixel steps.
            const glm::vec3 dpdx(delta, 0.0f, -delta * n.x / n.z),
                dpdy(0.0f, -delta, delta * n.y / n.z);
            const float rxz = n.x * n.x + n.z * n.z;
            const glm::vec3 gu = glm::vec3(n.z, 0.0f, -n.x) / (2.0f * kPi * rxz);
            const glm::vec3 gv(0.0f, -1.0f / (kPi * std::sqrt(std::max(1.0f - n.y * n.y, 1e-8f))),
                               0.0f);
            p.fp.uv = glm::vec2(std::atan2(n.x, n.z) / (2.0f * kPi) + 0.5f, std::acos(n.y) / kPi);
            p.fp.duvdx = glm::vec2(glm::dot(gu, dpdx), glm::dot(gv, dpdx));
            p.fp.duvdy = glm::vec2(glm::dot(gu, dpdy), glm::dot(gv, dpdy));
            p.area =
                std::abs(double(p.fp.duvdx.x) * p.fp.duvdy.y - double(p.fp.duvdx.y) * p.fp.duvdy.x);
            pixels.push_back(p);
        }
    return pixels;
}

// Density giving `facets_per_pixel` in the centre pixel, whose uv footprint
// is (delta / 2pi) x (delta / pi).
double log_density_for_centre(int res, double facets_per_pixel) {
    const double delta = 2.0 / res;
    return std::log(facets_per_pixel / (delta * delta / (2.0 * kPi * kPi)));
}

GlintDesc validation_desc(float alpha, int K, double log_density) {
    GlintDesc desc;
    desc.model_id = GlintModelId::Kneiphof2025;
    desc.ndf = NdfType::GGX;
    desc.alpha_x = desc.alpha_y = alpha;
    desc.log_density = static_cast<float>(log_density);
    Kneiphof2025Params kp;
    kp.levels = K;
    // S = 2: the grid's trials equal density x footprint area (see
    // random_footprint), the ground truth's E[N_P].
    kp.screen_space_scale = 2.0f;
    desc.params = kp;
    return desc;
}

}  // namespace

FurnaceStats kneiphof2025_furnace_stats(const Kneiphof2025Environment& env,
                                        const GlintDesc& desc_in, float log_count, int footprints,
                                        uint32_t seed) {
    GlintDesc desc = desc_in;
    const float S = std::get<Kneiphof2025Params>(desc.params).screen_space_scale;
    const float s = 1e-3f;
    desc.log_density = log_density_for(log_count, s, S);
    Pcg32 rng(seed, 0x6b32u);
    FurnaceStats st;
    double sum = 0.0;
    int n = 0;
    for (int i = 0; i < footprints; ++i) {
        const Footprint fp = random_footprint(rng, s);
        const float cos_o = 0.2f + 0.8f * rng.next_float();
        const glm::vec3 wr = random_direction(rng);
        desc.seed = rng.next_uint();
        const glm::vec3 L = kneiphof2025_environment_radiance(env, wr, wr, cos_o, fp, desc);
        const glm::vec3 Ls = kneiphof2025_environment_smooth(env, wr, wr, cos_o, desc);
        if (!std::isfinite(L.x + L.y + L.z)) {
            ++st.nan_count;
            continue;
        }
        const float ls = luminance(Ls);
        if (ls > 0.0f) {
            sum += luminance(L) / ls;
            ++n;
        }
    }
    st.mean_factor = n > 0 ? sum / n : 0.0;
    return st;
}

GateBias kneiphof2025_gate_bias(float p, float n_expected, int footprints, uint32_t seed) {
    const float S = 1.5f, R = 0.025f, s = 1e-3f;
    const float log_density = log_density_for(std::log(n_expected), s, S);
    Pcg32 rng(seed, 0x9a7eu);
    double fixed = 0.0, original = 0.0;
    for (int i = 0; i < footprints; ++i) {
        const Footprint fp = random_footprint(rng, s);
        const glm::vec3 h = glm::normalize(
            glm::vec3(0.2f * rng.next_float() - 0.1f, 0.2f * rng.next_float() - 0.1f, 1.0f));
        const uint32_t sd = rng.next_uint();
        const shader::Deliot2023Grids g = shader::deliot2023_footprint_grids(fp, S, false);
        const glm::vec2 slope = glm::vec2(h.x, h.y) / R;
        glm::vec2 a(0.0f), b(0.0f);
        for (int k = 0; k < 4; ++k) {
            if (g.weight[k] <= 0.0f) continue;
            a +=
                shader::deliot2023_grid_counts(shader::deliot2023_grid_id(g, k), g.weight[k], fp.uv,
                                               slope, p, log_density, sd, 0.0f, false, false);
            b +=
                shader::deliot2023_grid_counts(shader::deliot2023_grid_id(g, k), g.weight[k], fp.uv,
                                               slope, p, log_density, sd, 0.0f, true, false);
        }
        fixed += a.y > 0.0f ? a.x / (a.y * p) : 0.0f;
        original += b.y > 0.0f ? b.x / (b.y * p) : 0.0f;
    }
    return {fixed / footprints, original / footprints};
}

std::vector<SphereComparison> kneiphof2025_sphere_comparison(const SphereComparisonOptions& o) {
    const int res = o.resolution;
    const double log_density_1 = log_density_for_centre(res, o.facets_per_pixel);

    const std::vector<SpherePixel> pixels = sphere_pixels(res);
    const glm::vec3 wo_world(0.0f, 0.0f, 1.0f);
    const int tiles_x = 3 * static_cast<int>(o.log_rhos.size());
    const int tiles_y = static_cast<int>(o.environments.size() * o.sqrt_alphas.size());
    Image grid(tiles_x * res, tiles_y * res, glm::vec3(0.0f));
    std::vector<SphereComparison> out;
    int row = 0;
    for (const auto& path : o.environments) {
        const auto env = std::make_shared<const EnvironmentMap>(read_image(path), 1.0f, 0.0f);
        for (float sa : o.sqrt_alphas) {
            const float alpha = sa * sa;
            const GgxAreaSampler sampler(alpha);
            const double dh = kneiphof2025_total_facet_area(alpha);
            // Expectation of the ground truth per pixel, int rho~ L dwi (F = 1):
            // multiple importance sampling (balance heuristic) of the facet
            // normals (h ~ D / D_H: pdf(wi) = D / (4 D_H <h, wo>)) and of the
            // environment's luminance (EnvironmentMap::sample), 64 + 64
            // stratified samples: the suns of city / interior (luminance 3e4)
            // are found by the second strategy.
            std::vector<double> gt_mean(pixels.size());
            {
                Pcg32 rng(o.seed, 0x1000u + row);
                const int m = 8;
                for (size_t i = 0; i < pixels.size(); ++i) {
                    const SpherePixel& p = pixels[i];
                    const glm::vec3 wo(glm::dot(wo_world, p.t), glm::dot(wo_world, p.b), p.n.z);
                    auto brdf = [&](glm::vec3 wi, glm::vec3 h, float* pdf_b) {
                        const float d = shader::D_Microfacet(shader::NDF_GGX, h, alpha, alpha);
                        *pdf_b = static_cast<float>(d / (4.0 * dh * glm::dot(h, wo)));
                        return shader::G2_SmithCorrelated(shader::NDF_GGX, wo, wi, alpha, alpha) *
                               d / (4.0f * wo.z);
                    };
                    double acc = 0.0;
                    for (int a = 0; a < m; ++a)
                        for (int c = 0; c < m; ++c) {
                            const glm::vec2 u((a + rng.next_float()) / m,
                                              (c + rng.next_float()) / m);
                            const glm::vec3 h = sampler.sample(u.x, u.y);
                            const float oh = glm::dot(wo, h);
                            if (oh > 0.0f) {
                                const glm::vec3 wi = 2.0f * oh * h - wo;
                                if (wi.z > 0.0f) {
                                    const glm::vec3 w = wi.x * p.t + wi.y * p.b + wi.z * p.n;
                                    float pdf_b = 0.0f;
                                    const float f = brdf(wi, h, &pdf_b);
                                    acc += f * luminance(env->eval(w)) / (pdf_b + env->pdf(w));
                                }
                            }
                            glm::vec3 w;
                            float pdf_e = 0.0f;
                            const glm::vec3 le = env->sample(
                                glm::vec2((c + rng.next_float()) / m, (a + rng.next_float()) / m),
                                &w, &pdf_e);
                            const glm::vec3 wi(glm::dot(w, p.t), glm::dot(w, p.b),
                                               glm::dot(w, p.n));
                            if (pdf_e > 0.0f && wi.z > 0.0f) {
                                const glm::vec3 h2 = glm::normalize(wi + wo);
                                float pdf_b = 0.0f;
                                const float f = brdf(wi, h2, &pdf_b);
                                acc += f * luminance(le) / (pdf_b + pdf_e);
                            }
                        }
                    gt_mean[i] = acc / (m * m);
                }
            }
            double gt_mean_sum = 0.0;
            for (double v : gt_mean) gt_mean_sum += v;
            for (size_t di = 0; di < o.log_rhos.size(); ++di) {
                const float log_rho = o.log_rhos[di];
                const double log_density = log_density_1 + log_rho;
                const double fpp = o.facets_per_pixel * std::exp(log_rho);
                const int R = std::clamp(static_cast<int>(std::ceil(256.0 / fpp)), 2, 16);
                const float exposure = log_rho < 0.0f ? 0.25f : 1.0f;  // 003 Fig. 6: -2 stops
                // Ground truth realizations: Poisson(density |P|) facets per footprint.
                double gt_sq = 0.0, gt_sum = 0.0;
                Pcg32 rng(o.seed, 0x2000u + 16u * row + di);
                for (int r = 0; r < R; ++r)
                    for (size_t i = 0; i < pixels.size(); ++i) {
                        const SpherePixel& p = pixels[i];
                        const double lambda = std::exp(log_density) * p.area;
                        const int count = poisson(rng, lambda);
                        const glm::vec3 wo(glm::dot(wo_world, p.t), glm::dot(wo_world, p.b), p.n.z);
                        glm::vec3 acc(0.0f);
                        for (int k = 0; k < count; ++k)
                            acc += facet_contribution(
                                *env, sampler.sample(rng.next_float(), rng.next_float()), wo, p.t,
                                p.b, p.n, alpha);
                        const glm::vec3 L = acc * static_cast<float>(dh / lambda);
                        const double l = luminance(L);
                        gt_sum += l;
                        gt_sq += (l - gt_mean[i]) * (l - gt_mean[i]);
                        if (r == 0)
                            grid.at(static_cast<int>(di) * 3 * res + 2 * res + p.x,
                                    row * res + p.y) = L * exposure;
                    }
                // The `explicit` model on the same footprints: its own facet
                // field (N = rho per unit uv area, exact counts, normals
                // D(m)(m·n)), environment read in each pixel's local frame.
                double ex_sq = 0.0, ex_sum = 0.0;
                ExplicitFacetField field;
                field.ndf = NdfType::GGX;
                field.alpha_x = field.alpha_y = alpha;
                field.log_density = log_density;
                for (int r = 0; r < R; ++r) {
                    field.seed = o.seed * 104729u + static_cast<uint32_t>(r);
                    for (size_t i = 0; i < pixels.size(); ++i) {
                        const SpherePixel& p = pixels[i];
                        const glm::vec3 wo(glm::dot(wo_world, p.t), glm::dot(wo_world, p.b), p.n.z);
                        const std::function<glm::vec3(glm::vec3)> local_env = [&](glm::vec3 d) {
                            return env->eval(d.x * p.t + d.y * p.b + d.z * p.n);
                        };
                        const double l =
                            luminance(explicit_environment_radiance(field, p.fp, wo, local_env));
                        ex_sum += l;
                        ex_sq += (l - gt_mean[i]) * (l - gt_mean[i]);
                    }
                }
                for (int variant = 0; variant < 4; ++variant) {
                    const int K = variant % 2 == 0 ? 4 : 8;
                    const bool conditional = variant >= 2;
                    const auto pre = kneiphof2025_environment_for(env, K, 1e-2f);
                    GlintDesc desc = validation_desc(alpha, K, log_density);
                    std::get<Kneiphof2025Params>(desc.params).conditional_gaussian = conditional;
                    SphereComparison c;
                    c.environment = path.stem().string();
                    c.sqrt_alpha = sa;
                    c.log_rho = log_rho;
                    c.levels = K;
                    c.conditional = conditional;
                    c.facets_per_pixel = fpp;
                    c.realizations = R;
                    double sum = 0.0, sq = 0.0, sum_means = 0.0, sum_means2 = 0.0, sum_smooth = 0.0;
                    for (int r = 0; r < R; ++r) {
                        const double sum_before = sum;
                        desc.seed = o.seed * 7919u + static_cast<uint32_t>(r);
                        for (const SpherePixel& p : pixels) {
                            const glm::vec3 L = kneiphof2025_environment_radiance(
                                *pre, p.n, p.wr, p.n.z, p.fp, desc);
                            if (!std::isfinite(L.x + L.y + L.z)) {
                                ++c.nan_count;
                                continue;
                            }
                            const double l = luminance(L);
                            const double m = luminance(
                                kneiphof2025_environment_smooth(*pre, p.n, p.wr, p.n.z, desc));
                            sum += l;
                            sum_smooth += m;
                            sq += (l - m) * (l - m);
                            if (r == 0 && conditional)
                                grid.at(
                                    static_cast<int>(di) * 3 * res + (K == 4 ? 0 : 1) * res + p.x,
                                    row * res + p.y) = L * exposure;
                        }
                        const double m = (sum - sum_before) / static_cast<double>(pixels.size());
                        sum_means += m;
                        sum_means2 += m * m;
                    }
                    const double np = static_cast<double>(pixels.size());
                    c.mean_ours = sum / (R * np);
                    const double mm = sum_means / R;
                    // Two estimates of the standard error, the larger is kept:
                    // the spread of the R image means (1 degree of freedom
                    // at R = 2, where a rare sun glint is easily missed by
                    // both), and the pixels' squared deviations from the
                    // smooth mean taken as independent, sqrt(sum sq) / (np R).
                    const double se_realizations =
                        std::sqrt(std::max(sum_means2 / R - mm * mm, 0.0) / std::max(R - 1, 1));
                    const double se_pixels = std::sqrt(sq) / (np * R);
                    c.mean_ours_se = std::max(se_realizations, se_pixels);
                    c.mean_gt = gt_mean_sum / np;
                    c.mean_gt_realized = gt_sum / (R * np);
                    c.mean_rel_err = std::abs(c.mean_ours - c.mean_gt) / c.mean_gt;
                    c.mean_smooth = sum_smooth / (R * np);
                    c.smooth_rel_err = std::abs(c.mean_smooth - c.mean_gt) / c.mean_gt;
                    c.variance_ratio = gt_sq > 0.0 ? sq / gt_sq : 0.0;
                    c.mean_explicit = ex_sum / (R * np);
                    c.variance_ratio_explicit = ex_sq > 0.0 ? sq / ex_sq : 0.0;
                    out.push_back(c);
                }
            }
            ++row;
        }
    }
    if (!o.grid_png.empty()) write_png(grid, o.grid_png, 0.0f);
    return out;
}

std::vector<SphereFurnace> kneiphof2025_sphere_furnace(int res, float sqrt_alpha,
                                                       const std::vector<float>& log_rhos,
                                                       double facets_per_pixel, int realizations,
                                                       uint32_t seed) {
    const std::vector<SpherePixel> pixels = sphere_pixels(res);
    const auto env =
        std::make_shared<const EnvironmentMap>(EnvironmentMap::constant(glm::vec3(1.0f)));
    const float alpha = sqrt_alpha * sqrt_alpha;
    const auto pre = kneiphof2025_environment_for(env, 8, 1e-2f);
    // The smooth model's reflected radiance in the furnace: E_rho(wo) = int rho~ dwi
    // with F = 1, integrated per pixel (not from the LUT).
    double smooth = 0.0;
    for (const SpherePixel& p : pixels) {
        const glm::vec3 e = Kneiphof2025DfgLut::integrate(p.n.z, sqrt_alpha, 1024);
        smooth += e.x + e.y;
    }
    std::vector<SphereFurnace> out;
    for (float log_rho : log_rhos) {
        GlintDesc desc =
            validation_desc(alpha, 8, log_density_for_centre(res, facets_per_pixel) + log_rho);
        SphereFurnace f;
        f.log_rho = log_rho;
        f.realizations = realizations;
        double sum = 0.0;
        for (int r = 0; r < realizations; ++r) {
            desc.seed = seed * 104729u + static_cast<uint32_t>(r);
            for (const SpherePixel& p : pixels) {
                const glm::vec3 L =
                    kneiphof2025_environment_radiance(*pre, p.n, p.wr, p.n.z, p.fp, desc);
                if (!std::isfinite(L.x + L.y + L.z)) {
                    ++f.nan_count;
                    continue;
                }
                sum += luminance(L);
            }
        }
        f.mean_glints = sum / (double(realizations) * pixels.size());
        f.mean_smooth = smooth / pixels.size();
        f.rel_err = std::abs(f.mean_glints - f.mean_smooth) / f.mean_smooth;
        out.push_back(f);
    }
    return out;
}

}  // namespace glintlab
