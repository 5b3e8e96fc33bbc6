// `glintlab view`: a GLFW window showing the OpenGL renderer with a Dear
// ImGui panel — orbit camera (left drag: orbit, right drag: pan, wheel:
// dolly), model switcher (same material, any GPU model, with that model's
// default parameters), every material parameter live, light and environment
// controls, exposure, per-pass GPU milliseconds (GL_TIME_ELAPSED, median of
// the last 60 frames), bloom (GPU, the filter of the PNGs) and a screenshot
// key (P). Screenshots are the linear
// frame read back and written by write_png with the scene's exposure and
// bloom: the PNG that `glintlab render --gpu` writes for the same view.
#pragma once

#include <filesystem>

#include "glintlab/scene/scene.h"

namespace glintlab {

struct ViewerOptions {
    int frames = 0;  // > 0: close after this many frames (scripted use)
    std::filesystem::path
        screenshot;  // written after the last frame when set; P key target otherwise
    std::filesystem::path
        window_screenshot;  // the window as shown (panel included), after the last frame
    bool show_ui = true;
    // kneiphof2025's environment prefiltered by compute passes every frame
    // (003 §5, GpuRenderer::set_model_option "kneiphof2025" "dynamic_environment"); the
    // panel's "dynamic IBL" checkbox toggles it.
    bool dynamic_ibl = false;
};

// Runs until the window closes (or `frames` frames). Throws glintlab::Error
// when no window or OpenGL 4.5 core context can be created.
void run_viewer(Scene scene, const ViewerOptions& options);

}  // namespace glintlab
