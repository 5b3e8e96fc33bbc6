#include "glintlab/glints/wang2020/wang2020_postprocess.h"

#include <algorithm>
#include <cmath>

#include "glintlab/core/error.h"

namespace glintlab::wang2020 {

std::vector<float> gaussian_blur(const std::vector<float>& img, int w, int h, int size) {
    if (size < 1 || size % 2 == 0) fail("wang2020: blur size {} must be odd and >= 1", size);
    if (w < 1 || h < 1 || img.size() != static_cast<size_t>(w) * h)
        fail("wang2020: blur image {}x{} does not match {} texels", w, h, img.size());
    const int r = size / 2;
    const double sigma = size / 6.0;
    std::vector<double> k(static_cast<size_t>(size));
    double sum = 0.0;
    for (int i = -r; i <= r; ++i) sum += k[i + r] = std::exp(-0.5 * i * i / (sigma * sigma));
    for (double& v : k) v /= sum;
    std::vector<float> tmp(img.size()), out(img.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double s = 0.0;
            for (int i = -r; i <= r; ++i)
                s += k[i + r] * img[static_cast<size_t>(y) * w + std::clamp(x + i, 0, w - 1)];
            tmp[static_cast<size_t>(y) * w + x] = static_cast<float>(s);
        }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double s = 0.0;
            for (int i = -r; i <= r; ++i)
                s += k[i + r] * tmp[static_cast<size_t>(std::clamp(y + i, 0, h - 1)) * w + x];
            out[static_cast<size_t>(y) * w + x] = static_cast<float>(s);
        }
    return out;
}

GlintBuffer postprocess_glints(const GlintBuffer& in, int occlusion_size, int glint_size) {
    const size_t n = in.texels.size();
    std::vector<float> vis(n);
    for (size_t i = 0; i < n; ++i) vis[i] = in.texels[i].w;
    const std::vector<float> delta = gaussian_blur(vis, in.width, in.height, occlusion_size);
    GlintBuffer out{in.width, in.height, std::vector<glm::vec4>(n)};
    for (int c = 0; c < 3; ++c) {
        std::vector<float> ch(n);
        for (size_t i = 0; i < n; ++i) ch[i] = in.texels[i][c] * delta[i];
        const std::vector<float> b = gaussian_blur(ch, in.width, in.height, glint_size);
        for (size_t i = 0; i < n; ++i) out.texels[i][c] = b[i];
    }
    for (size_t i = 0; i < n; ++i) out.texels[i].w = delta[i];
    return out;
}

}  // namespace glintlab::wang2020
