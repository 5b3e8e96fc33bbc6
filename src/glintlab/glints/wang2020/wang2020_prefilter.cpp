#include "glintlab/glints/wang2020/wang2020_prefilter.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include "glintlab/core/error.h"
#include "glintlab/core/image.h"
#include "glintlab/core/rng.h"
#include "glintlab/glints/glint_bxdf.h"
#include "glintlab/glints/wang2020/wang2020_beckmann.h"
#include "glintlab/scene/environment.h"

namespace glintlab::wang2020 {

namespace {
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kHalfPi = 0.5 * kPi;

void cell(double x, int n, bool periodic, int& i0, int& i1, double& f) {
    if (periodic) {
        x -= std::floor(x / n) * n;
        i0 = std::min(static_cast<int>(x), n - 1);
        i1 = (i0 + 1) % n;
        f = x - i0;
    } else {
        x = std::clamp(x, 0.0, static_cast<double>(n - 1));
        i0 = std::min(static_cast<int>(x), n - 1);
        i1 = std::min(i0 + 1, n - 1);
        f = x - i0;
    }
}

// fn(row) for row in [0, rows) on up to 16 threads; each row depends only on
// its index, so the result is identical for any thread count.
template <typename Fn>
void parallel_rows(int rows, Fn&& fn) {
    const int threads =
        std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, std::min(rows, 16));
    std::atomic<int> next{0};
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t)
        pool.emplace_back([&] {
            for (int a = next++; a < rows; a = next++) fn(a);
        });
    for (int a = next++; a < rows; a = next++) fn(a);
    for (std::thread& th : pool) th.join();
}

// pdf_b(i) of the Beckmann reflection sampling (local frame).
double brdf_pdf(const glm::dvec3& i, const glm::dvec3& o, double alpha) {
    const glm::dvec3 hs = i + o;
    const double len = glm::length(hs);
    if (!(len > 0.0)) return 0.0;
    const glm::dvec3 h = hs / len;
    const double oh = glm::dot(o, h);
    if (oh <= 0.0 || h.z <= 0.0) return 0.0;
    return beckmann_D(h.z, alpha) * h.z / (4.0 * oh);
}
}  // namespace

ParticleRadianceTable::ParticleRadianceTable(const EnvironmentFn& env, double gamma_rad) {
    if (!(gamma_rad > 0.0 && gamma_rad < kHalfPi))
        fail("wang2020: cone half-angle {} rad outside (0, pi/2)", gamma_rad);
    // Output grid: about γ/2 per texel (L_γ is smooth at that scale).
    height_ = std::clamp(static_cast<int>(std::ceil(2.0 * kPi / gamma_rad)), 16, 512);
    width_ = 2 * height_;
    // Fine grid: ≥ 16 points across the cone's diameter 2γ, and at least
    // 512 rows (the studio maps' resolution).
    const int hf = std::clamp(static_cast<int>(std::ceil(8.0 * kPi / gamma_rad)), 512, 1536);
    const int wf = 2 * hf;
    const double dt = kPi / hf, dp = kTwoPi / wf;
    std::vector<double> st(hf), ct(hf), sp(wf), cp(wf);
    for (int j = 0; j < hf; ++j) {
        st[j] = std::sin((j + 0.5) * dt);
        ct[j] = std::cos((j + 0.5) * dt);
    }
    for (int i = 0; i < wf; ++i) {
        sp[i] = std::sin((i + 0.5) * dp);
        cp[i] = std::cos((i + 0.5) * dp);
    }
    std::vector<glm::vec3> fine(static_cast<size_t>(hf) * wf);
    parallel_rows(hf, [&](int j) {
        for (int i = 0; i < wf; ++i)
            fine[static_cast<size_t>(j) * wf + i] =
                env(glm::dvec3(st[j] * cp[i], st[j] * sp[i], ct[j]));
    });
    const double cos_g = std::cos(gamma_rad);
    data_.assign(static_cast<size_t>(width_) * height_, glm::vec4(0.0f));
    parallel_rows(height_, [&](int y) {
        const double tc = (y + 0.5) / height_ * kPi;
        const double stc = std::sin(tc), ctc = std::cos(tc);
        const int j0 = std::max(0, static_cast<int>(std::floor((tc - gamma_rad) / dt)) - 1);
        const int j1 = std::min(hf - 1, static_cast<int>(std::ceil((tc + gamma_rad) / dt)) + 1);
        for (int x = 0; x < width_; ++x) {
            const double pc = (x + 0.5) / width_ * kTwoPi;
            const glm::dvec3 c(stc * std::cos(pc), stc * std::sin(pc), ctc);
            glm::dvec3 sum(0.0);
            double wsum = 0.0;
            for (int j = j0; j <= j1; ++j) {
                // Columns whose points can lie in the cone: cos Δφ ≥
                // (cos γ − cos θ cos θc) / (sin θ sin θc).
                const double den = st[j] * stc;
                int i0 = 0, i1 = wf - 1;
                if (den > 1e-12) {
                    const double q = (cos_g - ct[j] * ctc) / den;
                    if (q > 1.0) continue;
                    if (q > -1.0) {
                        const double half = std::acos(q);
                        i0 = static_cast<int>(std::floor((pc - half) / dp)) - 1;
                        i1 = static_cast<int>(std::ceil((pc + half) / dp)) + 1;
                        if (i1 - i0 + 1 >= wf) i0 = 0, i1 = wf - 1;
                    }
                }
                for (int ii = i0; ii <= i1; ++ii) {
                    const int i = ((ii % wf) + wf) % wf;
                    const glm::dvec3 d(st[j] * cp[i], st[j] * sp[i], ct[j]);
                    if (glm::dot(d, c) < cos_g) continue;
                    sum += st[j] * glm::dvec3(fine[static_cast<size_t>(j) * wf + i]);
                    wsum += st[j];
                }
            }
            const glm::dvec3 v = wsum > 0.0 ? sum / wsum : glm::dvec3(env(c));
            data_[static_cast<size_t>(y) * width_ + x] = glm::vec4(glm::vec3(v), 0.0f);
        }
    });
    build_sampling_map();
}

ParticleRadianceTable ParticleRadianceTable::point_values(const EnvironmentFn& env, int rows) {
    if (rows < 2 || rows > 4096)
        fail("wang2020: point-value table of {} rows outside [2, 4096]", rows);
    ParticleRadianceTable t;
    t.height_ = rows;
    t.width_ = 2 * rows;
    t.data_.assign(static_cast<size_t>(t.width_) * t.height_, glm::vec4(0.0f));
    parallel_rows(t.height_, [&](int y) {
        const double tc = (y + 0.5) / t.height_ * kPi;
        const double stc = std::sin(tc), ctc = std::cos(tc);
        for (int x = 0; x < t.width_; ++x) {
            const double pc = (x + 0.5) / t.width_ * kTwoPi;
            const glm::dvec3 c(stc * std::cos(pc), stc * std::sin(pc), ctc);
            t.data_[static_cast<size_t>(y) * t.width_ + x] = glm::vec4(env(c), 0.0f);
        }
    });
    t.build_sampling_map();
    return t;
}

void ParticleRadianceTable::build_sampling_map() {
    // The sampling map, in EnvironmentMap's convention (y up: d = (sinθ sinφ,
    // cosθ, −sinθ cosφ) at u = 0.5 + φ/2π, v = θ/π), at the table's
    // resolution.
    Image image(width_, height_);
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const double th = (y + 0.5) / height_ * kPi;
            const double ph = ((x + 0.5) / width_ - 0.5) * kTwoPi;
            const glm::dvec3 d(std::sin(th) * std::sin(ph), std::cos(th),
                               -std::sin(th) * std::cos(ph));
            image.at(x, y) = glm::vec3(lookup(d));
        }
    map_ = std::make_shared<const EnvironmentMap>(std::move(image), 1.0f, 0.0f);
}

double ParticleRadianceTable::sample(const glm::dvec2& u, glm::dvec3& world_dir) const {
    glm::vec3 d(0.0f);
    float pdf = 0.0f;
    map_->sample(glm::vec2(u), &d, &pdf);
    world_dir = glm::dvec3(d);
    return static_cast<double>(pdf);
}

double ParticleRadianceTable::pdf(const glm::dvec3& world_dir) const {
    return static_cast<double>(map_->pdf(glm::vec3(world_dir)));
}

glm::dvec3 ParticleRadianceTable::lookup(const glm::dvec3& d) const {
    if (!std::isfinite(d.x + d.y + d.z)) return glm::dvec3(0.0);
    const double len = glm::length(d);
    if (!(len > 0.0)) return glm::dvec3(0.0);
    const double t = std::acos(std::clamp(d.z / len, -1.0, 1.0));
    const double p = std::atan2(d.y, d.x);
    int a0, a1, b0, b1;
    double fa, fb;
    cell(t / kPi * height_ - 0.5, height_, false, a0, a1, fa);
    cell(p / kTwoPi * width_ - 0.5, width_, true, b0, b1, fb);
    auto at = [&](int y, int x) {
        return glm::dvec3(glm::vec3(data_[static_cast<size_t>(y) * width_ + x]));
    };
    return (1.0 - fa) * ((1.0 - fb) * at(a0, b0) + fb * at(a0, b1)) +
           fa * ((1.0 - fb) * at(a1, b0) + fb * at(a1, b1));
}

PrefilterResolution default_prefilter_resolution(double alpha) {
    // Table 2 lists two resolutions: α = 0.1 (Shoe) and α = 0.5 (Snow,
    // Cloth). Smooth lobes need fewer samples; we switch at α = 0.3.
    if (alpha < 0.3) return {31, 60, 10, 36};
    return {10, 18, 4, 12};
}

void tangent_frame(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
    const double s = n.z >= 0.0 ? 1.0 : -1.0;
    const double a = -1.0 / (s + n.z);
    const double c = n.x * n.y * a;
    t = {1.0 + s * n.x * n.x * a, s * c, -s * n.x};
    b = {c, s + n.y * n.y * a, -n.y};
}

double m_term(const glm::dvec3& wi, const glm::dvec3& wo, double alpha) {
    if (!(wi.z > 0.0) || !(wo.z > 0.0)) return 0.0;
    const glm::dvec3 h = glm::normalize(wi + wo);
    if (h.z <= 0.0) return 0.0;
    return glm::dot(wi, h) * beckmann_G2(wi.z, wo.z, alpha) / (h.z * wo.z);
}

glm::dvec3 m_fresnel(const FresnelDesc* fresnel, const glm::dvec3& wi, const glm::dvec3& wo) {
    if (fresnel == nullptr || fresnel->mode == FresnelDesc::Mode::None) return glm::dvec3(1.0);
    const glm::dvec3 h = glm::normalize(wi + wo);
    return glm::dvec3(glint_fresnel(*fresnel, static_cast<float>(glm::dot(wi, h))));
}

glm::dvec4 PrefilterTable::evaluate(const DpfTable& dpf, double alpha, const EnvironmentFn& env,
                                    const glm::dvec3& n, const glm::dvec3& o, int K,
                                    uint64_t texel_id, const EnvironmentSampler* sampler,
                                    const FresnelDesc* fresnel, const ParticleRadianceTable* cone) {
    glm::dvec3 t, b;
    tangent_frame(n, t, b);
    auto to_world = [&](const glm::dvec3& v) { return v.x * t + v.y * b + v.z * n; };
    glm::dvec3 lo(0.0);
    // Effective fraction (cone != null): the moments E[f], E[f²] of one
    // particle's luminance f = lum(L_γ(i) F) M(i, o) over its normal
    // m ~ D(m)(m·n), i.e. ∫ f^k p_b di, from the K BRDF samples and K samples
    // of L_γ's own distribution p_c (ParticleRadianceTable::sample), balance
    // heuristic: weight p_b / (K (p_b + p_c)). A particle whose reflection
    // leaves the hemisphere counts as f = 0.
    double f1 = 0.0, f2 = 0.0;
    // i local, w = i in world space, f_i = F(i·h).
    auto add_moment = [&](const glm::dvec3& i, const glm::dvec3& w, const glm::dvec3& f_i,
                          double weight) {
        const double f = luminance(glm::vec3(cone->lookup(w) * f_i)) * m_term(i, o, alpha);
        f1 += weight * f;
        f2 += weight * f * f;
    };
    const int side = std::max(1, static_cast<int>(std::lround(std::sqrt(K))));
    const int k_used = side * side;
    Pcg32 rng(texel_id, 0x9e3779b97f4a7c15ull);
    // One jittered stratum per (sx, sy) of a second strategy's 2-D sample
    // space: sample(u, world_dir) returns its density; visit(world_dir, i,
    // density) gets the samples above the horizon (i local).
    auto for_each_stratum = [&](auto&& sample, auto&& visit) {
        for (int sy = 0; sy < side; ++sy) {
            for (int sx = 0; sx < side; ++sx) {
                const glm::dvec2 u((sx + rng.next_double()) / side,
                                   (sy + rng.next_double()) / side);
                glm::dvec3 d(0.0);
                const double p = sample(u, d);
                if (!(p > 0.0) || !std::isfinite(p)) continue;
                const glm::dvec3 i{glm::dot(d, t), glm::dot(d, b), glm::dot(d, n)};
                if (i.z <= 0.0) continue;
                visit(d, i, p);
            }
        }
    };
    for (int sy = 0; sy < side; ++sy) {
        for (int sx = 0; sx < side; ++sx) {
            // Jittered strata (one Pcg32 stream per texel): unbiased per texel,
            // so a small bright source (a sun) is not systematically missed
            // by every texel's fixed sample pattern.
            const double u1 = (sx + rng.next_double()) / side, u2 = (sy + rng.next_double()) / side;
            // Beckmann: tan²θh = −α² ln(1 − u1).
            const double tan2 = -alpha * alpha * std::log(1.0 - u1);
            const double ch = 1.0 / std::sqrt(1.0 + tan2);
            const glm::dvec3 h = spherical_dir(std::acos(ch), kTwoPi * u2);
            const double oh = glm::dot(o, h);
            if (oh <= 0.0) continue;
            const glm::dvec3 i = 2.0 * oh * h - o;
            if (i.z <= 0.0) continue;
            const double pdf = beckmann_D(h.z, alpha) * h.z / (4.0 * oh);
            if (!(pdf > 0.0)) continue;
            const glm::dvec3 w = to_world(i);
            const glm::dvec3 f_i = m_fresnel(fresnel, i, o);
            const glm::dvec3 li = glm::dvec3(env(w)) * f_i;
            if (cone != nullptr) add_moment(i, w, f_i, pdf / (k_used * (pdf + cone->pdf(w))));
            if (!sampler) {
                lo += li * (dpf.lookup(i, o) * m_term(i, o, alpha) / (pdf * k_used));  // Eq. 16
                continue;
            }
            // Balance heuristic: g / (K pdf_b + K pdf_e) for samples of either strategy.
            const double pe = sampler->pdf(w);
            lo += li * (dpf.lookup(i, o) * m_term(i, o, alpha) / (k_used * (pdf + pe)));
        }
    }
    if (sampler) {
        // The environment strategy: K samples of its luminance distribution
        // (same jittered strata over its 2-D sample space).
        for_each_stratum([&](const glm::dvec2& u, glm::dvec3& d) { return sampler->sample(u, d); },
                         [&](const glm::dvec3& d, const glm::dvec3& i, double pe) {
                             const double pb = brdf_pdf(i, o, alpha);
                             const double g = dpf.lookup(i, o) * m_term(i, o, alpha);
                             if (!(g > 0.0)) return;
                             lo += glm::dvec3(env(d)) * m_fresnel(fresnel, i, o) *
                                   (g / (k_used * (pb + pe)));
                         });
    }
    if (cone != nullptr) {
        // The moments' second strategy: K samples of L_γ's luminance.
        for_each_stratum([&](const glm::dvec2& u, glm::dvec3& d) { return cone->sample(u, d); },
                         [&](const glm::dvec3& d, const glm::dvec3& i, double pc) {
                             const double pb = brdf_pdf(i, o, alpha);
                             if (pb > 0.0)
                                 add_moment(i, d, m_fresnel(fresnel, i, o),
                                            pb / (k_used * (pb + pc)));
                         });
        // r = E[f]² / E[f²] ∈ (0, 1]; 1 where nothing is reflected (no
        // texture either way).
        const double r = f2 > 0.0 ? std::clamp(f1 * f1 / f2, 0.0, 1.0) : 1.0;
        return {lo, r};
    }
    // Eq. 17: B = 36 × 9 uniform (equal solid angle) hemisphere strata.
    double p_avg = 0.0;
    constexpr int kPhi = 36, kTheta = 9;
    for (int a = 0; a < kTheta; ++a) {
        const double cos_t = 1.0 - (a + 0.5) / kTheta;  // uniform in cos θ
        for (int p = 0; p < kPhi; ++p) {
            const glm::dvec3 i = spherical_dir(std::acos(cos_t), (p + 0.5) / kPhi * kTwoPi);
            p_avg += kTwoPi * dpf.lookup(i, o) / (kPhi * kTheta);
        }
    }
    return {lo, p_avg};
}

PrefilterTable::PrefilterTable(const DpfTable& dpf, double alpha, double /*gamma_rad*/,
                               const EnvironmentFn& env, PrefilterResolution res, int K,
                               const EnvironmentSampler* sampler, const FresnelDesc* fresnel,
                               const ParticleRadianceTable* cone)
    : res_(res) {
    if (res.theta_n < 2 || res.phi_n < 2 || res.theta_o < 2 || res.phi_o < 2)
        fail("wang2020: prefilter resolution {}x{}x{}x{} must be at least 2 everywhere",
             res.theta_n, res.phi_n, res.theta_o, res.phi_o);
    if (K < 1 || K > 4096) fail("wang2020: prefilter sample count K={} outside [1, 4096]", K);
    const auto t0 = std::chrono::steady_clock::now();
    data_.resize(static_cast<size_t>(res.theta_n) * res.phi_n * res.theta_o * res.phi_o);
    // Rows of θn in parallel (each texel depends only on its own index, so
    // the table is identical for any thread count).
    const size_t per_row = static_cast<size_t>(res.phi_n) * res.theta_o * res.phi_o;
    auto row = [&](int a) {
        size_t k = static_cast<size_t>(a) * per_row;
        for (int b = 0; b < res.phi_n; ++b) {
            const glm::dvec3 n =
                spherical_dir((a + 0.5) / res.theta_n * kPi, (b + 0.5) / res.phi_n * kTwoPi);
            for (int c = 0; c < res.theta_o; ++c)
                for (int d = 0; d < res.phi_o; ++d) {
                    const glm::dvec3 o = spherical_dir((c + 0.5) / res.theta_o * kHalfPi,
                                                       (d + 0.5) / res.phi_o * kTwoPi);
                    data_[k] =
                        glm::vec4(evaluate(dpf, alpha, env, n, o, K, k, sampler, fresnel, cone));
                    ++k;
                }
        }
    };
    parallel_rows(res.theta_n, row);
    build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

glm::dvec4 PrefilterTable::texel(int tn, int pn, int to, int po) const {
    return glm::dvec4(
        data_[((static_cast<size_t>(tn) * res_.phi_n + pn) * res_.theta_o + to) * res_.phi_o + po]);
}

glm::dvec3 PrefilterTable::texel_normal(int tn, int pn) const {
    return spherical_dir((tn + 0.5) / res_.theta_n * kPi, (pn + 0.5) / res_.phi_n * kTwoPi);
}

// The azimuth, in the tangent frame of the normal m, of the query frame's
// tangent t (frame of n) carried to m by the rotation taking n to m (the
// shortest arc): local azimuths of n's frame read at texel m are shifted by
// it. tangent_frame's two branches (n.z >= 0, n.z < 0) meet at the equator
// with frames turned against each other; within a branch the turn between
// neighbouring texels is small but not zero.
double frame_turn(const glm::dvec3& n, const glm::dvec3& t, const glm::dvec3& m) {
    const double c = glm::dot(n, m);
    const glm::dvec3 k = glm::cross(n, m);
    const glm::dvec3 tm = t * c + glm::cross(k, t) + k * (glm::dot(k, t) / (1.0 + c));
    glm::dvec3 tt, bb;
    tangent_frame(m, tt, bb);
    return std::atan2(glm::dot(tm, bb), glm::dot(tm, tt));
}

glm::dvec4 PrefilterTable::lookup(const glm::dvec3& n, const glm::dvec3& o_world) const {
    if (!std::isfinite(n.x + n.y + n.z + o_world.x + o_world.y + o_world.z))
        return glm::dvec4(0.0);  // no NaN → int casts in the cell search
    const double tn = std::acos(std::clamp(n.z, -1.0, 1.0));
    const double pn = std::atan2(n.y, n.x);
    int a0, a1, b0, b1;
    double fa, fb;
    cell(tn / kPi * res_.theta_n - 0.5, res_.theta_n, false, a0, a1, fa);
    cell(pn / kTwoPi * res_.phi_n - 0.5, res_.phi_n, true, b0, b1, fb);
    // o in the query normal's tangent frame; the four neighbouring normal
    // texels are read at these local coordinates (L̂o varies slowly with n at
    // fixed local o; exact for a constant environment), the azimuth turned
    // by frame_turn into each texel's own frame: tangent_frame's two
    // branches meet at the equator turned against each other, and reading a
    // texel across it at the query's azimuth was a seam under a sun (2-3x
    // the interpolation error in |n.z| < 0.05, Wang2020Prefilter.
    // LookupHasNoSeamAtTheFramesEquator). Reading each texel at o expressed
    // in that texel's own frame instead was measured 5 % off the furnace at
    // θo = 70° with 4 normal rows (docs/MODELS.md).
    glm::dvec3 t, b;
    tangent_frame(n, t, b);
    const glm::dvec3 ol{glm::dot(o_world, t), glm::dot(o_world, b),
                        std::max(glm::dot(o_world, n), 0.0)};
    const double to = std::acos(std::clamp(ol.z / std::max(glm::length(ol), 1e-12), 0.0, 1.0));
    const double po = std::atan2(ol.y, ol.x);
    int c0, c1;
    double fc;
    cell(to / kHalfPi * res_.theta_o - 0.5, res_.theta_o, false, c0, c1, fc);
    glm::dvec4 sum(0.0);
    const int an[2] = {a0, a1}, bn[2] = {b0, b1};
    const double wa[2] = {1.0 - fa, fa}, wb[2] = {1.0 - fb, fb};
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            const double w = wa[i] * wb[j];
            if (w == 0.0) continue;
            const double dphi = frame_turn(n, t, texel_normal(an[i], bn[j]));
            int d0, d1;
            double fd;
            cell((po + dphi) / kTwoPi * res_.phi_o - 0.5, res_.phi_o, true, d0, d1, fd);
            const glm::dvec4 v =
                (1 - fc) *
                    ((1 - fd) * texel(an[i], bn[j], c0, d0) + fd * texel(an[i], bn[j], c0, d1)) +
                fc * ((1 - fd) * texel(an[i], bn[j], c1, d0) + fd * texel(an[i], bn[j], c1, d1));
            sum += w * v;
        }
    return sum;
}

}  // namespace glintlab::wang2020
