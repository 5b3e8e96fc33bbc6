#include "glintlab/glints/wang2020/wang2020_gpu.h"

#include <cmath>
#include <variant>
#include <vector>

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include "glintlab/core/error.h"
#include "glintlab/gl/uniform_cache.h"
#include "glintlab/glints/wang2020/wang2020_model.h"
#include "glintlab/glints/wang2020/wang2020_shading.h"
#include "glintlab/scene/scene.h"

namespace glintlab::gl {
namespace {

static_assert(kWang2020DpfBinding == 1 && kWang2020PrefilterBinding == 2 &&
              kWang2020NodeBinding == 3 &&
              kWang2020ConeBinding == 4);  // the layout qualifiers of wang2020_gpu.glsl

template <typename T>
Buffer upload(const std::vector<T>& data, const char* what) {
    if (data.empty()) fail("OpenGL renderer: wang2020 {} table is empty", what);
    GLint max_size = 0;
    glGetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &max_size);
    const size_t bytes = data.size() * sizeof(T);
    if (bytes > static_cast<size_t>(max_size))
        fail(
            "OpenGL renderer: the wang2020 {} table ({} bytes) exceeds "
            "GL_MAX_SHADER_STORAGE_BLOCK_SIZE = {}; lower its resolution or the quadtree depth",
            what, bytes, max_size);
    Buffer b = make_buffer();
    glNamedBufferStorage(b.get(), static_cast<GLsizeiptr>(bytes), data.data(), 0);
    return b;
}

}  // namespace

void Wang2020Resources::bind(unsigned program, UniformCache& u, const GlintDesc& desc,
                             const Scene& scene) {
    std::shared_ptr<const EnvironmentMap> env;
    for (const Light& l : scene.lights)
        if (const auto* e = std::get_if<EnvironmentLight>(&l)) {
            env = e->map;
            break;
        }
    auto model = wang2020_model_for(desc, env);
    if (model != model_) {
        dpf_ = upload(model->dpf().values(), "DPF");
        // Without an environment the shader never reads L̂o/P̂: one texel.
        prefilter_ = model->prefiltered() != nullptr
                         ? upload(model->prefiltered()->data(), "prefiltered environment")
                         : upload(std::vector<glm::vec4>(1, glm::vec4(0.0f)), "prefiltered");
        std::vector<glm::uvec2> nodes;
        nodes.reserve(model->quadtree().nodes().size());
        for (const wang2020::QuadtreeNode& n : model->quadtree().nodes())
            nodes.emplace_back(n.first_child, n.count_mask);
        nodes_ = upload(nodes, "quadtree");
        // L_γ exists for "micro": "per_particle" under an environment only.
        cone_ = model->particle_radiance_table() != nullptr
                    ? upload(model->particle_radiance_table()->data(), "cone-averaged environment")
                    : upload(std::vector<glm::vec4>(1, glm::vec4(0.0f)), "cone-averaged");
        model_ = std::move(model);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWang2020DpfBinding, dpf_.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWang2020PrefilterBinding, prefilter_.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWang2020NodeBinding, nodes_.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWang2020ConeBinding, cone_.get());
    auto loc = [&](const char* name) { return u.location(program, name); };
    const wang2020::DpfResolution& d = model_->dpf().resolution();
    glProgramUniform3i(program, loc("u_wang2020_dpf_res"), d.theta_i, d.theta_o, d.phi);
    glm::ivec4 pres(1);
    if (model_->prefiltered() != nullptr) {
        const wang2020::PrefilterResolution& p = model_->prefiltered()->resolution();
        pres = {p.theta_n, p.phi_n, p.theta_o, p.phi_o};
    }
    glProgramUniform4i(program, loc("u_wang2020_prefilter_res"), pres.x, pres.y, pres.z, pres.w);
    glProgramUniform1i(program, loc("u_wang2020_depth"), model_->quadtree().depth());
    glProgramUniform1ui(program, loc("u_wang2020_seed"), model_->material().seed);
    glProgramUniform1f(program, loc("u_wang2020_particles"),
                       static_cast<float>(model_->quadtree().particles()));
    glProgramUniform1f(program, loc("u_wang2020_sigma"), static_cast<float>(model_->sigma_o()));
    glProgramUniform1i(program, loc("u_wang2020_micro"), model_->micro_mode_index());
    const glm::ivec2 cres = model_->particle_radiance_table() != nullptr
                                ? glm::ivec2(model_->particle_radiance_table()->width(),
                                             model_->particle_radiance_table()->height())
                                : glm::ivec2(1);
    glProgramUniform2i(program, loc("u_wang2020_cone_res"), cres.x, cres.y);
    glProgramUniform1f(program, loc("u_wang2020_cos_gamma"),
                       static_cast<float>(std::cos(model_->material().gamma_deg *
                                                   3.14159265358979323846 / 180.0)));
}

}  // namespace glintlab::gl
