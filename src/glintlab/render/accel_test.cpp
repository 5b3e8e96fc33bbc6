// The Embree device must leave TBB's parallelism to the renderer.
#include <gtest/gtest.h>

#include <tbb/global_control.h>
#include <tbb/info.h>

#include "glintlab/loader/scene_loader.h"
#include "glintlab/render/accel.h"

namespace glintlab {
namespace {

// Embree's TBB scheduler keeps a process-wide tbb::global_control at the
// device's thread count: the "threads=1" device this project created from
// its first renderer capped every TBB loop at one thread while a scene was
// loaded, so CPU renders used one core whatever --threads said (and the
// renderer's thread-count test compared two single-threaded renders).
TEST(Accelerator, LeavesEveryCoreToTheRenderer) {
    nlohmann::json j = {{"film", {{"width", 8}, {"height", 8}}},
                        {"camera", {{"eye", {0, 0, 5}}, {"target", {0, 0, 0}}, {"fov_deg", 20}}},
                        {"materials", {{{"name", "d"}, {"type", "diffuse"}, {"albedo", 0.5}}}},
                        {"shapes", {{{"type", "sphere"}, {"radius", 1.0}, {"material", "d"}}}},
                        {"lights", {{{"type", "environment"}, {"radiance", 1.0}}}}};
    const Scene scene = parse_scene(j, "t.json");
    const Accelerator accel(scene);
    EXPECT_GE(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism),
              static_cast<size_t>(tbb::info::default_concurrency()));
}

}  // namespace
}  // namespace glintlab
