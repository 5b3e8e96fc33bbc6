#include "glintlab/glints/wang2020/wang2020_dpf.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>

#include <fmt/format.h>

#include "glintlab/core/disk_cache.h"
#include "glintlab/core/error.h"
#include "glintlab/core/progress.h"
#include "glintlab/glints/wang2020/wang2020_beckmann.h"

namespace glintlab::wang2020 {

namespace {

constexpr double kHalfPi = 0.5 * kPi;
constexpr double kTwoPi = 2.0 * kPi;

double cone_solid_angle(double gamma) {
    return kTwoPi * (1.0 - std::cos(gamma));
}

// Orthonormal basis around a unit vector (Frisvad/Duff et al. 2017).
void basis(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
    const double s = n.z >= 0.0 ? 1.0 : -1.0;
    const double a = -1.0 / (s + n.z);
    const double c = n.x * n.y * a;
    t = {1.0 + s * n.x * n.x * a, s * c, -s * n.x};
    b = {c, s + n.y * n.y * a, -n.y};
}

}  // namespace

DpfTable::DpfTable(DpfResolution res, std::vector<float> values)
    : res_(res), values_(std::move(values)) {}

float DpfTable::at(int ti, int to, int p) const {
    return values_[(static_cast<size_t>(ti) * res_.theta_o + to) * res_.phi + p];
}

double DpfTable::lookup_angles(double theta_i, double theta_o, double dphi) const {
    if (values_.empty() || !(theta_i < kHalfPi) || !(theta_o < kHalfPi) || !std::isfinite(dphi))
        return 0.0;  // below the horizon or non-finite input (no NaN → int casts)
    // Cell-centred samples: coordinate x = θ / (π/2) · n − 0.5.
    auto split = [](double x, int n, int& i0, int& i1, double& f) {
        x = std::clamp(x, 0.0, static_cast<double>(n - 1));
        i0 = std::min(static_cast<int>(x), n - 1);
        i1 = std::min(i0 + 1, n - 1);
        f = x - i0;
    };
    int a0, a1, b0, b1;
    double fa, fb;
    split(theta_i / kHalfPi * res_.theta_i - 0.5, res_.theta_i, a0, a1, fa);
    split(theta_o / kHalfPi * res_.theta_o - 0.5, res_.theta_o, b0, b1, fb);
    double xp = dphi / kTwoPi * res_.phi - 0.5;
    xp -= std::floor(xp / res_.phi) * res_.phi;
    const int p0 = std::min(static_cast<int>(xp), res_.phi - 1);
    const int p1 = (p0 + 1) % res_.phi;
    const double fp = xp - p0;
    auto lerp_phi = [&](int ti, int to) {
        return (1.0 - fp) * at(ti, to, p0) + fp * at(ti, to, p1);
    };
    const double v0 = (1.0 - fb) * lerp_phi(a0, b0) + fb * lerp_phi(a0, b1);
    const double v1 = (1.0 - fb) * lerp_phi(a1, b0) + fb * lerp_phi(a1, b1);
    return (1.0 - fa) * v0 + fa * v1;
}

double DpfTable::lookup(const glm::dvec3& wi, const glm::dvec3& wo) const {
    if (!(wi.z > 0.0) || !(wo.z > 0.0)) return 0.0;
    const double ti = std::acos(std::min(1.0, wi.z));
    const double to = std::acos(std::min(1.0, wo.z));
    const double dphi = std::atan2(wo.y, wo.x) - std::atan2(wi.y, wi.x);
    return lookup_angles(ti, to, dphi);
}

double dpf_exact(const glm::dvec3& wi, const glm::dvec3& wo, double alpha, double gamma_rad) {
    if (!(wi.z > 0.0) || !(wo.z > 0.0)) return 0.0;
    const glm::dvec3 hs = wi + wo;
    const double len = glm::length(hs);
    if (len < 1e-12) return 0.0;
    const glm::dvec3 h = hs / len;
    const double ih = std::max(glm::dot(wi, h), 1e-12);
    // P = D(h)(h·n) σ(Ωo) / (4 (i·h))  (Eq. 6, N → ∞; see header).
    const double p = beckmann_D(h.z, alpha) * h.z * cone_solid_angle(gamma_rad) / (4.0 * ih);
    return std::min(p, 1.0);  // a probability
}

DpfTable generate_dpf_table(double alpha, double gamma_rad, DpfResolution res) {
    if (res.theta_i < 2 || res.theta_o < 2 || res.phi < 2)
        fail("wang2020: DPF table resolution {}x{}x{} must be at least 2 in every dimension",
             res.theta_i, res.theta_o, res.phi);
    std::vector<float> v(static_cast<size_t>(res.theta_i) * res.theta_o * res.phi);
    size_t k = 0;
    for (int a = 0; a < res.theta_i; ++a) {
        const glm::dvec3 wi = spherical_dir((a + 0.5) / res.theta_i * kHalfPi, 0.0);
        for (int b = 0; b < res.theta_o; ++b) {
            const double to = (b + 0.5) / res.theta_o * kHalfPi;
            for (int p = 0; p < res.phi; ++p) {
                const glm::dvec3 wo = spherical_dir(to, (p + 0.5) / res.phi * kTwoPi);
                v[k++] = static_cast<float>(dpf_exact(wi, wo, alpha, gamma_rad));
            }
        }
    }
    return DpfTable(res, std::move(v));
}

size_t DpfSet::memory_bytes() const {
    size_t s = 0;
    for (const auto& t : tables) s += t.memory_bytes();
    return s;
}

namespace {

// Bump when generate_dpf_table or dpf_exact change their output: cached
// tables of an older version are then never read (the key changes).
constexpr uint32_t kDpfTableVersion = 1;

uint64_t dpf_cache_key(DpfResolution res, double gamma_rad) {
    CacheKey key("wang2020_dpf", kDpfTableVersion);
    key.add(res.theta_i).add(res.theta_o).add(res.phi).add(gamma_rad);
    for (double a : kRoughnessSet) key.add(a);
    return key.value();
}

}  // namespace

DpfSet load_or_build_dpf_set(DpfResolution res) {
    const auto t0 = std::chrono::steady_clock::now();
    DpfSet set;
    set.res = res;
    set.gamma_rad = kPi / 180.0;  // γ = 1° (§4.4)
    const uint64_t key = dpf_cache_key(res, set.gamma_rad);
    const size_t cells = size_t(res.theta_i) * size_t(res.theta_o) * size_t(res.phi);
    bool loaded = false;
    if (const auto bytes = disk_cache_load("wang2020_dpf", key)) {
        ByteReader in(*bytes);
        loaded = true;
        for (size_t r = 0; r < kRoughnessSet.size() && loaded; ++r) {
            std::vector<float> v;
            loaded = in.get_vector(v) && v.size() == cells;
            if (loaded) set.tables[r] = DpfTable(res, std::move(v));
        }
        loaded = loaded && in.at_end();
    }
    if (!loaded) {
        ProgressReporter progress(int64_t(kRoughnessSet.size()),
                                  fmt::format("wang2020 DPF tables {}x{}x{} (cached afterwards)",
                                              res.theta_i, res.theta_o, res.phi),
                                  false);
        ByteWriter out;
        for (size_t r = 0; r < kRoughnessSet.size(); ++r) {
            set.tables[r] = generate_dpf_table(kRoughnessSet[r], set.gamma_rad, res);
            out.put_vector(set.tables[r].values());
            progress.update();
        }
        progress.done();
        disk_cache_store("wang2020_dpf", key, out.bytes);
    }
    set.build_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return set;
}

DpfTable load_or_extract_dpf(const DpfSet& set, double alpha, double gamma_rad,
                             DpfRoughness roughness) {
    CacheKey key("wang2020_dpf_extract", kDpfTableVersion);
    key.add(dpf_cache_key(set.res, set.gamma_rad)).add(alpha).add(gamma_rad);
    if (roughness == DpfRoughness::Exact) key.add(std::string_view("exact roughness"));
    const DpfResolution res = set.res;
    const size_t cells = size_t(res.theta_i) * size_t(res.theta_o) * size_t(res.phi);
    if (const auto bytes = disk_cache_load("wang2020_dpf_extract", key.value())) {
        ByteReader in(*bytes);
        std::vector<float> v;
        if (in.get_vector(v) && v.size() == cells && in.at_end())
            return DpfTable(res, std::move(v));
    }
    ProgressReporter progress(1,
                              fmt::format("wang2020 DPF for roughness {:.3g}, gamma {:.3g} deg "
                                          "(cached afterwards)",
                                          alpha, gamma_rad * 180.0 / kPi),
                              false);
    DpfTable t = extract_dpf(set, alpha, gamma_rad, roughness);
    progress.update();
    progress.done();
    ByteWriter out;
    out.put_vector(t.values());
    disk_cache_store("wang2020_dpf_extract", key.value(), out.bytes);
    return t;
}

const DpfSet& dpf_set(DpfResolution res) {
    static std::mutex mutex;
    static std::map<std::tuple<int, int, int>, std::unique_ptr<DpfSet>> cache;
    const std::lock_guard lock(mutex);
    auto& slot = cache[{res.theta_i, res.theta_o, res.phi}];
    if (!slot) slot = std::make_unique<DpfSet>(load_or_build_dpf_set(res));
    return *slot;
}

DpfTable extract_dpf(const DpfSet& set, double alpha, double gamma_rad, DpfRoughness roughness) {
    // A scene's roughness is a float: its 0.02 is 0.0199999996, the first
    // table's roughness up to float rounding.
    if (alpha >= double(float(kRoughnessSet.front())) && alpha < kRoughnessSet.front())
        alpha = kRoughnessSet.front();
    if (!(alpha >= kRoughnessSet.front() && alpha <= kRoughnessSet.back()))
        fail("wang2020: roughness {} outside the tabulated range [0.02, 1]", alpha);
    const double gamma_max = 30.0 * kPi / 180.0;
    if (!(gamma_rad >= set.gamma_rad * (1.0 - 1e-9) && gamma_rad <= gamma_max))
        fail("wang2020: gamma {} deg outside [1, 30] deg", gamma_rad * 180.0 / kPi);
    const auto& res = set.res;
    auto interpolated = [&] {
        // Roughness interpolation (linear in α between bracketing tables).
        size_t hi = 1;
        while (hi + 1 < kRoughnessSet.size() && kRoughnessSet[hi] < alpha) ++hi;
        const size_t lo = hi - 1;
        const double w = (alpha - kRoughnessSet[lo]) / (kRoughnessSet[hi] - kRoughnessSet[lo]);
        const auto& vl = set.tables[lo].values();
        const auto& vh = set.tables[hi].values();
        std::vector<float> mixed(vl.size());
        for (size_t k = 0; k < vl.size(); ++k)
            mixed[k] = static_cast<float>((1.0 - w) * vl[k] + w * vh[k]);
        return DpfTable(res, std::move(mixed));
    };
    const DpfTable base = roughness == DpfRoughness::Exact
                              ? generate_dpf_table(alpha, set.gamma_rad, res)
                              : interpolated();
    if (gamma_rad <= set.gamma_rad * (1.0 + 1e-9)) return base;

    // γ accumulation: P_γ(i, o) = ∫_{cone(o, γ)} P_1(i, o') / σ_1 do', a sum
    // of 1° cells over the γ cone. Ring quadrature: R rings of equal angular
    // width, 6k points on ring k, each weighted by its share of the ring's
    // solid angle.
    const double sigma1 = cone_solid_angle(set.gamma_rad);
    const int rings = std::max(2, static_cast<int>(std::ceil(gamma_rad / set.gamma_rad)));
    std::vector<float> out(base.values().size());
    size_t k = 0;
    for (int a = 0; a < res.theta_i; ++a) {
        const glm::dvec3 wi = spherical_dir((a + 0.5) / res.theta_i * kHalfPi, 0.0);
        for (int b = 0; b < res.theta_o; ++b) {
            const double to = (b + 0.5) / res.theta_o * kHalfPi;
            for (int p = 0; p < res.phi; ++p) {
                const glm::dvec3 wo = spherical_dir(to, (p + 0.5) / res.phi * kTwoPi);
                glm::dvec3 t, bt;
                basis(wo, t, bt);
                double sum = 0.0;
                for (int r = 1; r <= rings; ++r) {
                    const double psi0 = (r - 1) * gamma_rad / rings;
                    const double psi1 = r * gamma_rad / rings;
                    const double psi = 0.5 * (psi0 + psi1);
                    const int n = 6 * r;
                    const double dw = kTwoPi * (std::cos(psi0) - std::cos(psi1)) / n;
                    for (int j = 0; j < n; ++j) {
                        const double ph = (j + 0.5 * (r & 1)) * kTwoPi / n;
                        const glm::dvec3 d = std::cos(psi) * wo +
                                             std::sin(psi) * (std::cos(ph) * t + std::sin(ph) * bt);
                        sum += base.lookup(wi, d) * dw;
                    }
                }
                out[k++] = static_cast<float>(std::min(1.0, sum / sigma1));
            }
        }
    }
    return DpfTable(res, std::move(out));
}

}  // namespace glintlab::wang2020
