// `glintlab compare`: one scene rendered with every glint model that can
// shade its lights, each against the `explicit` ground truth, with the
// pixel-level metrics of compare/metrics.h (docs/VALIDATION.md "compare").
// The CLI (src/cmd/compare_command.cpp), `glintlab validate compare`
// (compare/validate_compare.h) and tests call run_compare().
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "glintlab/compare/metrics.h"
#include "glintlab/core/image.h"

namespace glintlab::compare {

struct CompareOptions {
    std::filesystem::path scene;
    std::vector<std::string> sets;    // POINTER=VALUE edits (loader/scene_edits.h), in order
    std::string material;             // the compared glint material; empty: the first one
    std::vector<std::string> models;  // empty: every model (the ground truth is always run)
    int realizations = 4;             // seeds per model, >= 2
    // Seeds of the explicit ground truth; 0: `realizations`. Under an
    // environment with a small bright source, sparse facets reflect it
    // rarely and one realization's mean is heavy-tailed (most miss it, a few
    // are many times brighter), so a few realizations underestimate the
    // truth's mean and their sample standard error hides it
    // (docs/VALIDATION.md "compare", heavy tail).
    int truth_realizations = 0;
    int width = 0, height = 0;  // 0: the scene's resolution
    int spp = 0;                // 0: the scene's samples per pixel
    int frames = 8;             // camera-path frames of the flicker measure, >= 2
    // Camera paths of the flicker measure: path p is realization p's
    // microstructure and sampling seed over the `frames` frames (its frame 0
    // is that realization's render). The flicker is their mean, with a
    // standard error: one path's flicker varies 2-3x between seeds where
    // few facets sparkle (docs/VALIDATION.md "compare"). In [1, 256].
    int flicker_paths = 4;
    double orbit_deg = 4.0;  // the path: an orbit about the target's up axis
    // Every model but the scene's own gets facets of the truth's angular
    // extent (facet_extent.h; false: the models' default parameters).
    bool match_facet_extent = true;
    bool gpu = false;   // real-time models on the OpenGL renderer (the truth stays on the CPU)
    int threads = 0;    // CPU render threads, 0: all cores
    uint64_t seed = 1;  // realization r uses render seed and glint seed seed + r
    // Optional: called after every render with (done, total) renders.
    std::function<void(int, int)> progress;
};

struct ModelMetrics {
    std::string model;
    bool compared = false;  // false: `reason` says why it was not rendered
    std::string reason;
    bool reference = false;       // the explicit ground truth itself
    std::string backend;          // "cpu" or "gpu"
    std::string truth;            // which ground-truth render it is compared with
    std::string facet_extent;     // the facets' extent it was given (facet_extent.h)
    double mean_luminance = 0.0;  // masked, averaged over realizations
    // Its standard error over the realizations, relative to it (the truth's
    // part of a model's mean_rel_err_se; validate compare re-runs a truth
    // whose part keeps a dense check inconclusive).
    double mean_luminance_rel_se = 0.0;
    double mean_rel_err = 0.0;      // vs the truth (0 for the truth)
    double mean_rel_err_se = 0.0;   // its standard error
    double blurred_rel_rmse = 0.0;  // after gaussian_blur(sigma = blur_sigma_px)
    double pixel_variance = 0.0;    // mean over the mask of the variance over realizations
    double variance_ratio = 0.0;    // pixel_variance / the truth's
    // The part of pixel_variance that is one render's sampling noise
    // (metrics.h sampling_pixel_variance of frame 0 and its resampled twin;
    // 0 for a deterministic render), and the rest, the microstructure's
    // variance (pixel_variance - sampling_variance, at least 0), as a ratio
    // to the truth's: the sparkle's strength without either estimator's
    // noise, which dominates a truth's pixel_variance under an environment
    // at a few spp (docs/VALIDATION.md "compare").
    double sampling_variance = 0.0;
    double structure_variance_ratio = 0.0;
    double wasserstein = 0.0;    // W1 of pooled luminance / the truth's mean
    double flicker = 0.0;        // metrics.h flicker, the mean over the flicker paths
    double flicker_se = 0.0;     // its standard error over the paths (0 for one path)
    double flicker_ratio = 0.0;  // flicker / the truth's
    // The ratio's standard error (first order: the relative standard errors
    // of the two flickers added in quadrature; 0 for the truth itself).
    double flicker_ratio_se = 0.0;
    // flicker between frame 0 and the same frame with another sampling seed
    // (same microstructure, same camera): the estimator's own sampling noise,
    // part of `flicker` for a Monte Carlo render, 0 for a deterministic one.
    double sampling_flicker = 0.0;
    double seconds = 0.0;  // mean render time of one image
    PixelFaults faults;    // over every image rendered for it
    // OpenGL rows: fragments whose shading loops the OpenGL implementation
    // cut short, over every image (GpuRenderer::cut_fragments; too dark).
    uint64_t cut_fragments = 0;
    Image image;       // realization 0 (for the grid)
    Plane mean_plane;  // luminance averaged over realizations
};

struct CompareResult {
    std::string scene;
    std::string material;
    std::string lights;  // "environment, directional", the scene's light types
    int width = 0, height = 0, spp = 0, realizations = 0, frames = 0;
    int truth_realizations = 0;  // of the explicit rows
    int flicker_paths = 0;
    double orbit_deg = 0.0;
    double blur_sigma_px = 0.0;
    int64_t mask_pixels = 0;           // pixels of the compared material (first frame)
    std::vector<ModelMetrics> models;  // the truth rows first, then model order
    Mask mask;

    const ModelMetrics* find(const std::string& model) const;
    nlohmann::json to_json() const;  // the metrics.json document
    std::string to_csv() const;      // metrics.csv: one row per model
    std::string to_text() const;     // the table the CLI prints
};

// Renders and measures; throws glintlab::Error (naming the file, option and
// allowed range) for a bad scene, material, model name or option.
CompareResult run_compare(const CompareOptions& options);

// Writes metrics.json, metrics.csv, grid.png (labelled: model, time, error),
// <model>.png / .exr (realization 0), <model>_diff.png (per-pixel signed
// difference of the realization means, blue = darker, red = brighter, full
// scale = 2x the truth's mean) and <model>_diff_blur.png (the same after the
// sparkle blur, relative, full scale +-50 %) into `dir` (created).
void write_compare_outputs(const CompareResult& result, const std::filesystem::path& dir);

}  // namespace glintlab::compare
