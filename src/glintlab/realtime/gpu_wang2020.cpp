#include "glintlab/realtime/gpu_wang2020.h"

#include <cmath>
#include <variant>
#include <vector>

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include "glintlab/core/error.h"
#include "glintlab/glints/wang2020/wang2020_model.h"
#include "glintlab/glints/wang2020/wang2020_shading.h"
#include "glintlab/realtime/uniform_cache.h"
#include "glintlab/scene/scene.h"

namespace glintlab::gl {
namespace {

constexpr const char* kGlue = R"(
#include "glintlab/glints/wang2020/wang2020_tables.glsl"
#define GLINTLAB_GLINT_OWN_LIGHTS 1
// The CPU's arrays (gpu_wang2020.cpp): DpfTable::values(),
// PrefilterTable::data(), ParticleQuadtree::nodes().
layout(std430, binding = 1) readonly buffer Wang2020Dpf { float u_wang2020_dpf[]; };
layout(std430, binding = 2) readonly buffer Wang2020Prefilter { vec4 u_wang2020_prefilter[]; };
layout(std430, binding = 3) readonly buffer Wang2020Nodes { uvec2 u_wang2020_nodes[]; };
layout(std430, binding = 4) readonly buffer Wang2020Cone { vec4 u_wang2020_cone[]; };
float wang2020_dpf_value(int index) { return u_wang2020_dpf[index]; }
vec4 wang2020_prefilter_value(int index) { return u_wang2020_prefilter[index]; }
uvec2 wang2020_node(int index) { return u_wang2020_nodes[index]; }
vec4 wang2020_cone_value(int index) { return u_wang2020_cone[index]; }
uniform ivec3 u_wang2020_dpf_res;
uniform ivec4 u_wang2020_prefilter_res;
uniform int u_wang2020_depth;
uniform uint u_wang2020_seed;
uniform float u_wang2020_particles;
uniform float u_wang2020_sigma;
uniform int u_wang2020_micro;
uniform ivec2 u_wang2020_cone_res;
uniform float u_wang2020_cos_gamma;
Wang2020Tables wang2020_tables() {
    Wang2020Tables t;
    t.dpf_res = u_wang2020_dpf_res;
    t.prefilter_res = u_wang2020_prefilter_res;
    t.depth = u_wang2020_depth;
    t.seed = u_wang2020_seed;
    t.particles = u_wang2020_particles;
    t.sigma = u_wang2020_sigma;
    t.alpha = u_glint_alpha.x;
    t.micro = u_wang2020_micro;
    t.cone_res = u_wang2020_cone_res;
    t.cos_gamma = u_wang2020_cos_gamma;
    return t;
}
// Eq. 21 (the CPU's wang2020_light_radiance, untinted).
vec3 glint_own_light(vec3 wo, vec3 wi, vec3 li, Footprint fp) {
    vec2 lo, hi;
    wang2020_footprint_box(fp, lo, hi);
    return wang2020_light(wang2020_tables(), lo, hi, wi, wo, li);
}
// Eqs. 18-20 (untinted; no directional occlusion on the GPU).
vec3 glint_own_environment(vec3 n, vec3 o_world, Footprint fp) {
    vec2 lo, hi;
    wang2020_footprint_box(fp, lo, hi);
    return wang2020_environment(wang2020_tables(), lo, hi, n, o_world);
}
// The smooth Beckmann limit (the CPU GlintBxdf's wang2020 case). eval_bsdf
// needs these, but every light of the forward pass (point, sphere as point,
// directional, environment) goes through the functions above for wang2020.
vec3 glint_ndf(vec3 h, Footprint fp) {
    return vec3(D_Microfacet(u_glint_ndf, h, u_glint_alpha.x, u_glint_alpha.y));
}
float glint_masking(vec3 wo, vec3 wi, vec3 h) {
    return G2_SmithCorrelated(u_glint_ndf, wo, wi, u_glint_alpha.x, u_glint_alpha.y);
}
)";

static_assert(kWang2020DpfBinding == 1 && kWang2020PrefilterBinding == 2 &&
              kWang2020NodeBinding == 3 &&
              kWang2020ConeBinding == 4);  // the layout qualifiers above

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

std::string wang2020_glsl() {
    return kGlue;
}

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
        cone_ = model->cone_average() != nullptr
                    ? upload(model->cone_average()->data(), "cone-averaged environment")
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
    const bool per_particle = model_->material().micro == wang2020::MicroMode::PerParticle;
    glProgramUniform1i(program, loc("u_wang2020_micro"), per_particle ? 1 : 0);
    const glm::ivec2 cres =
        model_->cone_average() != nullptr
            ? glm::ivec2(model_->cone_average()->width(), model_->cone_average()->height())
            : glm::ivec2(1);
    glProgramUniform2i(program, loc("u_wang2020_cone_res"), cres.x, cres.y);
    glProgramUniform1f(program, loc("u_wang2020_cos_gamma"),
                       static_cast<float>(std::cos(model_->material().gamma_deg *
                                                   3.14159265358979323846 / 180.0)));
}

}  // namespace glintlab::gl
