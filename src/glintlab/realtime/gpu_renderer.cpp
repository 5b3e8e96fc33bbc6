#include "glintlab/realtime/gpu_renderer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>

#include <epoxy/gl.h>
#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "glintlab/core/error.h"
#include "glintlab/gl/gl_context.h"
#include "glintlab/gl/gl_handles.h"
#include "glintlab/gl/gl_program.h"
#include "glintlab/gl/gpu_timer.h"
#include "glintlab/gl/uniform_cache.h"
#include "glintlab/glints/glint_bxdf.h"
#include "glintlab/glints/gpu_model_hooks.h"
#include "glintlab/realtime/forward_shaders.h"
#include "glintlab/realtime/glint_programs.h"
#include "glintlab/realtime/gpu_geometry.h"
#include "glintlab/scene/environment_mips.h"
#include "glintlab/scene/environment_sources.h"

namespace glintlab {
namespace {

constexpr GLuint kLoopProbeBinding = 5;  // forward.frag.glsl LoopProbe

struct GpuShape {
    gl::VertexArray vao;
    gl::Buffer vertices, indices, triangles;
    GLsizei index_count = 0;
    bool per_triangle_frame = false;
    bool closed = false;  // GpuMeshData::closed
    bool has_normals = true;
};

GpuShape upload_shape(const Shape& shape, int sphere_segments) {
    const GpuMeshData data = gpu_mesh_data(shape, sphere_segments);
    GpuShape g;
    g.vao = gl::make_vertex_array();
    g.vertices = gl::make_buffer();
    g.indices = gl::make_buffer();
    glNamedBufferStorage(g.vertices.get(),
                         static_cast<GLsizeiptr>(data.vertices.size() * sizeof(GpuVertex)),
                         data.vertices.data(), 0);
    glNamedBufferStorage(g.indices.get(),
                         static_cast<GLsizeiptr>(data.indices.size() * sizeof(uint32_t)),
                         data.indices.data(), 0);
    const GLuint vao = g.vao.get();
    glVertexArrayVertexBuffer(vao, 0, g.vertices.get(), 0, sizeof(GpuVertex));
    glVertexArrayElementBuffer(vao, g.indices.get());
    const GLuint offsets[4] = {offsetof(GpuVertex, position), offsetof(GpuVertex, normal),
                               offsetof(GpuVertex, uv), offsetof(GpuVertex, dpdu)};
    const GLint sizes[4] = {3, 3, 2, 4};
    for (GLuint a = 0; a < 4; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
        glVertexArrayAttribBinding(vao, a, 0);
    }
    if (!data.triangles.empty()) {
        g.triangles = gl::make_buffer();
        glNamedBufferStorage(
            g.triangles.get(),
            static_cast<GLsizeiptr>(data.triangles.size() * sizeof(GpuTriangleFrame)),
            data.triangles.data(), 0);
    }
    g.index_count = static_cast<GLsizei>(data.indices.size());
    g.per_triangle_frame = data.per_triangle_frame;
    g.closed = data.closed;
    g.has_normals = data.has_normals;
    return g;
}

// The shape's normal turns over its surface (a sphere, a mesh whose vertex
// normals differ): a glint material on it widens its α by the footprint's
// normal covariance (docs/MODELS.md, "Curved surfaces").
bool shape_is_curved(const Shape& shape) {
    if (std::holds_alternative<SphereGeometry>(shape.geometry)) return true;
    const TriangleMesh& mesh = std::get<TriangleMesh>(shape.geometry);
    for (const glm::vec3& n : mesh.normals)
        if (glm::dot(n - mesh.normals.front(), n - mesh.normals.front()) > 1e-12f) return true;
    return false;
}

// `model_options`: the renderer's option mask of each model (set_model_option).
gl::ProgramKey program_key(const Scene& scene, const Shape& shape,
                           const std::map<GlintModelId, unsigned>& model_options) {
    gl::ProgramKey key;
    if (shape.material >= 0) {
        const MaterialDesc& m = scene.materials[static_cast<size_t>(shape.material)];
        if (m.type == MaterialDesc::Type::Glint) key.model = m.glint.model_id;
        key.material_textures = m.textures != nullptr || m.glint.textures != nullptr;
        key.normal_map = m.normal_map != nullptr;
        if (m.normal_map && m.normal_map->filtering == NormalMap::Filtering::LeanMixture)
            key.normal_map_mixture = m.normal_map->mixture;
        key.curvature = m.type == MaterialDesc::Type::Glint && m.glint.curvature &&
                        glint_model(m.glint.model_id).filters_curvature && shape_is_curved(shape);
    }
    const auto it = model_options.find(key.model);
    const GpuModelHooks* hooks = find_gpu_model_hooks(key.model);
    if (it != model_options.end() && hooks != nullptr)
        key.model_options = it->second & hooks->program_option_mask();
    for (const Light& light : scene.lights) {
        if (std::holds_alternative<PointLight>(light) || std::holds_alternative<SphereLight>(light))
            ++key.point_lights;
        if (std::holds_alternative<DirectionalLight>(light)) ++key.directional_lights;
        if (std::holds_alternative<EnvironmentLight>(light)) key.environment = true;
    }
    return key;
}

// A glint material whose model defers part of its shading to the glint
// layer (GpuModelHooks::uses_glint_layer; wang2020 with "blur" on).
bool uses_glint_layer(const MaterialDesc& m) {
    if (m.type != MaterialDesc::Type::Glint) return false;
    const GpuModelHooks* hooks = find_gpu_model_hooks(m.glint.model_id);
    return hooks != nullptr && hooks->uses_glint_layer != nullptr &&
           hooks->uses_glint_layer(m.glint);
}

int ndf_code(NdfType t) {
    return t == NdfType::GGX ? 1 : 0;
}  // ndf.glsl NDF_GGX / NDF_BECKMANN

}  // namespace

struct GpuRenderer::Impl {
    std::vector<GpuShape> shapes;
    glm::vec4 bounds{0.0f};
    gl::Texture environment;
    // The map without its bright sources when it has any (else the lobe
    // reads `environment`), and the sources' sample directions and powers.
    gl::Texture environment_residual;
    std::vector<glm::vec3> source_directions, source_powers;
    float environment_scale = 1.0f, environment_rotation = 0.0f;
    int environment_width = 0, environment_height = 0;
    std::map<gl::ProgramKey, gl::Program> programs;
    // Material textures by their CPU texture (kept alive so the key stays unique).
    std::map<const MipTexture*, std::pair<std::shared_ptr<const MipTexture>, gl::Texture>>
        material_textures;
    gl::Program background;
    gl::UniformCache uniforms;
    // The forward pass's count of fragments whose loops the implementation
    // cut short (forward.frag.glsl u_cut_fragments), binding 5.
    gl::Buffer loop_probe;
    // Each model's GPU state (GpuModelHooks::make_state, made on first use)
    // and option mask (set_model_option).
    std::map<GlintModelId, std::unique_ptr<GpuModelState>> model_states;
    std::map<GlintModelId, unsigned> model_options;
    gl::Framebuffer fbo;
    gl::Texture color, depth;
    int width = 0, height = 0;
    gl::PassTimer shadow_timer, background_timer, forward_timer, glint_post_timer;
    // The glint layer (GpuModelHooks::uses_glint_layer): the forward pass
    // writes the deferred environment glints of such materials into
    // `glint_layer` (colour attachment 1, created on first use), which the
    // model's GpuModelState::post_pass adds into `color` (wang2020's §4.4
    // blurs).
    gl::Texture glint_layer;
    bool glint_post_frame = false;  // the last render() ran a post pass
    // Shadow maps (realtime/shaders/forward.frag.glsl directional_visibility).
    bool shadows = true;
    gl::Program shadow_program;
    gl::Framebuffer shadow_fbo;
    gl::Texture shadow_maps;
    int shadow_layers = 0;
    std::vector<glm::mat4> shadow_matrices;
    float shadow_texel = 0.0f, shadow_depth_range = 1.0f;
    gl::Texture point_shadow_maps;
    int point_shadow_cubes = 0;
    std::vector<float> point_near, point_far;  // empty: no point shadows this frame

    // One depth cube per point/sphere light, in set_lights' order; a sphere
    // light's own shape is not drawn into its cube.
    void render_point_shadow_maps(const Scene& scene) {
        point_near.clear();
        point_far.clear();
        struct Source {
            glm::vec3 position;
            int light;
        };
        std::vector<Source> sources;
        for (size_t i = 0; i < scene.lights.size(); ++i) {
            if (const auto* l = std::get_if<PointLight>(&scene.lights[i]))
                sources.push_back({l->position, static_cast<int>(i)});
            else if (const auto* l = std::get_if<SphereLight>(&scene.lights[i]))
                sources.push_back({l->center, static_cast<int>(i)});
        }
        if (!shadows || sources.empty()) return;
        const int cubes = static_cast<int>(sources.size());
        const int size = gl::kPointShadowSize;
        if (cubes != point_shadow_cubes) {
            point_shadow_maps = gl::make_texture(GL_TEXTURE_CUBE_MAP_ARRAY);
            glTextureStorage3D(point_shadow_maps.get(), 1, GL_DEPTH_COMPONENT32F, size, size,
                               6 * cubes);
            glTextureParameteri(point_shadow_maps.get(), GL_TEXTURE_COMPARE_MODE,
                                GL_COMPARE_REF_TO_TEXTURE);
            glTextureParameteri(point_shadow_maps.get(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
            glTextureParameteri(point_shadow_maps.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTextureParameteri(point_shadow_maps.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            point_shadow_cubes = cubes;
        }
        if (!shadow_fbo) {
            shadow_fbo = gl::make_framebuffer();
            glNamedFramebufferDrawBuffer(shadow_fbo.get(), GL_NONE);
            glNamedFramebufferReadBuffer(shadow_fbo.get(), GL_NONE);
        }
        // Cube face order +X -X +Y -Y +Z -Z with GL's face orientations.
        const glm::vec3 dirs[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                   {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
        const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1},
                                  {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
        const GLuint p = shadow_program.get();
        glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo.get());
        glViewport(0, 0, size, size);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.5f, 4.0f);
        glUseProgram(p);
        const glm::vec3 c(bounds);
        for (int i = 0; i < cubes; ++i) {
            const glm::vec3 o = sources[static_cast<size_t>(i)].position;
            const float far_plane = std::max(glm::length(o - c) + bounds.w * 1.01f, 1e-3f);
            const float near_plane = std::max(far_plane * 1e-4f, 1e-4f);
            point_near.push_back(near_plane);
            point_far.push_back(far_plane);
            const glm::mat4 proj =
                glm::perspective(glm::half_pi<float>(), 1.0f, near_plane, far_plane);
            for (int face = 0; face < 6; ++face) {
                glNamedFramebufferTextureLayer(shadow_fbo.get(), GL_DEPTH_ATTACHMENT,
                                               point_shadow_maps.get(), 0, 6 * i + face);
                glClear(GL_DEPTH_BUFFER_BIT);
                const glm::mat4 vp = proj * glm::lookAt(o, o + dirs[face], ups[face]);
                glProgramUniformMatrix4fv(p, uniforms.location(p, "u_light_view_projection"), 1,
                                          GL_FALSE, glm::value_ptr(vp));
                for (size_t k = 0; k < shapes.size(); ++k) {
                    if (scene.shapes[k].area_light == sources[static_cast<size_t>(i)].light)
                        continue;
                    glBindVertexArray(shapes[k].vao.get());
                    glDrawElements(GL_TRIANGLES, shapes[k].index_count, GL_UNSIGNED_INT, nullptr);
                }
            }
        }
        glDisable(GL_POLYGON_OFFSET_FILL);
    }

    // Renders one depth layer per directional light (none: shadow_matrices empty).
    void render_shadow_maps(const Scene& scene) {
        shadow_matrices.clear();
        std::vector<glm::vec3> directions;
        for (const Light& light : scene.lights)
            if (const auto* l = std::get_if<DirectionalLight>(&light))
                directions.push_back(l->direction);
        if (!shadows || directions.empty()) return;
        const int layers = static_cast<int>(directions.size());
        if (layers != shadow_layers) {
            shadow_maps = gl::make_texture(GL_TEXTURE_2D_ARRAY);
            glTextureStorage3D(shadow_maps.get(), 1, GL_DEPTH_COMPONENT32F, gl::kShadowMapSize,
                               gl::kShadowMapSize, layers);
            glTextureParameteri(shadow_maps.get(), GL_TEXTURE_COMPARE_MODE,
                                GL_COMPARE_REF_TO_TEXTURE);
            glTextureParameteri(shadow_maps.get(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
            glTextureParameteri(shadow_maps.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTextureParameteri(shadow_maps.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glTextureParameteri(shadow_maps.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTextureParameteri(shadow_maps.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            shadow_fbo = gl::make_framebuffer();
            glNamedFramebufferDrawBuffer(shadow_fbo.get(), GL_NONE);
            glNamedFramebufferReadBuffer(shadow_fbo.get(), GL_NONE);
            shadow_layers = layers;
        }
        const glm::vec3 c(bounds);
        const float radius = bounds.w * 1.01f;
        shadow_texel = 2.0f * radius / static_cast<float>(gl::kShadowMapSize);
        shadow_depth_range = 2.0f * radius;
        // [-1, 1]^3 -> [0, 1]^3.
        const glm::mat4 to_unit = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) *
                                  glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
        const GLuint p = shadow_program.get();
        glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo.get());
        glViewport(0, 0, gl::kShadowMapSize, gl::kShadowMapSize);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.5f, 4.0f);
        glUseProgram(p);
        for (int i = 0; i < layers; ++i) {
            const glm::vec3 d = glm::normalize(directions[static_cast<size_t>(i)]);
            const glm::vec3 up = std::abs(d.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
            const glm::mat4 vp =
                glm::ortho(-radius, radius, -radius, radius, radius, 3.0f * radius) *
                glm::lookAt(c + d * (2.0f * radius), c, up);
            shadow_matrices.push_back(to_unit * vp);
            glNamedFramebufferTextureLayer(shadow_fbo.get(), GL_DEPTH_ATTACHMENT, shadow_maps.get(),
                                           0, i);
            glClear(GL_DEPTH_BUFFER_BIT);
            glProgramUniformMatrix4fv(p, uniforms.location(p, "u_light_view_projection"), 1,
                                      GL_FALSE, glm::value_ptr(vp));
            for (const GpuShape& g : shapes) {
                glBindVertexArray(g.vao.get());
                glDrawElements(GL_TRIANGLES, g.index_count, GL_UNSIGNED_INT, nullptr);
            }
        }
        glDisable(GL_POLYGON_OFFSET_FILL);
    }
    gl::VertexArray empty_vao;

    unsigned options_of(GlintModelId model) const {
        const auto it = model_options.find(model);
        return it != model_options.end() ? it->second : 0u;
    }

    // The model's state, made on first use; null when it has none.
    GpuModelState* model_state(GlintModelId model) {
        auto it = model_states.find(model);
        if (it == model_states.end()) {
            const GpuModelHooks* hooks = find_gpu_model_hooks(model);
            std::unique_ptr<GpuModelState> state;
            if (hooks != nullptr && hooks->make_state != nullptr) state = hooks->make_state();
            it = model_states.emplace(model, std::move(state)).first;
        }
        return it->second.get();
    }

    GpuFrame frame(const Scene& scene) const {
        return GpuFrame{scene,
                        environment ? environment.get() : 0u,
                        environment_width,
                        environment_height,
                        environment_scale,
                        environment_rotation};
    }

    GLuint program(const gl::ProgramKey& key) {
        auto it = programs.find(key);
        if (it != programs.end()) return it->second.get();
        const GLuint p = gl::link_program(gl::forward_vertex_shader(),
                                          gl::forward_fragment_shader(key), key.name());
        programs.emplace(key, gl::Program(p));
        return p;
    }

    void resize(int w, int h) {
        if (w == width && h == height && fbo) return;
        GLint max_renderbuffer = 0, max_texture = 0;
        glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_renderbuffer);
        glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
        const GLint max_size = std::min(max_renderbuffer, max_texture);
        if (w < 1 || h < 1 || w > max_size || h > max_size)
            fail(
                "OpenGL renderer: resolution {}x{} outside [1, {}] (this driver's "
                "GL_MAX_TEXTURE_SIZE and GL_MAX_RENDERBUFFER_SIZE)",
                w, h, max_size);
        while (glGetError() != GL_NO_ERROR) {
        }
        color = gl::make_texture(GL_TEXTURE_2D);
        glTextureStorage2D(color.get(), 1, GL_RGBA32F, w, h);
        glTextureParameteri(color.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(color.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        depth = gl::make_texture(GL_TEXTURE_2D);
        glTextureStorage2D(depth.get(), 1, GL_DEPTH_COMPONENT32F, w, h);
        glint_layer = {};
        fbo = gl::make_framebuffer();
        glNamedFramebufferTexture(fbo.get(), GL_COLOR_ATTACHMENT0, color.get(), 0);
        glNamedFramebufferTexture(fbo.get(), GL_DEPTH_ATTACHMENT, depth.get(), 0);
        // A driver that cannot allocate the targets (16384² is 4 GiB of
        // RGBA32F and 1 GiB of depth) reports GL_OUT_OF_MEMORY here and an
        // incomplete attachment below: both name the size and the cure.
        const double gib = double(w) * double(h) * (16.0 + 4.0) / double(1u << 30);
        if (glGetError() == GL_OUT_OF_MEMORY)
            fail(
                "OpenGL renderer: out of GPU memory for the {}x{} colour (RGBA32F) and depth "
                "targets ({:.2f} GiB); lower the resolution (--res)",
                w, h, gib);
        const GLenum status = glCheckNamedFramebufferStatus(fbo.get(), GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE)
            fail(
                "OpenGL renderer: the {}x{} colour (RGBA32F) and depth targets ({:.2f} GiB) could "
                "not be made a framebuffer (status 0x{:x}{}); lower the resolution (--res)",
                w, h, gib, static_cast<unsigned>(status),
                status == GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT
                    ? ", incomplete attachment: usually out of GPU memory"
                    : "");
        width = w;
        height = h;
    }

    // Colour attachment 1 (RGBA32F, this size): rgb glints, a visibility.
    void attach_glint_layer() {
        if (glint_layer) return;
        glint_layer = gl::make_texture(GL_TEXTURE_2D);
        glTextureStorage2D(glint_layer.get(), 1, GL_RGBA32F, width, height);
        glNamedFramebufferTexture(fbo.get(), GL_COLOR_ATTACHMENT1, glint_layer.get(), 0);
        const GLenum status = glCheckNamedFramebufferStatus(fbo.get(), GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE)
            fail("OpenGL renderer: framebuffer with the glint layer incomplete (0x{:x})",
                 static_cast<unsigned>(status));
    }

    void set_material(GLuint p, const Scene& scene, const Shape& shape) {
        auto loc = [&](const char* name) { return uniforms.location(p, name); };
        glm::vec3 emission(0.0f);
        if (shape.area_light >= 0)
            if (const auto* l =
                    std::get_if<SphereLight>(&scene.lights[static_cast<size_t>(shape.area_light)]))
                emission = l->radiance;
        glProgramUniform3fv(p, loc("u_emission"), 1, glm::value_ptr(emission));
        if (shape.material < 0) {
            glProgramUniform1i(p, loc("u_material_type"),
                               static_cast<int>(gl::GpuMaterialType::EmissionOnly));
            return;
        }
        const MaterialDesc& m = scene.materials[static_cast<size_t>(shape.material)];
        int type = 0;
        switch (m.type) {
            case MaterialDesc::Type::Diffuse:
                type = static_cast<int>(gl::GpuMaterialType::Diffuse);
                break;
            case MaterialDesc::Type::Conductor:
                type = static_cast<int>(gl::GpuMaterialType::Conductor);
                break;
            case MaterialDesc::Type::Dielectric:
                type = static_cast<int>(gl::GpuMaterialType::Dielectric);
                break;
            case MaterialDesc::Type::Plastic:
                type = static_cast<int>(gl::GpuMaterialType::Plastic);
                break;
            case MaterialDesc::Type::MetallicRoughness:
                type = static_cast<int>(gl::GpuMaterialType::MetallicRoughness);
                break;
            case MaterialDesc::Type::Glint:
                type = static_cast<int>(gl::GpuMaterialType::Glint);
                break;
        }
        glProgramUniform1i(p, loc("u_material_type"), type);
        glProgramUniform3fv(p, loc("u_albedo"), 1, glm::value_ptr(m.albedo));
        glProgramUniform1f(p, loc("u_metallic"), m.metallic);
        glProgramUniform1i(p, loc("u_ndf"), ndf_code(m.ndf));
        glProgramUniform2f(p, loc("u_alpha"), m.alpha_x, m.alpha_y);
        glProgramUniform3fv(p, loc("u_eta"), 1, glm::value_ptr(m.eta));
        glProgramUniform3fv(p, loc("u_k"), 1, glm::value_ptr(m.k));
        if (m.type != MaterialDesc::Type::Glint) return;
        const GlintDesc& g = m.glint;
        glProgramUniform1i(p, loc("u_glint_ndf"), ndf_code(g.ndf));
        glProgramUniform2f(p, loc("u_glint_alpha"), g.alpha_x, g.alpha_y);
        glProgramUniform1f(p, loc("u_glint_log_density"), g.log_density);
        glProgramUniform1ui(p, loc("u_glint_seed"), g.seed);
        glProgramUniform3fv(p, loc("u_glint_color"), 1, glm::value_ptr(g.color));
        glProgramUniform3fv(p, loc("u_glint_base_albedo"), 1, glm::value_ptr(g.base_albedo));
        glProgramUniform1i(p, loc("u_fresnel_mode"), static_cast<int>(g.fresnel.mode));
        glProgramUniform3fv(p, loc("u_fresnel_f0"), 1, glm::value_ptr(g.fresnel.f0));
        glProgramUniform3fv(p, loc("u_fresnel_eta"), 1, glm::value_ptr(g.fresnel.eta));
        glProgramUniform3fv(p, loc("u_fresnel_k"), 1, glm::value_ptr(g.fresnel.k));
        glProgramUniform1i(p, loc("u_glint_g2"), glint_g2_mode(g));
        // Programs with a per-fragment α (textures, a normal map, curvature):
        // the model shears its target by the slopes' correlation.
        const GlintModelDescriptor& model = glint_model(g.model_id);
        glProgramUniform1i(
            p, loc("u_glint_reads_correlation"),
            model.reads_slope_correlation && model.reads_slope_correlation(g) ? 1 : 0);
        if (GpuModelState* state = model_state(g.model_id))
            state->prepare(p, uniforms, g, frame(scene), options_of(g.model_id));
    }

    // The material's textures (shaders/material_textures.glsl): bound to
    // units kMaterialTextureUnit + slot, with their uv transforms and the
    // mask of the textured slots.
    void set_material_textures(GLuint p, const MaterialDesc& m) {
        if (!m.textured()) return;
        std::shared_ptr<const TextureInput> slots[gl::kMaterialTextureSlots];
        if (const MaterialTextures* t = m.textures.get()) {
            slots[1] = t->alpha_x_sq, slots[2] = t->alpha_y_sq, slots[3] = t->albedo;
            slots[5] = t->metallic;
        }
        if (const GlintTextures* t = m.glint.textures.get()) {
            slots[0] = t->density, slots[1] = t->alpha_x_sq, slots[2] = t->alpha_y_sq;
            slots[3] = t->color, slots[4] = t->base_albedo;
        }
        // An isotropic roughness map (one texture on both axes) is read once.
        const bool alpha_isotropic = slots[1] && slots[2] == slots[1];
        if (alpha_isotropic) slots[2] = nullptr;
        int mask = 0;
        // A one-value slot reads its channel of the first slot it shares a
        // lookup with (a texture packed by the loader, pack_scalar_inputs).
        GLint source[gl::kMaterialTextureSlots];
        glm::vec4 channel[gl::kMaterialTextureSlots];  // one-hot
        glm::mat2 linear[gl::kMaterialTextureSlots];
        glm::vec2 offset[gl::kMaterialTextureSlots], size[gl::kMaterialTextureSlots];
        for (int i = 0; i < gl::kMaterialTextureSlots; ++i) {
            linear[i] = glm::mat2(1.0f), offset[i] = glm::vec2(0.0f), size[i] = glm::vec2(1.0f);
            source[i] = i, channel[i] = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
            if (!slots[i]) continue;
            const TextureInput& in = *slots[i];
            mask |= 1 << i;
            channel[i] = glm::vec4(0.0f);
            channel[i][std::max(in.channel, 0)] = 1.0f;
            for (int j = 0; j < i && source[i] == i; ++j)
                if (slots[j] && slots[j]->shares_lookup(in)) source[i] = j;
            linear[i] = glm::mat2(in.transform.apply_vector({1.0f, 0.0f}),
                                  in.transform.apply_vector({0.0f, 1.0f}));
            offset[i] = in.transform.offset;
            size[i] = glm::vec2(float(in.texture->width()), float(in.texture->height()));
            glBindTextureUnit(static_cast<GLuint>(gl::kMaterialTextureUnit + i),
                              material_texture(in.texture));
        }
        auto loc = [&](const char* name) { return uniforms.location(p, name); };
        glProgramUniform1i(p, loc("u_material_texture_mask"), mask);
        glProgramUniform1i(p, loc("u_material_texture_alpha_isotropic"), alpha_isotropic ? 1 : 0);
        glProgramUniform1iv(p, loc("u_material_texture_source"), gl::kMaterialTextureSlots, source);
        glProgramUniform4fv(p, loc("u_material_texture_channel"), gl::kMaterialTextureSlots,
                            glm::value_ptr(channel[0]));
        glProgramUniformMatrix2fv(p, loc("u_material_texture_linear"), gl::kMaterialTextureSlots,
                                  GL_FALSE, glm::value_ptr(linear[0]));
        glProgramUniform2fv(p, loc("u_material_texture_offset"), gl::kMaterialTextureSlots,
                            glm::value_ptr(offset[0]));
        glProgramUniform2fv(p, loc("u_material_texture_size"), gl::kMaterialTextureSlots,
                            glm::value_ptr(size[0]));
        if (const NormalMap* map = m.normal_map.get()) {
            // shaders/normal_map.glsl: slopes and moments share the map's
            // transform and size.
            const TextureInput& slopes = *map->slopes;
            glBindTextureUnit(gl::kNormalMapUnit, material_texture(slopes.texture));
            glBindTextureUnit(gl::kNormalMapUnit + 1, material_texture(map->cross_moment->texture));
            const glm::mat2 map_linear(slopes.transform.apply_vector({1.0f, 0.0f}),
                                       slopes.transform.apply_vector({0.0f, 1.0f}));
            glProgramUniformMatrix2fv(p, loc("u_normal_map_linear"), 1, GL_FALSE,
                                      glm::value_ptr(map_linear));
            glProgramUniform2fv(p, loc("u_normal_map_offset"), 1,
                                glm::value_ptr(slopes.transform.offset));
            glProgramUniform2f(p, loc("u_normal_map_size"), float(slopes.texture->width()),
                               float(slopes.texture->height()));
            glProgramUniform1i(p, loc("u_normal_map_filtering"),
                               map->filtering == NormalMap::Filtering::None ? 1 : 0);
            glProgramUniform1i(p, loc("u_normal_map_mixture"), map->mixture);
            // Models whose tables hold one α take the mean normal only
            // (glint_model_descriptor.h textured_roughness).
            glProgramUniform1i(p, loc("u_normal_map_widens_glint"),
                               m.type == MaterialDesc::Type::Glint &&
                                       glint_model(m.glint.model_id).textured_roughness
                                   ? 1
                                   : 0);
        }
    }

    // A material texture's GL texture, uploaded on first use with the CPU's
    // mip chain (exact box means), trilinear, the texture's wrap mode; one
    // channel is read as grey (swizzle r, r, r).
    GLuint material_texture(const std::shared_ptr<const MipTexture>& tex) {
        auto it = material_textures.find(tex.get());
        if (it != material_textures.end()) return it->second.second.get();
        gl::Texture t = gl::make_texture(GL_TEXTURE_2D);
        const bool grey = tex->channels() == 1;
        const GLenum internals[] = {GL_R32F, GL_RG32F, GL_RGB32F, GL_RGBA32F};
        const GLenum formats[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
        const GLenum internal = internals[tex->channels() - 1];
        const GLenum format = formats[tex->channels() - 1];
        glTextureStorage2D(t.get(), tex->level_count(), internal, tex->width(), tex->height());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        for (int level = 0; level < tex->level_count(); ++level)
            glTextureSubImage2D(t.get(), level, 0, 0, tex->width(level), tex->height(level), format,
                                GL_FLOAT, tex->level_texels(level).data());
        glTextureParameteri(t.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTextureParameteri(t.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        auto gl_wrap = [](TextureWrap w) -> GLint {
            return w == TextureWrap::Clamp    ? GL_CLAMP_TO_EDGE
                   : w == TextureWrap::Mirror ? GL_MIRRORED_REPEAT
                                              : GL_REPEAT;
        };
        glTextureParameteri(t.get(), GL_TEXTURE_WRAP_S, gl_wrap(tex->wrap().u));
        glTextureParameteri(t.get(), GL_TEXTURE_WRAP_T, gl_wrap(tex->wrap().v));
        if (grey) {
            const GLint swizzle[4] = {GL_RED, GL_RED, GL_RED, GL_ONE};
            glTextureParameteriv(t.get(), GL_TEXTURE_SWIZZLE_RGBA, swizzle);
        }
        const GLuint id = t.get();
        material_textures.emplace(tex.get(), std::make_pair(tex, std::move(t)));
        return id;
    }

    void set_lights(GLuint p, const Scene& scene) {
        std::vector<glm::vec3> point_position, point_intensity, dir_direction, dir_irradiance;
        // The shapes of area lights, for glint models that shade them as
        // cones (GLINTLAB_GLINT_SHADES_AREA_LIGHTS in realtime/shaders/forward.frag.glsl).
        std::vector<float> point_radius, dir_solid_angle, dir_cos_max;
        std::vector<glm::vec3> point_radiance, dir_radiance;
        for (const Light& light : scene.lights) {
            if (const auto* l = std::get_if<PointLight>(&light)) {
                point_position.push_back(l->position);
                point_intensity.push_back(l->intensity);
                point_radius.push_back(0.0f);
                point_radiance.push_back(glm::vec3(0.0f));
            } else if (const auto* l = std::get_if<SphereLight>(&light)) {
                // A sphere of radiance L seen whole from distance d gives the
                // irradiance pi L r^2 / d^2 cos: a point of intensity pi r^2 L.
                point_position.push_back(l->center);
                point_intensity.push_back(glm::pi<float>() * l->radius * l->radius * l->radiance);
                point_radius.push_back(l->radius);
                point_radiance.push_back(l->radiance);
            } else if (const auto* l = std::get_if<DirectionalLight>(&light)) {
                dir_direction.push_back(l->direction);
                dir_irradiance.push_back(l->irradiance);
                dir_solid_angle.push_back(l->solid_angle);
                dir_cos_max.push_back(l->cos_max);
                dir_radiance.push_back(l->radiance);
            }
        }
        auto loc = [&](const char* name) { return uniforms.location(p, name); };
        auto set = [&](const char* name, const std::vector<glm::vec3>& v) {
            if (!v.empty())
                glProgramUniform3fv(p, loc(name), static_cast<GLsizei>(v.size()),
                                    glm::value_ptr(v[0]));
        };
        glProgramUniform1i(p, loc("u_point_light_count"),
                           static_cast<GLint>(point_position.size()));
        glProgramUniform1i(p, loc("u_directional_light_count"),
                           static_cast<GLint>(dir_direction.size()));
        set("u_point_position", point_position);
        set("u_point_intensity", point_intensity);
        set("u_directional_direction", dir_direction);
        set("u_directional_irradiance", dir_irradiance);
        set("u_point_radiance", point_radiance);
        set("u_directional_radiance", dir_radiance);
        auto set_floats = [&](const char* name, const std::vector<float>& v) {
            if (!v.empty())
                glProgramUniform1fv(p, loc(name), static_cast<GLsizei>(v.size()), v.data());
        };
        set_floats("u_point_radius", point_radius);
        set_floats("u_directional_solid_angle", dir_solid_angle);
        set_floats("u_directional_cos_max", dir_cos_max);
    }
};

namespace {

// A lat-long map as a texture with its full mip chain, solid-angle weighted
// (scene/environment_mips.h): filtered importance samples read coarser
// levels for wider samples.
gl::Texture upload_latlong(const Image& image) {
    gl::Texture t = gl::make_texture(GL_TEXTURE_2D);
    const std::vector<Image> mips = latlong_mip_chain(image);
    glTextureStorage2D(t.get(), static_cast<GLsizei>(mips.size()), GL_RGB32F, image.width,
                       image.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    for (size_t level = 0; level < mips.size(); ++level)
        glTextureSubImage2D(t.get(), static_cast<GLint>(level), 0, 0, mips[level].width,
                            mips[level].height, GL_RGB, GL_FLOAT, mips[level].pixels.data());
    glTextureParameteri(t.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(t.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t.get(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(t.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

}  // namespace

// What the renderer cannot draw is said first, before any OpenGL call (the
// renderer's state is built with the context current).
std::unique_ptr<GpuRenderer::Impl> GpuRenderer::make_impl(const Scene&) {
    return std::make_unique<Impl>();
}

GpuRenderer::GpuRenderer(const Scene& scene) : impl_(make_impl(scene)) {
    require_gl45("OpenGL renderer");
    for (const MaterialDesc& m : scene.materials) {
        if (!m.normal_map) continue;
        GLint units = 0;
        glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units);
        if (units < gl::kNormalMapUnit + 2)
            fail(
                "{}: material \"{}\" has a normal map: the OpenGL renderer reads it on texture "
                "units {} and {}, and this driver has {} fragment texture units "
                "(GL_MAX_TEXTURE_IMAGE_UNITS); render it on the CPU (without --gpu)",
                scene.file.string(), m.name, gl::kNormalMapUnit, gl::kNormalMapUnit + 1, units);
        break;
    }
    Impl& r = *impl_;
    const int segments = sphere_segments(scene);
    for (const Shape& shape : scene.shapes) r.shapes.push_back(upload_shape(shape, segments));
    r.bounds = scene_bounds(scene);
    if (scene.environment >= 0) {
        const auto& env =
            std::get<EnvironmentLight>(scene.lights[static_cast<size_t>(scene.environment)]);
        if (!env.map)
            fail("{}: OpenGL renderer: the environment light has no map loaded",
                 scene.file.string());
        const Image& image = env.map->image();
        if (image.width < 1 || image.height < 1 || image.pixels.empty())
            fail("{}: OpenGL renderer: the environment map {} is empty", scene.file.string(),
                 env.file.string());
        r.environment = upload_latlong(image);
        EnvironmentSourceSplit sources =
            split_environment_sources(image, gl::kEnvironmentSourceSamples);
        if (!sources.directions.empty()) {
            r.environment_residual = upload_latlong(sources.residual);
            r.source_directions = std::move(sources.directions);
            r.source_powers = std::move(sources.powers);
        }
        r.environment_width = image.width;
        r.environment_height = image.height;
        r.environment_scale = env.map->scale();
        r.environment_rotation = glm::radians(env.map->rotation_deg());
    }
    r.background = gl::Program(gl::link_program(gl::background_vertex_shader(),
                                                gl::background_fragment_shader(), "background"));
    r.empty_vao = gl::make_vertex_array();
    r.shadow_program = gl::Program(
        gl::link_program(gl::shadow_vertex_shader(), gl::shadow_fragment_shader(), "shadow"));
    for (const Shape& shape : scene.shapes) {
        const gl::ProgramKey key = program_key(scene, shape, {});
        if (!gl::gpu_supports_model(key.model)) (void)gl::glint_model_glsl(key.model);  // throws
        r.program(key);
    }
}

GpuRenderer::~GpuRenderer() = default;

void GpuRenderer::compile_all_models(const Scene& scene) {
    Shape probe;
    for (const GpuModelHooks& hooks : gpu_model_hooks()) {
        gl::ProgramKey key = program_key(scene, probe, {});
        key.model = hooks.model;
        // Every glue variant: each subset of the options that change the program.
        const unsigned mask = hooks.program_option_mask();
        for (unsigned subset = mask;; subset = (subset - 1) & mask) {
            key.model_options = subset;
            impl_->program(key);
            if (subset == 0) break;
        }
    }
}

void GpuRenderer::render(const Scene& scene) {
    Impl& r = *impl_;
    if (scene.shapes.size() != r.shapes.size())
        fail("OpenGL renderer: the scene's shapes changed after upload ({} != {})",
             scene.shapes.size(), r.shapes.size());
    r.resize(scene.camera.width, scene.camera.height);
    const Camera& c = scene.camera;
    const float aspect = static_cast<float>(c.width) / static_cast<float>(c.height);
    // Depth range from the scene's bounding sphere.
    const glm::vec3 centre(r.bounds);
    const float radius = r.bounds.w;
    const glm::vec3 forward = glm::normalize(c.target - c.eye);
    const float along = glm::dot(centre - c.eye, forward);
    const float far_plane = std::max(along + radius * 1.01f, 1e-3f);
    const glm::mat4 view = glm::lookAt(c.eye, c.target, c.up);
    glm::mat4 projection;
    if (c.type == Camera::Type::Perspective) {
        const float near_plane = std::max(along - radius * 1.01f, far_plane * 1e-5f);
        projection = glm::perspective(glm::radians(c.fov_deg), aspect, near_plane, far_plane);
    } else {
        const float h = 0.5f * c.ortho_height;
        projection = glm::ortho(-h * aspect, h * aspect, -h, h, along - radius * 1.01f, far_plane);
    }
    const glm::mat4 view_projection = projection * view;
    const bool ortho = c.type == Camera::Type::Orthographic;
    // The glint layer and its post pass (wang2020's §4.4 blurs, render_scene's
    // postprocess_glints): only the environment term is deferred, so only
    // scenes with an environment and a shape of a material that uses the
    // layer pay for them. One model per frame owns the layer.
    bool blur = false;
    GlintModelId layer_model = GlintModelId::Smooth;
    if (r.environment)
        for (const Shape& shape : scene.shapes) {
            if (shape.material < 0) continue;
            const MaterialDesc& m = scene.materials[static_cast<size_t>(shape.material)];
            if (!uses_glint_layer(m)) continue;
            if (blur && m.glint.model_id != layer_model)
                fail(
                    "OpenGL renderer: materials of two glint models ({}, {}) defer to the glint "
                    "layer in one frame",
                    find_glint_model(layer_model)->name, glint_model(m.glint.model_id).name);
            blur = true;
            layer_model = m.glint.model_id;
        }

    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);  // two-sided materials

    // The models' per-frame work (kneiphof2025's dynamic IBL, 003 §5), for
    // each model of the scene's materials, before the passes (it may rebind
    // any unit).
    {
        std::set<GlintModelId> models;
        for (const MaterialDesc& m : scene.materials)
            if (m.type == MaterialDesc::Type::Glint) models.insert(m.glint.model_id);
        const GpuFrame frame = r.frame(scene);
        for (GlintModelId model : models)
            if (GpuModelState* state = r.model_state(model))
                state->begin_frame(frame, r.options_of(model));
    }

    // Pass 0: shadow maps of the directional lights.
    r.shadow_timer.begin();
    r.render_shadow_maps(scene);
    r.render_point_shadow_maps(scene);
    r.shadow_timer.end();

    glBindFramebuffer(GL_FRAMEBUFFER, r.fbo.get());
    glViewport(0, 0, r.width, r.height);
    glNamedFramebufferDrawBuffer(r.fbo.get(), GL_COLOR_ATTACHMENT0);

    // Pass 1: background (environment or black).
    r.background_timer.begin();
    glDisable(GL_DEPTH_TEST);
    const GLuint bg = r.background.get();
    const glm::mat4 inverse = glm::inverse(view_projection);
    glProgramUniformMatrix4fv(bg, r.uniforms.location(bg, "u_inverse_view_projection"), 1, GL_FALSE,
                              glm::value_ptr(inverse));
    glProgramUniform1i(bg, r.uniforms.location(bg, "u_orthographic"), ortho ? 1 : 0);
    glProgramUniform3fv(bg, r.uniforms.location(bg, "u_view_forward"), 1, glm::value_ptr(forward));
    glProgramUniform1i(bg, r.uniforms.location(bg, "u_has_environment"), r.environment ? 1 : 0);
    glProgramUniform1f(bg, r.uniforms.location(bg, "u_environment_scale"), r.environment_scale);
    glProgramUniform1f(bg, r.uniforms.location(bg, "u_environment_rotation"),
                       r.environment_rotation);
    if (r.environment) glBindTextureUnit(gl::kEnvironmentUnit, r.environment.get());
    glUseProgram(bg);
    glBindVertexArray(r.empty_vao.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    r.background_timer.end();

    // Pass 2: forward shading of every shape.
    if (!r.loop_probe) {
        r.loop_probe = gl::make_buffer();
        glNamedBufferStorage(r.loop_probe.get(), sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    const GLuint zero = 0;
    glNamedBufferSubData(r.loop_probe.get(), 0, sizeof(GLuint), &zero);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLoopProbeBinding, r.loop_probe.get());
    r.forward_timer.begin();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    if (blur) {
        // The glint layer: cleared to rgb 0, visibility 1 (render_scene's
        // convention), so pixels without wang2020 neither add glints nor
        // darken a neighbour's occlusion blur.
        r.attach_glint_layer();
        const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glNamedFramebufferDrawBuffers(r.fbo.get(), 2, buffers);
        const GLfloat clear[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        glClearNamedFramebufferfv(r.fbo.get(), GL_COLOR, 1, clear);
    }
    for (size_t i = 0; i < r.shapes.size(); ++i) {
        const Shape& shape = scene.shapes[i];
        const GpuShape& g = r.shapes[i];
        const GLuint p = r.program(program_key(scene, shape, r.model_options));
        auto loc = [&](const char* name) { return r.uniforms.location(p, name); };
        glProgramUniformMatrix4fv(p, loc("u_view_projection"), 1, GL_FALSE,
                                  glm::value_ptr(view_projection));
        glProgramUniform3fv(p, loc("u_eye"), 1, glm::value_ptr(c.eye));
        glProgramUniform1i(p, loc("u_orthographic"), ortho ? 1 : 0);
        glProgramUniform3fv(p, loc("u_view_forward"), 1, glm::value_ptr(forward));
        glProgramUniform1i(p, loc("u_per_triangle_frame"), g.per_triangle_frame ? 1 : 0);
        glProgramUniform1i(p, loc("u_has_normals"), g.has_normals ? 1 : 0);
        glProgramUniform1i(p, loc("u_closed_surface"), g.closed ? 1 : 0);
        r.set_material(p, scene, shape);
        if (shape.material >= 0)
            r.set_material_textures(p, scene.materials[static_cast<size_t>(shape.material)]);
        if (r.environment) {
            glProgramUniform1f(p, loc("u_environment_scale"), r.environment_scale);
            glProgramUniform1f(p, loc("u_environment_rotation"), r.environment_rotation);
            glProgramUniform2f(p, loc("u_environment_size"),
                               static_cast<float>(r.environment_width),
                               static_cast<float>(r.environment_height));
            const auto count = static_cast<GLsizei>(r.source_directions.size());
            glProgramUniform1i(p, loc("u_environment_source_count"), count);
            if (count > 0) {
                glProgramUniform3fv(p, loc("u_environment_source_direction"), count,
                                    glm::value_ptr(r.source_directions[0]));
                glProgramUniform3fv(p, loc("u_environment_source_power"), count,
                                    glm::value_ptr(r.source_powers[0]));
            }
            glBindTextureUnit(gl::kEnvironmentResidualUnit, r.environment_residual
                                                                ? r.environment_residual.get()
                                                                : r.environment.get());
        }
        r.set_lights(p, scene);
        const bool deferred =
            blur && shape.material >= 0 &&
            uses_glint_layer(scene.materials[static_cast<size_t>(shape.material)]);
        glProgramUniform1i(p, loc("u_glint_layer"), deferred ? 1 : 0);
        glProgramUniform1i(p, loc("u_loop_probe"), 2);
        const bool shadowed = !r.shadow_matrices.empty();
        glProgramUniform1i(p, loc("u_shadows"), shadowed ? 1 : 0);
        if (shadowed) {
            glProgramUniformMatrix4fv(p, loc("u_shadow_matrix"),
                                      static_cast<GLsizei>(r.shadow_matrices.size()), GL_FALSE,
                                      glm::value_ptr(r.shadow_matrices[0]));
            glProgramUniform1f(p, loc("u_shadow_texel"), r.shadow_texel);
            glProgramUniform1f(p, loc("u_shadow_depth_range"), r.shadow_depth_range);
            glBindTextureUnit(gl::kShadowUnit, r.shadow_maps.get());
        }
        const bool point_shadowed = !r.point_near.empty();
        glProgramUniform1i(p, loc("u_point_shadows"), point_shadowed ? 1 : 0);
        if (point_shadowed) {
            glProgramUniform1fv(p, loc("u_point_near"), static_cast<GLsizei>(r.point_near.size()),
                                r.point_near.data());
            glProgramUniform1fv(p, loc("u_point_far"), static_cast<GLsizei>(r.point_far.size()),
                                r.point_far.data());
            glProgramUniform1f(p, loc("u_point_shadow_size"),
                               static_cast<float>(gl::kPointShadowSize));
            glBindTextureUnit(gl::kPointShadowUnit, r.point_shadow_maps.get());
        }
        if (g.triangles) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, g.triangles.get());
        glUseProgram(p);
        glBindVertexArray(g.vao.get());
        glDrawElements(GL_TRIANGLES, g.index_count, GL_UNSIGNED_INT, nullptr);
    }
    r.forward_timer.end();
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    // Pass 3: the layer model's post pass (wang2020's §4.4 blurs) over the
    // glint layer, added into the colour target (before any read-back, tone
    // map or bloom).
    r.glint_post_frame = blur;
    if (blur) {
        glNamedFramebufferDrawBuffer(r.fbo.get(), GL_COLOR_ATTACHMENT0);
        GpuModelState* state = r.model_state(layer_model);
        if (state == nullptr)
            fail("OpenGL renderer: glint model {} uses the glint layer but has no GPU state",
                 find_glint_model(layer_model)->name);
        r.glint_post_timer.begin();
        state->post_pass(r.glint_layer.get(), r.color.get(), r.width, r.height);
        r.glint_post_timer.end();
    }
}

Image GpuRenderer::read_image() const {
    const Impl& r = *impl_;
    if (!r.color) fail("OpenGL renderer: read_image() before render()");
    Image image(r.width, r.height);
    // Strips of rows below 256 MiB, so the byte count fits glGetTextureSubImage's GLsizei.
    const size_t row_bytes = static_cast<size_t>(r.width) * 4 * sizeof(float);
    const int strip = std::max(1, static_cast<int>((size_t{1} << 28) / row_bytes));
    std::vector<float> rgba(static_cast<size_t>(r.width) * 4 *
                            static_cast<size_t>(std::min(strip, r.height)));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    for (int y0 = 0; y0 < r.height; y0 += strip) {
        const int rows = std::min(strip, r.height - y0);
        glGetTextureSubImage(r.color.get(), 0, 0, y0, 0, r.width, rows, 1, GL_RGBA, GL_FLOAT,
                             static_cast<GLsizei>(row_bytes * static_cast<size_t>(rows)),
                             rgba.data());
        for (int k = 0; k < rows; ++k) {
            const int y = r.height - 1 - (y0 + k);  // GL rows go up, Image rows down
            const float* px = &rgba[static_cast<size_t>(k) * r.width * 4];
            for (int x = 0; x < r.width; ++x, px += 4)
                image.at(x, y) = glm::vec3(px[0], px[1], px[2]);
        }
    }
    return image;
}

uint64_t GpuRenderer::cut_fragments() const {
    const Impl& r = *impl_;
    if (!r.loop_probe) return 0;
    GLuint count = 0;
    glGetNamedBufferSubData(r.loop_probe.get(), 0, sizeof(GLuint), &count);
    return count;
}

std::string cut_fragments_warning(uint64_t cut) {
    if (cut == 0) return {};
    return fmt::format(
        "OpenGL renderer: the OpenGL implementation cut the shading loops of {} "
        "fragment{} short (Mesa llvmpipe ends a shader's loops after 65535 iterations in all): "
        "those pixels are too dark. Fewer lights or lean_mixture cells, a hardware GPU or the "
        "CPU renderer avoid it",
        cut, cut == 1 ? "" : "s");
}

unsigned GpuRenderer::hdr_texture() const {
    return impl_->color.get();
}
int GpuRenderer::width() const {
    return impl_->width;
}
int GpuRenderer::height() const {
    return impl_->height;
}

void GpuRenderer::finish() const {
    glFinish();
}

void GpuRenderer::set_environment(float scale, float rotation_deg) {
    impl_->environment_scale = scale;
    impl_->environment_rotation = glm::radians(rotation_deg);
}

bool GpuRenderer::has_environment() const {
    return static_cast<bool>(impl_->environment);
}

namespace {

// The hooks of the model called `model` and the index of its option
// `option`; glintlab::Error naming both and what is allowed otherwise.
std::pair<const GpuModelHooks*, int> find_model_option(std::string_view model,
                                                       std::string_view option) {
    const GlintModelInfo* info = find_glint_model(model);
    const GpuModelHooks* hooks = info != nullptr ? find_gpu_model_hooks(info->id) : nullptr;
    if (hooks == nullptr) {
        std::string supported;
        for (const GpuModelHooks& h : gpu_model_hooks())
            if (!h.options.empty())
                supported += fmt::format("{}{}", supported.empty() ? "" : ", ",
                                         find_glint_model(h.model)->name);
        fail(
            "OpenGL renderer: model option \"{}.{}\": \"{}\" is not a GPU glint model (models "
            "with options: {})",
            model, option, model, supported);
    }
    const int index = hooks->option_index(option);
    if (index < 0) {
        std::string allowed;
        for (const GpuModelOption& o : hooks->options)
            allowed += fmt::format("{}{}", allowed.empty() ? "" : ", ", o.name);
        fail("OpenGL renderer: model option \"{}.{}\": {} has no such GPU option (options: {})",
             model, option, model, allowed.empty() ? "none" : allowed);
    }
    return {hooks, index};
}

}  // namespace

void GpuRenderer::set_model_option(std::string_view model, std::string_view option, bool on) {
    const auto [hooks, index] = find_model_option(model, option);
    unsigned& mask = impl_->model_options[hooks->model];
    const unsigned bit = 1u << index;
    mask = on ? (mask | bit) : (mask & ~bit);
}

bool GpuRenderer::model_option(std::string_view model, std::string_view option) const {
    const auto [hooks, index] = find_model_option(model, option);
    return ((impl_->options_of(hooks->model) >> index) & 1u) != 0;
}

void GpuRenderer::set_shadows(bool on) {
    impl_->shadows = on;
}

GpuPassTimes GpuRenderer::pass_times() {
    Impl& r = *impl_;
    return {r.shadow_timer.elapsed_ms(), r.background_timer.elapsed_ms(),
            r.forward_timer.elapsed_ms(),
            r.glint_post_frame ? r.glint_post_timer.elapsed_ms() : 0.0};
}

Image render_scene_gpu(const Scene& scene, uint64_t* cut_fragments) {
    HeadlessContext context;
    GpuRenderer renderer(scene);
    renderer.render(scene);
    Image image = renderer.read_image();
    const uint64_t cut = renderer.cut_fragments();
    if (cut_fragments)
        *cut_fragments = cut;
    else if (cut > 0)
        fmt::print(stderr, "warning: {}\n", cut_fragments_warning(cut));
    return image;
}

}  // namespace glintlab
