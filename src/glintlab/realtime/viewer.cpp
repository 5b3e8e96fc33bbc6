#include "glintlab/realtime/viewer.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <fstream>
#include <string>
#include <vector>

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <fmt/format.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include "glintlab/core/bloom.h"
#include "glintlab/core/error.h"
#include "glintlab/core/image.h"
#include "glintlab/gl/gl_context.h"
#include "glintlab/gl/gl_handles.h"
#include "glintlab/gl/gl_program.h"
#include "glintlab/gl/gpu_timer.h"
#include "glintlab/glints/glint_panel_model.h"
#include "glintlab/glints/gpu_model_hooks.h"
#include "glintlab/glints/registry.h"
#include "glintlab/realtime/forward_shaders.h"
#include "glintlab/realtime/glint_programs.h"
#include "glintlab/realtime/gpu_bloom.h"
#include "glintlab/realtime/gpu_renderer.h"
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

// What the panel drew this frame, for --panel-report (ViewerPanelReport):
// every item's rectangle and the window's content region.
ViewerPanelReport* g_report = nullptr;

// Records the last item (text or widget with its label) under `what`.
void note(const std::string& what) {
    if (g_report == nullptr) return;
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    // Visible = wholly inside the panel's clip rectangle: an item cut by the
    // bottom edge of a panel that scrolls (more rows than the window's
    // height) is partly scrolled out, not drawn past the panel.
    const ImDrawList* dl = ImGui::GetWindowDrawList();
    const bool whole =
        lo.y >= dl->GetClipRectMin().y - 0.5f && hi.y <= dl->GetClipRectMax().y + 0.5f;
    g_report->items.push_back({what, lo.x, lo.y, hi.x, hi.y, ImGui::IsItemVisible() && whole});
}

// A text line that wraps at the panel's edge instead of running past it.
void text(const std::string& s) {
    ImGui::TextWrapped("%s", s.c_str());
    note(s);
}

// The label to give the next widget, `widget_w` wide: its own where it fits
// right of the widget; otherwise the label is drawn as a wrapped line above
// and the widget, given the full row, gets a hidden one ("##label").
// In a panel narrower than kSideBySideMinWidth (a small window: 35 % of
// 384 px is 130 px) every widget is stacked under its label at full width:
// side by side, a combo showed "beckn" for beckmann and a colour "2 2 1".
constexpr float kSideBySideMinWidth = 260.0f;
std::string fit_label(const std::string& label, float widget_w) {
    const float need = widget_w + ImGui::GetStyle().ItemInnerSpacing.x +
                       ImGui::CalcTextSize(label.c_str(), nullptr, true).x;
    const float avail = ImGui::GetContentRegionAvail().x;
    if (need <= avail && avail >= kSideBySideMinWidth) return label;
    text(label);
    ImGui::SetNextItemWidth(-FLT_MIN);
    return "##" + label;
}

// fit_label for a widget of the pushed item width (sliders, combos).
std::string fit_label(const std::string& label) {
    return fit_label(label, ImGui::CalcItemWidth());
}

void slider(const char* name, float* v, float lo, float hi, bool log_scale = false) {
    const std::string label = fit_label(name);
    ImGui::SliderFloat(label.c_str(), v, lo, hi, "%.4g",
                       log_scale ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None);
    note(name);
    *v = std::clamp(*v, lo, hi);  // the scene loader's ranges
}

// A combo box over `items`; true when the selection changed.
bool combo(const char* name, int* index, const std::vector<std::string>& items) {
    bool changed = false;
    const std::string label = fit_label(name);
    if (ImGui::BeginCombo(label.c_str(), items[static_cast<size_t>(*index)].c_str())) {
        for (size_t i = 0; i < items.size(); ++i)
            if (ImGui::Selectable(items[i].c_str(), static_cast<int>(i) == *index)) {
                changed = static_cast<int>(i) != *index;
                *index = static_cast<int>(i);
            }
        ImGui::EndCombo();
    }
    note(name);
    return changed;
}

// The model switcher: same material, any model the GPU implements (with
// that model's default parameters).
void model_switcher(GlintDesc& g) {
    std::vector<const GlintModelInfo*> models;
    int current = 0;
    for (const GlintModelInfo& info : glint_models())
        if (gl::gpu_supports_model(info.id)) {
            if (info.id == g.model_id) current = static_cast<int>(models.size());
            models.push_back(&info);
        }
    if (ImGui::BeginCombo(fit_label("model").c_str(),
                          std::string(models[static_cast<size_t>(current)]->name).c_str())) {
        for (size_t i = 0; i < models.size(); ++i)
            if (ImGui::Selectable(std::string(models[i]->name).c_str(),
                                  static_cast<int>(i) == current))
                switch_glint_model(g, models[i]->id);
        ImGui::EndCombo();
    }
    note("model");
}

// Material controls; edits in place within the loader's ranges.
void material_panel(MaterialDesc& m) {
    // Parameters read from textures have no number to edit: the panel names
    // them and leaves their widgets out.
    const MaterialTextures* mt = m.textures.get();
    const GlintTextures* gt = m.glint.textures.get();
    if (m.textured()) text(fmt::format("from textures: {}", textured_keys(m)));
    if (m.type != MaterialDesc::Type::Glint) {
        const bool metallic_roughness = m.type == MaterialDesc::Type::MetallicRoughness;
        const bool diffuse_part = m.type == MaterialDesc::Type::Diffuse ||
                                  m.type == MaterialDesc::Type::Plastic || metallic_roughness;
        if (diffuse_part && !(mt && mt->albedo)) {
            const char* key = metallic_roughness ? "base_color" : "albedo";
            ImGui::ColorEdit3(fit_label(key).c_str(), &m.albedo.x);
            note(key);
        }
        if (metallic_roughness && !(mt && mt->metallic))
            slider("metallic", &m.metallic, 0.0f, 1.0f);
        if (m.type == MaterialDesc::Type::Diffuse) return;
        int ndf = m.ndf == NdfType::GGX ? 1 : 0;
        if (ImGui::Combo(fit_label("ndf").c_str(), &ndf, "beckmann\0ggx\0"))
            m.ndf = ndf == 1 ? NdfType::GGX : NdfType::Beckmann;
        note("ndf");
        if (!(mt && mt->alpha_x_sq)) slider("alpha x", &m.alpha_x, 1e-3f, 1.0f, true);
        if (!(mt && mt->alpha_y_sq)) slider("alpha y", &m.alpha_y, 1e-3f, 1.0f, true);
        if (m.type == MaterialDesc::Type::Conductor) {
            ImGui::DragFloat3(fit_label("eta").c_str(), &m.eta.x, 0.01f, 0.01f, 10.0f);
            note("eta");
            ImGui::DragFloat3(fit_label("k").c_str(), &m.k.x, 0.01f, 0.0f, 20.0f);
            note("k");
        } else {
            slider("eta", &m.eta.x, 1.0f, 3.0f);
        }
        return;
    }
    GlintDesc& g = m.glint;
    // The NDF is editable unless the model accepts only one (its descriptor's
    // fit_material then sets it back: chermain2020, kneiphof2025, wang2020).
    const GlintModelDescriptor& model = glint_model(g.model_id);
    GlintDesc probe = g;
    probe.ndf = g.ndf == NdfType::GGX ? NdfType::Beckmann : NdfType::GGX;
    if (model.fit_material != nullptr) model.fit_material(probe);
    if (probe.ndf != g.ndf) {
        int ndf = g.ndf == NdfType::GGX ? 1 : 0;
        if (ImGui::Combo(fit_label("ndf").c_str(), &ndf, "beckmann\0ggx\0"))
            g.ndf = ndf == 1 ? NdfType::GGX : NdfType::Beckmann;
        note("ndf");
    }
    if (!(gt && gt->alpha_x_sq)) slider("alpha x", &g.alpha_x, 1e-3f, 1.0f, true);
    if (!(gt && gt->alpha_y_sq)) slider("alpha y", &g.alpha_y, 1e-3f, 1.0f, true);
    if (!(gt && gt->density)) slider("log density", &g.log_density, -20.0f, 60.0f);
    int seed = static_cast<int>(g.seed & 0x7fffffffu);
    if (ImGui::InputInt("seed", &seed)) g.seed = static_cast<uint32_t>(std::max(seed, 0));
    note("seed");
    if (!(gt && gt->color)) {
        ImGui::ColorEdit3(fit_label("colour").c_str(), &g.color.x);
        note("colour");
    }
    int fresnel = static_cast<int>(g.fresnel.mode);
    if (ImGui::Combo(fit_label("fresnel").c_str(), &fresnel,
                     "none\0schlick\0conductor\0dielectric\0"))
        g.fresnel.mode = static_cast<FresnelDesc::Mode>(fresnel);
    note("fresnel");
    if (g.fresnel.mode == FresnelDesc::Mode::Schlick) {
        ImGui::ColorEdit3(fit_label("F0").c_str(), &g.fresnel.f0.x);
        note("F0");
    }
    if (g.fresnel.mode == FresnelDesc::Mode::Conductor) {
        ImGui::DragFloat3(fit_label("eta").c_str(), &g.fresnel.eta.x, 0.01f, 0.01f, 10.0f);
        note("eta");
        ImGui::DragFloat3(fit_label("k").c_str(), &g.fresnel.k.x, 0.01f, 0.0f, 20.0f);
        note("k");
    }
    if (g.fresnel.mode == FresnelDesc::Mode::Dielectric) {
        slider("eta", &g.fresnel.eta.x, 1.0f, 3.0f);
        // The diffuse base lies under the dielectric coat (glint_bxdf.h).
        if (!(gt && gt->base_albedo)) {
            ImGui::ColorEdit3(fit_label("base albedo").c_str(), &g.base_albedo.x);
            note("base albedo");
        }
    } else {
        g.base_albedo = glm::vec3(0.0f);  // the loader's rule: no coat, no base
    }
    // The model's own block: one widget per row of its descriptor's
    // parameter table (glint_panel_model.h), within the loader's ranges.
    // Decade sliders serve values whose every change costs a prefilter
    // (kneiphof2025's black level: ~0.5 s each unless the dynamic IBL is
    // on), so that dragging does not prefilter every intermediate value.
    for (GlintPanelWidget& w : glint_panel_model(g)) {
        // Checkboxes are a square, every other widget the pushed width.
        const bool decades = w.type == GlintParamType::Number && w.ui == GlintParamUi::Decades;
        const std::string fitted = w.type == GlintParamType::Bool
                                       ? fit_label(w.key, ImGui::GetFrameHeight())
                                       : fit_label(decades ? w.key + " 10^" : w.key);
        const char* label = fitted.c_str();
        switch (w.type) {
            case GlintParamType::Number: {
                float v = static_cast<float>(std::get<double>(w.value));
                if (decades) {
                    int decade = static_cast<int>(std::lround(std::log10(v)));
                    if (ImGui::SliderInt(label, &decade,
                                         static_cast<int>(std::ceil(std::log10(w.min))),
                                         static_cast<int>(std::floor(std::log10(w.max)))))
                        w.set(static_cast<double>(std::pow(10.0f, static_cast<float>(decade))));
                    note(w.key);
                } else {
                    const float lo = static_cast<float>(w.min), hi = static_cast<float>(w.max);
                    if (ImGui::SliderFloat(label, &v, lo, hi, "%.4g",
                                           w.ui == GlintParamUi::Log ? ImGuiSliderFlags_Logarithmic
                                                                     : ImGuiSliderFlags_None))
                        w.set(static_cast<double>(std::clamp(v, lo, hi)));
                    note(w.key);
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
                if (w.integer_values.empty()) note(w.key);
                break;
            }
            case GlintParamType::Bool: {
                bool v = std::get<bool>(w.value);
                if (ImGui::Checkbox(label, &v)) w.set(v);
                note(w.key);
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
        ImGui::SliderInt(fit_label(c.key).c_str(), c.count, 0, c.max_count);
        note(c.key);
        for (int i = 0; i < *c.count; ++i) {
            const std::string key = fmt::format("{} {}", c.key, i);
            ImGui::ColorEdit3(fit_label(key).c_str(), &c.colours[i].x);
            note(key);
        }
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

void write_panel_report(const ViewerPanelReport& r, const std::filesystem::path& path) {
    make_parent(path);
    nlohmann::json items = nlohmann::json::array();
    for (const ViewerPanelReport::Item& i : r.items)
        items.push_back(
            {{"label", i.label}, {"rect", {i.x0, i.y0, i.x1, i.y1}}, {"visible", i.visible}});
    const nlohmann::json j = {{"window", {r.window_width, r.window_height}},
                              {"panel", {r.panel[0], r.panel[1], r.panel[2], r.panel[3]}},
                              {"content_max_x", r.content_max_x},
                              {"timing_frames", r.timing_frames},
                              {"items", items}};
    std::ofstream out(path);
    out << j.dump(1) << "\n";
    if (!out) fail("{}: cannot write the panel report", path.string());
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

ViewerPanelLayout viewer_panel_layout(int fb_w, int fb_h) {
    const float w = static_cast<float>(fb_w), h = static_cast<float>(fb_h);
    ViewerPanelLayout l;
    l.x = l.y = std::min(8.0f, 0.01f * w);
    // 28% of the width within [280, 420] px, never more than 35% of the
    // window: the scene's centre stays clear.
    l.width = std::floor(std::min(std::clamp(0.28f * w, 280.0f, 420.0f), 0.35f * w - l.x));
    l.max_height = std::max(h - 2.0f * l.y, 1.0f);
    return l;
}

void run_viewer(Scene scene, const ViewerOptions& options) {
    for (const std::string& name : options.gpu_options)
        find_scene_gpu_option(scene, name);  // before any window: throws on an unknown name
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
    for (const std::string& name : options.gpu_options) {
        const GpuModelOptionName o = find_scene_gpu_option(scene, name);
        renderer.set_model_option(o.model, o.option, true);
    }
    std::string status;
    uint64_t cut_fragments = 0;  // the last frame's (GpuRenderer::cut_fragments)
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

        const bool last = options.frames > 0 && frame + 1 >= options.frames;
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
            // Re-laid out every frame from the framebuffer: a resized window
            // gets a panel that fits it (viewer_panel_layout).
            const ViewerPanelLayout layout = viewer_panel_layout(fb_w, fb_h);
            ImGui::SetNextWindowPos(ImVec2(layout.x, layout.y), ImGuiCond_Always);
            ImGui::SetNextWindowSizeConstraints(ImVec2(layout.width, 0.0f),
                                                ImVec2(layout.width, layout.max_height));
            ImGui::SetNextWindowBgAlpha(0.8f);
            ViewerPanelReport report;
            report.window_width = fb_w;
            report.window_height = fb_h;
            const bool want_report = last && !options.panel_report.empty();
            g_report = want_report ? &report : nullptr;
            ImGui::Begin("glintlab", nullptr,
                         ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove);
            // Widgets take 55% of the row, their labels the rest.
            ImGui::PushItemWidth(std::floor(0.55f * ImGui::GetContentRegionAvail().x));
            if (!scene.materials.empty() &&
                ImGui::CollapsingHeader("Model", ImGuiTreeNodeFlags_DefaultOpen)) {
                selected_material =
                    std::clamp(selected_material, 0, static_cast<int>(scene.materials.size()) - 1);
                if (scene.materials.size() > 1) {
                    ImGui::SliderInt(fit_label("material").c_str(), &selected_material, 0,
                                     static_cast<int>(scene.materials.size()) - 1);
                    note("material");
                }
                MaterialDesc& m = scene.materials[static_cast<size_t>(selected_material)];
                text(fmt::format("material \"{}\"", m.name));
                if (m.type == MaterialDesc::Type::Glint)
                    model_switcher(m.glint);
                else
                    text("not a glint material: no model to switch");
            }
            if (!scene.materials.empty() &&
                ImGui::CollapsingHeader("Material parameters", ImGuiTreeNodeFlags_DefaultOpen)) {
                MaterialDesc& m = scene.materials[static_cast<size_t>(selected_material)];
                material_panel(m);
                // The model's GPU options (GpuModelHooks: deliot2023's noise
                // texture, kneiphof2025's dynamic IBL of 003 §5, ...).
                if (m.type == MaterialDesc::Type::Glint)
                    if (const GpuModelHooks* hooks = find_gpu_model_hooks(m.glint.model_id)) {
                        const std::string model(glint_model(m.glint.model_id).name);
                        for (const GpuModelOption& o : hooks->options) {
                            const std::string label(o.name);
                            bool on = renderer.model_option(model, o.name);
                            if (ImGui::Checkbox(fit_label(label, ImGui::GetFrameHeight()).c_str(),
                                                &on))
                                renderer.set_model_option(model, o.name, on);
                            if (ImGui::IsItemHovered())
                                ImGui::SetTooltip("%s", std::string(o.description).c_str());
                            note(label);
                        }
                    }
            }
            if (ImGui::CollapsingHeader("Lights")) {
                for (size_t i = 0; i < scene.lights.size(); ++i) {
                    if (std::holds_alternative<EnvironmentLight>(scene.lights[i]))
                        continue;  // under Environment
                    ImGui::PushID(static_cast<int>(i));
                    text(light_label(scene.lights[i], i));
                    if (auto* l = std::get_if<PointLight>(&scene.lights[i])) {
                        ImGui::DragFloat3(fit_label("position").c_str(), &l->position.x, 0.01f);
                        note("position");
                        ImGui::DragFloat3(fit_label("intensity W/sr").c_str(), &l->intensity.x,
                                          0.01f, 0.0f, 1e6f);
                        note("intensity W/sr");
                    } else if (auto* l = std::get_if<DirectionalLight>(&scene.lights[i])) {
                        if (ImGui::DragFloat3(fit_label("direction").c_str(), &l->direction.x,
                                              0.01f, -1.0f, 1.0f) &&
                            glm::dot(l->direction, l->direction) > 1e-8f)
                            l->direction = glm::normalize(l->direction);
                        note("direction");
                        ImGui::DragFloat3(fit_label("irradiance W/m2").c_str(), &l->irradiance.x,
                                          0.01f, 0.0f, 1e6f);
                        note("irradiance W/m2");
                    } else if (auto* l = std::get_if<SphereLight>(&scene.lights[i])) {
                        ImGui::DragFloat3(fit_label("radiance").c_str(), &l->radiance.x, 0.01f,
                                          0.0f, 1e6f);
                        note("radiance");
                    }
                    ImGui::PopID();
                }
            }
            if (ImGui::CollapsingHeader("Environment")) {
                if (renderer.has_environment()) {
                    slider("scale", &env_scale, 0.0f, 100.0f);
                    slider("rotation (deg)", &env_rotation, -180.0f, 180.0f);
                } else {
                    text("no environment light in this scene");
                }
            }
            if (ImGui::CollapsingHeader("View")) {
                if (ImGui::Checkbox(fit_label("shadows", ImGui::GetFrameHeight()).c_str(),
                                    &shadows))
                    renderer.set_shadows(shadows);
                note("shadows");
                slider("exposure (stops)", &scene.film.exposure, -10.0f, 10.0f);
                text("bloom");
                slider("strength", &scene.film.bloom.strength, 0.0f, 1.0f);
                slider("radius (px)", &scene.film.bloom.radius_px, 0.5f, 64.0f);
                slider("threshold", &scene.film.bloom.threshold, 0.0f, 100.0f);
                if (ImGui::Button("screenshot (P)")) take_shot = true;
                note("screenshot (P)");
                if (!status.empty()) text(status);
            }
            if (ImGui::CollapsingHeader("Timings", ImGuiTreeNodeFlags_DefaultOpen)) {
                text(gl_description());
                if (cut_fragments > 0) text(cut_fragments_warning(cut_fragments));
                // The history holds the frames so far, up to 60.
                report.timing_frames = static_cast<int>(shadow_ms.ms.size());
                text(fmt::format("GPU ms (GL_TIME_ELAPSED), median of {} frame{}",
                                 report.timing_frames, report.timing_frames == 1 ? "" : "s"));
                if (report.timing_frames > 0) {
                    text(fmt::format("shadow {:.3f}", shadow_ms.median()));
                    text(fmt::format("background {:.3f}", background_ms.median()));
                    text(fmt::format("forward {:.3f}", forward_ms.median()));
                    text(fmt::format("wang2020 blur {:.3f}", blur_ms.median()));
                    text(fmt::format("bloom {:.3f}", bloom_ms.median()));
                    text(fmt::format("display {:.3f}", display_ms.median()));
                }
            }
            const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
            report.panel = {pos.x, pos.y, pos.x + size.x, pos.y + size.y};
            report.content_max_x = pos.x + ImGui::GetWindowContentRegionMax().x;
            g_report = nullptr;
            if (want_report) write_panel_report(report, options.panel_report);
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
        cut_fragments = renderer.cut_fragments();
        blur_ms.add(t.glint_post_ms);
        bloom_ms.add(bloom_timer.elapsed_ms());
        display_ms.add(display_timer.elapsed_ms());

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
