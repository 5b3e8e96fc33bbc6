// 001 Table 3's passes for one wang2020 point of `glintlab bench --gpu`
// (table1_gpu.cpp): the table builds of the model the frames used (the
// cached CPU builds that GpuRenderer uploaded: DPF extraction with the γ
// accumulation, quadtree, environment prefilter on scenes with an
// environment) and the §4.4 post-process blur passes (GpuWang2020Blur) on
// the rendered frame, timed by wall clock with glFinish (llvmpipe's timer
// queries do not cover its deferred work, docs/BENCHMARKS.md).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "glintlab/core/image.h"

namespace glintlab {

struct Scene;

namespace gl {

// Appends one value per pass to `passes`: dpf_extract_ms, quadtree_ms,
// prefilter_ms (environment scenes only), blur_ms (median of `frames`
// applications on `frame`, visibility 1). Throws glintlab::Error when the
// scene has no wang2020 material.
void time_wang2020_passes(const Scene& scene, const Image& frame, int frames,
                          std::map<std::string, std::vector<double>>& passes);

}  // namespace gl
}  // namespace glintlab
