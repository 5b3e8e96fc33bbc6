#include "glintlab/glints/wang2020/wang2020_gpu_passes.h"

#include <chrono>
#include <memory>
#include <variant>

#include <epoxy/gl.h>

#include "glintlab/core/error.h"
#include "glintlab/gl/gl_handles.h"
#include "glintlab/gl/gpu_timer.h"
#include "glintlab/glints/wang2020/wang2020_gpu_blur.h"
#include "glintlab/glints/wang2020/wang2020_model.h"
#include "glintlab/glints/wang2020/wang2020_shading.h"
#include "glintlab/scene/scene.h"

namespace glintlab::gl {

void time_wang2020_passes(const Scene& scene, const Image& frame, int frames,
                          std::map<std::string, std::vector<double>>& passes) {
    const GlintDesc* desc = nullptr;
    for (const MaterialDesc& m : scene.materials)
        if (m.type == MaterialDesc::Type::Glint && m.glint.model_id == GlintModelId::Wang2020) {
            desc = &m.glint;
            break;
        }
    if (desc == nullptr) fail("bench: the scene has no wang2020 material");
    std::shared_ptr<const EnvironmentMap> env;
    for (const Light& l : scene.lights)
        if (const auto* e = std::get_if<EnvironmentLight>(&l)) {
            env = e->map;
            break;
        }
    // The cached model GpuRenderer uploaded: its build times are the passes.
    const auto model = wang2020_model_for(*desc, env);
    passes["dpf_extract_ms"].push_back(1e3 * model->extract_seconds());
    passes["quadtree_ms"].push_back(1e3 * model->quadtree().build_seconds());
    if (model->prefiltered() != nullptr)
        passes["prefilter_ms"].push_back(1e3 * model->prefiltered()->build_seconds());

    // §4.4 blurs on the frame (rgb = the frame, visibility 1).
    std::vector<glm::vec4> texels(frame.pixels.size());
    for (size_t i = 0; i < texels.size(); ++i) texels[i] = glm::vec4(frame.pixels[i], 1.0f);
    Texture tex = make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(tex.get(), 1, GL_RGBA32F, frame.width, frame.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(tex.get(), 0, 0, 0, frame.width, frame.height, GL_RGBA, GL_FLOAT,
                        texels.data());
    GpuWang2020Blur blur;
    blur.apply(tex.get(), frame.width, frame.height);  // warm-up
    glFinish();
    std::vector<double> ms;
    for (int f = 0; f < frames; ++f) {
        const auto t0 = std::chrono::steady_clock::now();
        blur.apply(tex.get(), frame.width, frame.height);
        glFinish();
        ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count());
    }
    passes["blur_ms"].push_back(timing_stats(ms).median_ms);
}

}  // namespace glintlab::gl
