#include "glintlab/scene/environment_mips.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "glintlab/core/error.h"

namespace glintlab {

namespace {

// The overlap of fine cell i (of n over [0, 1]) with coarse cell j (of m),
// for the fine cells that meet cell j.
struct Overlap {
    int first = 0, last = 0;  // fine cells [first, last)
};
Overlap overlapping(int j, int m, int n) {
    return {static_cast<int>(int64_t(j) * n / m),
            static_cast<int>((int64_t(j + 1) * n + m - 1) / m)};
}
double overlap_length(double a0, double a1, double b0, double b1) {
    return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}

}  // namespace

std::vector<Image> latlong_mip_chain(const Image& level0) {
    if (level0.width < 1 || level0.height < 1) fail("environment mip chain: empty image");
    constexpr double pi = std::numbers::pi;
    std::vector<Image> chain{level0};
    while (chain.back().width > 1 || chain.back().height > 1) {
        const Image& fine = chain.back();
        const int fw = fine.width, fh = fine.height;
        const int w = std::max(1, fw / 2), h = std::max(1, fh / 2);
        Image coarse(w, h);
        for (int y = 0; y < h; ++y) {
            const double t0 = pi * y / h, t1 = pi * (y + 1) / h;
            const double band = std::cos(t0) - std::cos(t1);
            const Overlap rows = overlapping(y, h, fh);
            for (int x = 0; x < w; ++x) {
                const double u0 = double(x) / w, u1 = double(x + 1) / w;
                const Overlap cols = overlapping(x, w, fw);
                glm::dvec3 sum(0.0);
                for (int fy = rows.first; fy < rows.last; ++fy) {
                    // cos θ is monotonic: the overlap of two bands in θ is
                    // the band between the inner bounds.
                    const double a = std::max(t0, pi * fy / fh),
                                 b = std::min(t1, pi * (fy + 1) / fh);
                    if (!(b > a)) continue;
                    const double row = (std::cos(a) - std::cos(b)) / band;
                    for (int fx = cols.first; fx < cols.last; ++fx) {
                        const double col =
                            overlap_length(u0, u1, double(fx) / fw, double(fx + 1) / fw) * w;
                        sum += row * col * glm::dvec3(fine.at(fx, fy));
                    }
                }
                coarse.at(x, y) = glm::vec3(sum);
            }
        }
        chain.push_back(std::move(coarse));
    }
    return chain;
}

}  // namespace glintlab
