// `glintlab view`: a GLFW window showing the OpenGL renderer with a Dear
// ImGui panel — orbit camera (left drag: orbit, right drag: pan, wheel:
// dolly), model switcher (same material, any GPU model, with that model's
// default parameters), every material parameter live, light and environment
// controls, exposure, per-pass GPU milliseconds (GL_TIME_ELAPSED, median of
// the last N <= 60 frames), bloom (GPU, the filter of the PNGs) and a screenshot
// key (P). Screenshots are the linear
// frame read back and written by write_png with the scene's exposure and
// bloom: the PNG that `glintlab render --gpu` writes for the same view.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "glintlab/scene/scene.h"

namespace glintlab {

struct ViewerOptions {
    int frames = 0;  // > 0: close after this many frames (scripted use)
    std::filesystem::path
        screenshot;  // written after the last frame when set; P key target otherwise
    std::filesystem::path
        window_screenshot;  // the window as shown (panel included), after the last frame
    bool show_ui = true;
    // GPU options of the scene's models turned on at start ("OPTION" or
    // "MODEL.OPTION", find_scene_gpu_option; GpuRenderer::set_model_option);
    // the panel's checkboxes toggle them.
    std::vector<std::string> gpu_options;
    // After the last of `frames`: the panel's rectangle and every text item
    // and widget it drew, as JSON (ViewerPanelReport), for tests of its layout.
    std::filesystem::path panel_report;
};

// The panel's place in a framebuffer of fb_w x fb_h pixels, applied every
// frame (so it follows resizes): at the left edge, width 28% of the window
// within [280, 420] px and never over 35% of it (the scene's centre stays
// clear), height fitting its content up to the window's (it scrolls beyond).
struct ViewerPanelLayout {
    float x = 0.0f, y = 0.0f, width = 0.0f, max_height = 0.0f;
};
ViewerPanelLayout viewer_panel_layout(int fb_w, int fb_h);

// What the panel drew in one frame, in window pixels (origin top left).
struct ViewerPanelReport {
    struct Item {
        std::string label;
        float x0, y0, x1, y1;  // the item's rectangle, its label included
        bool visible;          // false: scrolled out (even partly) or under a collapsed header
    };
    int window_width = 0, window_height = 0;
    std::array<float, 4> panel{};  // x0, y0, x1, y1
    float content_max_x = 0.0f;    // right edge of the panel's content region
    int timing_frames = 0;         // N of "median of N frames"
    std::vector<Item> items;
};

// Runs until the window closes (or `frames` frames). Throws glintlab::Error
// when no window or OpenGL 4.5 core context can be created.
void run_viewer(Scene scene, const ViewerOptions& options);

}  // namespace glintlab
