// The memory a render of a scene takes, item by item, for require_memory()
// (core/memory_limit.h): the film and its per-pixel buffers, the meshes and
// their acceleration structure, the environment map and its sampling
// distribution. Estimates (within a factor ~2 of what is allocated), meant to
// stop a run that would exhaust the machine, not to account for every byte.
#pragma once

#include <vector>

#include "glintlab/core/memory_limit.h"
#include "glintlab/scene/scene.h"

namespace glintlab {

std::vector<MemoryItem> estimate_render_memory(const Scene& scene, bool gpu);

}  // namespace glintlab
