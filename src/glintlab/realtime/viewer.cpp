#include "glintlab/realtime/viewer.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <string>
#include <vector>

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <fmt/format.h>
#include <imgui.h>

#include "glintlab/core/bloom.h"
#include "glintlab/core/error.h"
#include "glintlab/core/image.h"
#include "glintlab/glints/glint_panel_model.h"
#include "glintlab/glints/registry.h"
#include "glintlab/realtime/forward_shaders.h"
#include "glintlab/realtime/gl_context.h"
#include "glintlab/realtime/gl_handles.h"
#include "glintlab/realtime/gl_program.h"
#include "glintlab/realtime/glint_programs.h"
#include "glintlab/realtime/gpu_bloom.h"
#include "glintlab/realtime/gpu_renderer.h"
#include "glintlab/realtime/gpu_timer.h"
#include "glintlab/realtime/orbit_camera.h"

namespace glintlab {
namespace {

// Owns glfwInit/glfwTerminate and the window.
struct Glfw {
    GLFWwindow* window = nullptr;
    Glfw() {
        glfwSetErrorCallback(nullptr);
        if (!glfwInit())
            fail(
                "glintlab view: cannot initialise GLFW (no display? set DISPLAY, or run under "
                "xvfb-run -a -s \"-screen 0 1280x1024x24\")");
    }
    ~Glfw() {
        if (window != nullptr) glfwDestroyWindow(window);
        glfwTerminate();
    }
};

struct ImGuiScope {
    bool glfw = false, opengl = false;
    ImGuiScope() { ImGui::CreateContext(); }
    ~ImGuiScope() {
        if (opengl) ImGui_ImplOpenGL3_Shutdown();
        if (glfw) ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
};

// Running median of a pass's GPU time over the last 60 frames.
struct PassHistory {
    std::deque<double> ms;
    void add(double v) {
        ms.push_back(v);
        if (ms.size() > 60) ms.pop_front();
    }
    double median() const { return gl::timing_stats({ms.begin(), ms.end()}).median_ms; }
};

struct OrbitState {
    double scroll = 0.0;  // accumulated wheel steps since the last frame
};

void scroll_callback(GLFWwindow* window, double, double dy) {
    static_cast<OrbitState*>(glfwGetWindowUserPointer(window))->scroll += dy;
}

std::string light_label(const Light& light, size_t i) {
    if (std::holds_alternative<PointLight>(light)) return fmt::format("light {}: point", i);
    if (std::holds_alternative<DirectionalLight>(light))
        return fmt::format("light {}: directional", i);
    if (std::holds_alternative<SphereLight>(light)) return fmt::format("light {}: sphere", i);
    return fmt::format("light {}: environment", i);
}

void slider(const char* label, float* v, float lo, float hi, bool log_scale = false) {
    ImGui::SliderFloat(label, v, lo, hi, "%.4g",
                       log_scale ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None);
    *v = std::clamp(*v, lo, hi);  // the scene loader's ranges
}

// A combo box over `items`; true when the selection changed.
bool combo(const char* label, int* index, const std::vector<std::string>& items) {
    bool changed = false;
    if (ImGui::BeginCombo(label, items[static_cast<size_t>(*index)].c_str())) {
        for (size_t i = 0; i < items.size(); ++i)
            if (ImGui::Selectable(items[i].c_str(), static_cast<int>(i) == *index)) {
                changed = static_cast<int>(i) != *index;
                *index = static_cast<int>(i);
            }
        ImGui::EndCombo();
    }
    return changed;
}

// Material controls; returns nothing, edits in place within the loader's ranges.
void material_panel(MaterialDesc& m) {
    if (m.type != MaterialDesc::Type::Glint) {
        const bool diffuse_part =
            m.type == MaterialDesc::Type::Diffuse || m.type == MaterialDesc::Type::Plastic;
        if (diffuse_part) ImGui::ColorEdit3("albedo", &m.albedo.x);
        if (m.type == MaterialDesc::Type::Diffuse) return;
        int ndf = m.ndf == NdfType::GGX ? 1 : 0;
        if (ImGui::Combo("ndf", &ndf, "beckmann\0ggx\0"))
            m.ndf = ndf == 1 ? NdfType::GGX : NdfType::Beckmann;
        slider("alpha x", &m.alpha_x, 1e-3f, 1.0f, true);
        slider("alpha y", &m.alpha_y, 1e-3f, 1.0f, true);
        if (m.type == MaterialDesc::Type::Conductor) {
            ImGui::DragFloat3("eta", &m.eta.x, 0.01f, 0.01f, 10.0f);
            ImGui::DragFloat3("k", &m.k.x, 0.01f, 0.0f, 20.0f);
        } else {
            slider("eta", &m.eta.x, 1.0f, 3.0f);
        }
        return;
    }
    GlintDesc& g = m.glint;
    // Model switcher: same material, any model the GPU implements.
    std::vector<const GlintModelInfo*> models;
    int current = 0;
    for (const GlintModelInfo& info : glint_models())
        if (gl::gpu_supports_model(info.id)) {
            if (info.id == g.model_id) current = static_cast<int>(models.size());
            models.push_back(&info);
        }
    if (ImGui::BeginCombo("model",
                          std::string(models[static_cast<size_t>(current)]->name).c_str())) {
        for (size_t i = 0; i < models.size(); ++i)
            if (ImGui::Selectable(std::string(models[i]->name).c_str(),
                                  static_cast<int>(i) == current))
                gl::reset_model_params(g, models[i]->id);
        ImGui::EndCombo();
    }
    int ndf = g.ndf == NdfType::GGX ? 1 : 0;
    if (g.model_id != GlintModelId::Chermain2020 && ImGui::Combo("ndf", &ndf, "beckmann\0ggx\0"))
        g.ndf = ndf == 1 ? NdfType::GGX : NdfType::Beckmann;
    slider("alpha x", &g.alpha_x, 1e-3f, 1.0f, true);
    slider("alpha y", &g.alpha_y, 1e-3f, 1.0f, true);
    slider("log density", &g.log_density, -20.0f, 60.0f);
    int seed = static_cast<int>(g.seed & 0x7fffffffu);
    if (ImGui::InputInt("seed", &seed)) g.seed = static_cast<uint32_t>(std::max(seed, 0));
    ImGui::ColorEdit3("colour", &g.color.x);
    int fresnel = static_cast<int>(g.fresnel.mode);
    if (ImGui::Combo("fresnel", &fresnel, "none\0schlick\0conductor\0dielectric\0"))
        g.fresnel.mode = static_cast<FresnelDesc::Mode>(fresnel);
    if (g.fresnel.mode == FresnelDesc::Mode::Schlick) ImGui::ColorEdit3("F0", &g.fresnel.f0.x);
    if (g.fresnel.mode == FresnelDesc::Mode::Conductor) {
        ImGui::DragFloat3("eta", &g.fresnel.eta.x, 0.01f, 0.01f, 10.0f);
        ImGui::DragFloat3("k", &g.fresnel.k.x, 0.01f, 0.0f, 20.0f);
    }
    if (g.fresnel.mode == FresnelDesc::Mode::Dielectric) {
        slider("eta", &g.fresnel.eta.x, 1.0f, 3.0f);
        // The diffuse base lies under the dielectric coat (glint_bxdf.h).
        ImGui::ColorEdit3("base albedo", &g.base_albedo.x);
    } else {
        g.base_albedo = glm::vec3(0.0f);  // the loader's rule: no coat, no base
    }
    // The model's own block: one widget per row of its descriptor's
    // parameter table (glint_panel_model.h), within the loader's ranges.
    // Decade sliders serve values whose every change costs a prefilter
    // (kneiphof2025's black level: ~0.5 s each unless the dynamic IBL is
    // on), so that dragging does not prefilter every intermediate value.
    for (GlintPanelWidget& w : glint_panel_model(g)) {
        const char* label = w.key.c_str();
        switch (w.type) {
            case GlintParamType::Number: {
                float v = static_cast<float>(std::get<double>(w.value));
                if (w.ui == GlintParamUi::Decades) {
                    int decade = static_cast<int>(std::lround(std::log10(v)));
                    if (ImGui::SliderInt(fmt::format("{} 10^", w.key).c_str(), &decade,
                                         static_cast<int>(std::ceil(std::log10(w.min))),
                                         static_cast<int>(std::floor(std::log10(w.max)))))
                        w.set(static_cast<double>(std::pow(10.0f, static_cast<float>(decade))));
                } else {
                    const float lo = static_cast<float>(w.min), hi = static_cast<float>(w.max);
                    if (ImGui::SliderFloat(label, &v, lo, hi, "%.4g",
                                           w.ui == GlintParamUi::Log ? ImGuiSliderFlags_Logarithmic
                                                                     : ImGuiSliderFlags_None))
                        w.set(static_cast<double>(std::clamp(v, lo, hi)));
                }
                break;
            }
            case GlintParamType::Integer: {
                int v = std::get<int>(w.value);
                if (!w.integer_values.empty()) {
                    int index = 0;
                    for (size_t i = 0; i < w.integer_values.size(); ++i)
                        if (w.integer_values[i] == v) index = static_cast<int>(i);
                    if (combo(label, &index, w.choices))
                        w.set(w.integer_values[static_cast<size_t>(index)]);
                } else if (ImGui::SliderInt(label, &v, static_cast<int>(w.min),
                                            static_cast<int>(w.max))) {
                    w.set(v);
                }
                break;
            }
            case GlintParamType::Bool: {
                bool v = std::get<bool>(w.value);
                if (ImGui::Checkbox(label, &v)) w.set(v);
                break;
            }
            case GlintParamType::Enum: {
                const std::string& v = std::get<std::string>(w.value);
                int index = 0;
                for (size_t i = 0; i < w.choices.size(); ++i)
                    if (w.choices[i] == v) index = static_cast<int>(i);
                if (combo(label, &index, w.choices)) w.set(w.choices[static_cast<size_t>(index)]);
                break;
            }
        }
    }
    // Colour lists outside the table (chermain2020's colour table).
    for (const GlintPanelColours& c : glint_panel_colours(g)) {
        ImGui::SliderInt(c.key.c_str(), c.count, 0, c.max_count);
        for (int i = 0; i < *c.count; ++i)
            ImGui::ColorEdit3(fmt::format("{} {}", c.key, i).c_str(), &c.colours[i].x);
    }
}

// The window's back buffer as displayed (sRGB bytes), decoded to linear so
// write_png encodes it back unchanged.
// Creates the parent directory of a screenshot path if needed.
void make_parent(const std::filesystem::path& path) {
    if (path.parent_path().empty()) return;
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
    if (ec) fail("{}: cannot create the directory: {}", path.parent_path().string(), ec.message());
}

void write_window(int w, int h, const std::filesystem::path& path) {
    make_parent(path);
    std::vector<unsigned char> rgba(static_cast<size_t>(w) * h * 4);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const unsigned char* px = &rgba[(static_cast<size_t>(h - 1 - y) * w + x) * 4];
            image.at(x, y) = glm::vec3(srgb_decode(px[0] / 255.0f), srgb_decode(px[1] / 255.0f),
                                       srgb_decode(px[2] / 255.0f));
        }
    write_png(image, path);
}

void write_screenshot(const GpuRenderer& renderer, const Scene& scene,
                      const std::filesystem::path& path) {
    make_parent(path);
    const Image image = renderer.read_image();
    const Image preview =
        scene.film.bloom.strength > 0.0f ? apply_bloom(image, scene.film.bloom) : image;
    write_png(preview, path, scene.film.exposure);
}

}  // namespace

void run_viewer(Scene scene, const ViewerOptions& options) {
    Glfw glfw;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_FALSE);
    const std::string title = fmt::format("glintlab view: {}", scene.file.filename().string());
    glfw.window =
        glfwCreateWindow(scene.camera.width, scene.camera.height, title.c_str(), nullptr, nullptr);
    if (glfw.window == nullptr)
        fail(
            "glintlab view: cannot create a window with an OpenGL 4.5 core context (the display's "
            "driver lacks OpenGL 4.5?)");
    glfwMakeContextCurrent(glfw.window);
    glfwSwapInterval(options.frames > 0 ? 0 : 1);
    require_gl45("glintlab view");

    OrbitState orbit_state;
    glfwSetWindowUserPointer(glfw.window, &orbit_state);
    glfwSetScrollCallback(glfw.window, scroll_callback);  // before ImGui, which chains to it

    GpuRenderer renderer(scene);
    gl::Program tonemap(
        gl::link_program(gl::background_vertex_shader(), gl::tonemap_fragment_shader(), "tonemap"));
    const GLint exposure_location = glGetUniformLocation(tonemap.get(), "u_exposure_scale");
    gl::VertexArray empty_vao = gl::make_vertex_array();
    gl::PassTimer display_timer, bloom_timer;
    gl::GpuBloom bloom;

    ImGuiScope imgui;
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside the user's files
    imgui.glfw = ImGui_ImplGlfw_InitForOpenGL(glfw.window, true);
    imgui.opengl = ImGui_ImplOpenGL3_Init("#version 450 core");
    if (!imgui.glfw || !imgui.opengl)
        fail("glintlab view: Dear ImGui back ends failed to initialise");

    float env_scale = 1.0f, env_rotation = 0.0f;
    if (scene.environment >= 0) {
        const auto& env =
            std::get<EnvironmentLight>(scene.lights[static_cast<size_t>(scene.environment)]);
        env_scale = env.map->scale();
        env_rotation = env.map->rotation_deg();
    }
    const std::filesystem::path shot_path = options.screenshot.empty()
                                                ? std::filesystem::path("glintlab_screenshot.png")
                                                : options.screenshot;
    PassHistory shadow_ms, background_ms, forward_ms, blur_ms, bloom_ms, display_ms;
    bool shadows = true;
    bool noise_texture = false;
    bool dynamic_ibl = options.dynamic_ibl;
    renderer.set_model_option("kneiphof2025", "dynamic_environment", dynamic_ibl);
    std::string status;
    int selected_material = 0;
    bool p_was_down = false;
    glm::dvec2 last_cursor(0.0);
    glfwGetCursorPos(glfw.window, &last_cursor.x, &last_cursor.y);

    for (int frame = 0; !glfwWindowShouldClose(glfw.window); ++frame) {
        glfwPollEvents();
        int fb_w = 0, fb_h = 0;
        glfwGetFramebufferSize(glfw.window, &fb_w, &fb_h);
        if (fb_w < 1 || fb_h < 1) continue;  // minimised
        scene.camera.width = fb_w;
        scene.camera.height = fb_h;

        ImGuiIO& io = ImGui::GetIO();
        glm::dvec2 cursor;
        glfwGetCursorPos(glfw.window, &cursor.x, &cursor.y);
        const glm::vec2 delta(cursor - last_cursor);
        last_cursor = cursor;
        if (!io.WantCaptureMouse) {
            const bool left = glfwGetMouseButton(glfw.window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
            const bool right =
                glfwGetMouseButton(glfw.window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
            orbit_camera(scene.camera, left ? delta : glm::vec2(0.0f),
                         right ? delta : glm::vec2(0.0f), orbit_state.scroll);
        }
        orbit_state.scroll = 0.0;
        const bool p_down = glfwGetKey(glfw.window, GLFW_KEY_P) == GLFW_PRESS;
        bool take_shot = p_down && !p_was_down && !io.WantCaptureKeyboard;
        p_was_down = p_down;

        renderer.set_environment(env_scale, env_rotation);
        renderer.render(scene);

        // Bloom (the PNG's filter, on the GPU), then the display: tonemap to
        // the window and the panel.
        bloom_timer.begin();
        const GLuint shown = bloom.apply(renderer.hdr_texture(), fb_w, fb_h, scene.film.bloom);
        bloom_timer.end();
        display_timer.begin();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, fb_w, fb_h);
        glDisable(GL_DEPTH_TEST);
        glUseProgram(tonemap.get());
        glProgramUniform1f(tonemap.get(), exposure_location, std::exp2(scene.film.exposure));
        glBindTextureUnit(0, shown);
        glBindVertexArray(empty_vao.get());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
        glUseProgram(0);
        if (options.show_ui) {
            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
            ImGui::SetNextWindowSize(ImVec2(340.0f, 0.45f * static_cast<float>(fb_h)),
                                     ImGuiCond_FirstUseEver);
            ImGui::SetNextWindowBgAlpha(0.8f);
            ImGui::Begin("glintlab");
            ImGui::PushItemWidth(170.0f);
            ImGui::TextUnformatted(gl_description().c_str());
            ImGui::Text("GPU ms, median of 60 frames (GL_TIME_ELAPSED)");
            ImGui::Text("shadow %.3f  background %.3f  forward %.3f", shadow_ms.median(),
                        background_ms.median(), forward_ms.median());
            ImGui::Text("wang2020 blur %.3f  bloom %.3f  display %.3f", blur_ms.median(),
                        bloom_ms.median(), display_ms.median());
            if (ImGui::Checkbox("shadows", &shadows)) renderer.set_shadows(shadows);
            ImGui::SliderFloat("exposure (stops)", &scene.film.exposure, -10.0f, 10.0f);
            if (ImGui::CollapsingHeader("bloom")) {
                slider("strength", &scene.film.bloom.strength, 0.0f, 1.0f);
                slider("radius (px)", &scene.film.bloom.radius_px, 0.5f, 64.0f);
                slider("threshold", &scene.film.bloom.threshold, 0.0f, 100.0f);
            }
            if (ImGui::Button("screenshot (P)")) take_shot = true;
            if (!status.empty()) ImGui::TextUnformatted(status.c_str());
            if (!scene.materials.empty() &&
                ImGui::CollapsingHeader("material", ImGuiTreeNodeFlags_DefaultOpen)) {
                selected_material =
                    std::clamp(selected_material, 0, static_cast<int>(scene.materials.size()) - 1);
                if (scene.materials.size() > 1)
                    ImGui::SliderInt("material", &selected_material, 0,
                                     static_cast<int>(scene.materials.size()) - 1);
                MaterialDesc& m = scene.materials[static_cast<size_t>(selected_material)];
                ImGui::Text("%s", m.name.c_str());
                material_panel(m);
                if (m.type == MaterialDesc::Type::Glint &&
                    m.glint.model_id == GlintModelId::Deliot2023 &&
                    ImGui::Checkbox("noise texture (000 6.3)", &noise_texture))
                    renderer.set_model_option("deliot2023", "noise_texture", noise_texture);
                // 003 §5: the prefilter as compute passes every frame.
                if (m.type == MaterialDesc::Type::Glint &&
                    m.glint.model_id == GlintModelId::Kneiphof2025 &&
                    ImGui::Checkbox("dynamic IBL (003 5)", &dynamic_ibl))
                    renderer.set_model_option("kneiphof2025", "dynamic_environment", dynamic_ibl);
            }
            if (ImGui::CollapsingHeader("lights")) {
                for (size_t i = 0; i < scene.lights.size(); ++i) {
                    ImGui::PushID(static_cast<int>(i));
                    ImGui::TextUnformatted(light_label(scene.lights[i], i).c_str());
                    if (auto* l = std::get_if<PointLight>(&scene.lights[i])) {
                        ImGui::DragFloat3("position", &l->position.x, 0.01f);
                        ImGui::DragFloat3("intensity W/sr", &l->intensity.x, 0.01f, 0.0f, 1e6f);
                    } else if (auto* l = std::get_if<DirectionalLight>(&scene.lights[i])) {
                        if (ImGui::DragFloat3("direction", &l->direction.x, 0.01f, -1.0f, 1.0f) &&
                            glm::dot(l->direction, l->direction) > 1e-8f)
                            l->direction = glm::normalize(l->direction);
                        ImGui::DragFloat3("irradiance W/m2", &l->irradiance.x, 0.01f, 0.0f, 1e6f);
                    } else if (auto* l = std::get_if<SphereLight>(&scene.lights[i])) {
                        ImGui::DragFloat3("radiance", &l->radiance.x, 0.01f, 0.0f, 1e6f);
                    } else if (renderer.has_environment()) {
                        slider("scale", &env_scale, 0.0f, 100.0f);
                        slider("rotation (deg)", &env_rotation, -180.0f, 180.0f);
                    }
                    ImGui::PopID();
                }
            }
            ImGui::PopItemWidth();
            ImGui::End();
            ImGui::Render();
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        }
        display_timer.end();

        const GpuPassTimes t = renderer.pass_times();
        shadow_ms.add(t.shadow_ms);
        background_ms.add(t.background_ms);
        forward_ms.add(t.forward_ms);
        blur_ms.add(t.glint_post_ms);
        bloom_ms.add(bloom_timer.elapsed_ms());
        display_ms.add(display_timer.elapsed_ms());

        const bool last = options.frames > 0 && frame + 1 >= options.frames;
        if (take_shot || (last && !options.screenshot.empty())) {
            write_screenshot(renderer, scene, shot_path);
            status = "saved " + shot_path.string();
        }
        if (last && !options.window_screenshot.empty())
            write_window(fb_w, fb_h, options.window_screenshot);
        glfwSwapBuffers(glfw.window);
        if (last) break;
    }
}

}  // namespace glintlab
