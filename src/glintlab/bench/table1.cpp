#include "glintlab/bench/table1.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "glintlab/core/error.h"
#include "glintlab/glints/registry.h"
#include "glintlab/loader/scene_edits.h"
#include "glintlab/loader/scene_loader.h"
#include "glintlab/render/accel.h"
#include "glintlab/render/renderer.h"
#if GLINTLAB_WITH_GL
#include "glintlab/bench/table1_003_gpu.h"
#include "glintlab/bench/table1_gpu.h"
#endif

namespace glintlab {
namespace {

const char* const kPeerChermain2020 = "PEER_CHERMAIN2020";

// Camera at `elevation_deg` above a plane (90° = straight down), as the
// PLANE / HEIGHTMAP rows of 000 Table 1.
nlohmann::json camera_at(float elevation_deg, float distance) {
    const float e = glm::radians(elevation_deg);
    nlohmann::json c = {{"eye", {0.0f, distance * std::sin(e), distance * std::cos(e)}},
                        {"target", {0, 0, 0}},
                        {"fov_deg", 45}};
    if (elevation_deg > 89.0f) c["up"] = {0, 0, -1};
    return c;
}

nlohmann::json scene_json(const std::string& name) {
    nlohmann::json j;
    j["lights"] = {{{"type", "directional"}, {"direction", {0.3, 0.8, 0.5}}, {"irradiance", 2.0}}};
    j["render"] = {{"integrator", "direct"}, {"spp", 1}, {"seed", 1}};
    const nlohmann::json quad = {
        {"type", "quad"}, {"size", {8, 8}}, {"uv_scale", {8, 8}}, {"material", "g"}};
    const nlohmann::json heightfield = {
        {"type", "heightfield"}, {"size", {8, 8}},  {"uv_scale", {8, 8}}, {"resolution", 512},
        {"amplitude", 0.05},     {"frequency", 24}, {"octaves", 4},       {"material", "g"}};
    if (name == "PLANE_90" || name == "PLANE_25") {
        j["camera"] = camera_at(name == "PLANE_90" ? 90.0f : 25.0f, 3.0f);
        j["shapes"] = nlohmann::json::array({quad});
    } else if (name == "HEIGHTMAP_90" || name == "HEIGHTMAP_25") {
        j["camera"] = camera_at(name == "HEIGHTMAP_90" ? 90.0f : 25.0f, 3.0f);
        j["shapes"] = nlohmann::json::array({heightfield});
    } else if (name == "SPHERE") {
        j["camera"] = {{"eye", {0, 0, 3.2}}, {"target", {0, 0, 0}}, {"fov_deg", 45}};
        j["shapes"] = {{{"type", "sphere"}, {"radius", 1.0}, {"material", "g"}}};
    } else if (name == "MONKEY") {
        // 000's MONKEY: a procedural monkey-like head (scene/shapes.h make_head).
        j["camera"] = {{"eye", {0.8, 0.5, 3.2}}, {"target", {0, 0, 0}}, {"fov_deg", 45}};
        j["shapes"] = {{{"type", "head"}, {"uv_scale", {4, 2}}, {"material", "g"}}};
    } else if (name == "TORUS") {
        j["camera"] = {{"eye", {0, 1.6, 2.4}}, {"target", {0, 0, 0}}, {"fov_deg", 45}};
        j["shapes"] = {{{"type", "torus"},
                        {"major_radius", 0.9},
                        {"minor_radius", 0.35},
                        {"uv_scale", {4, 2}},
                        {"material", "g"}}};
    } else if (name == kPeerChermain2020) {
        // The configuration of chermain2020's official viewer:
        // UV sphere of radius 1 seen from (0, 0, 2.2) down -z, 60 deg
        // vertical fov, one point light at (5, 5, 5) of intensity 100; the
        // material (Beckmann alpha 0.5, zeta = 2) in table1_scene_json.
        j["camera"] = {{"eye", {0, 0, 2.2}}, {"target", {0, 0, 0}}, {"fov_deg", 60}};
        j["shapes"] = {{{"type", "sphere"}, {"radius", 1.0}, {"material", "g"}}};
        j["lights"] = {{{"type", "point"}, {"position", {5, 5, 5}}, {"intensity", 100.0}}};
    } else if (name == "MANY") {
        j["camera"] = {{"eye", {0, 9, 9}}, {"target", {0, 0, 0}}, {"fov_deg", 50}};
        nlohmann::json shapes = nlohmann::json::array({quad});
        for (int z = 0; z < 8; ++z)
            for (int x = 0; x < 8; ++x)
                shapes.push_back({{"type", "sphere"},
                                  {"center", {x - 3.5, 0.4, z - 3.5}},
                                  {"radius", 0.4},
                                  {"material", "g"}});
        j["shapes"] = shapes;
    } else {
        fail("bench: unknown scene \"{}\" (known: {})", name,
             fmt::join(table1_scene_names(), ", "));
    }
    return j;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

nlohmann::json table1_scene_json(const std::string& scene_name, const std::string& model,
                                 float log_density, int width, int height) {
    nlohmann::json j = scene_json(scene_name);
    j["film"] = {{"width", width}, {"height", height}};
    j["materials"] = {{{"name", "g"},
                       {"type", "glint"},
                       {"model", model},
                       {"ndf", "beckmann"},
                       {"roughness", 0.3},
                       {"log_density", log_density},
                       {"fresnel", {{"type", "conductor"}, {"metal", "silver"}}}}};
    if (scene_name == kPeerChermain2020) {
        j["materials"][0]["roughness"] = 0.5;
        if (model == "chermain2020")
            j["materials"][0]["chermain2020"] = {{"density_randomization", 2.0}};
    }
    return j;
}

std::vector<std::string> table1_scene_names() {
    return {"PLANE_90", "PLANE_25", "HEIGHTMAP_90", "HEIGHTMAP_25", "SPHERE", "MONKEY", "MANY"};
}

std::vector<Table1Row> run_table1(const Table1Options& options) {
    if (options.table == "003") {
        if (!options.gpu) fail("bench --table 003: 003 Table 1 is a GPU table (add --gpu)");
#if GLINTLAB_WITH_GL
        return run_table1_003_gpu(options);
#else
        fail("bench --gpu: this glintlab was built without OpenGL (GLINTLAB_WITH_GL=OFF)");
#endif
    }
    if (options.table != "000")
        fail("bench: unknown --table \"{}\" (known: 000, 003)", options.table);
    std::vector<std::string> scenes =
        options.scenes.empty() ? table1_scene_names() : options.scenes;
    std::vector<std::string> models = options.models;
    // 000 Table 1 compares the smooth model with the three real-time
    // point-light models; others (offline, IBL) are benchmarked on request.
    if (models.empty()) models = {"smooth", "deliot2023", "zirr2016", "chermain2020"};
    for (const std::string& m : models)
        if (!find_glint_model(m))
            fail("bench: unknown model \"{}\" (known: {})", m, glint_model_names());
    if (options.gpu) {
#if GLINTLAB_WITH_GL
        return run_table1_gpu(options, scenes, models);
#else
        fail("bench --gpu: this glintlab was built without OpenGL (GLINTLAB_WITH_GL=OFF)");
#endif
    }
    std::vector<Table1Row> rows;
    for (const std::string& scene_name : scenes) {
        for (const std::string& model : models) {
            Table1Row row;
            row.scene = scene_name;
            row.model = model;
            for (float log_density : options.log_densities) {
                const nlohmann::json j =
                    table1_scene_document(options, scene_name, model, log_density);
                const Scene scene = parse_scene(j, "bench:" + scene_name);
                std::vector<double> times;
                // Frame time = shading + ray casting, without the BVH build
                // (a real-time renderer keeps its geometry between frames).
                const Accelerator accel(scene);
                const RenderOptions ro{options.threads, true};
                render_scene(scene, accel, ro);  // warm-up
                for (int f = 0; f < options.frames; ++f) {
                    const auto t0 = std::chrono::steady_clock::now();
                    render_scene(scene, accel, ro);
                    times.push_back(std::chrono::duration<double, std::milli>(
                                        std::chrono::steady_clock::now() - t0)
                                        .count());
                }
                row.ms_per_density.push_back(median(times));
            }
            row.min_ms = *std::min_element(row.ms_per_density.begin(), row.ms_per_density.end());
            row.max_ms = *std::max_element(row.ms_per_density.begin(), row.ms_per_density.end());
            rows.push_back(std::move(row));
        }
    }
    return rows;
}

nlohmann::json table1_scene_document(const Table1Options& options, const std::string& scene,
                                     const std::string& model, float log_density) {
    nlohmann::json j = table1_scene_json(scene, model, log_density, options.width, options.height);
    for (const std::string& set : options.sets) apply_override_assignment(j, set);
    return j;
}

nlohmann::json table1_to_json(const Table1Options& o, const std::vector<Table1Row>& rows) {
    nlohmann::json j;
    j["benchmark"] = o.table == "003" ? "table1_003_gpu" : o.gpu ? "table1_gpu" : "table1_cpu";
    j["integrator"] = o.gpu ? "opengl_forward" : "direct";
#if GLINTLAB_WITH_GL
    if (o.gpu) {
        j["device"] = gpu_bench_device();
        j["deliot2023_noise_texture"] = o.gpu_noise_texture;
        j["deliot2023_stochastic_grid"] = o.gpu_stochastic_grid;
    }
#endif
    j["resolution"] = {o.width, o.height};
    if (!o.sets.empty()) j["sets"] = o.sets;
    j["frames"] = o.frames;
    j["log_densities"] = o.log_densities;
    nlohmann::json arr = nlohmann::json::array();
    for (const Table1Row& r : rows) {
        nlohmann::json row = {{"scene", r.scene},
                              {"model", r.model},
                              {"min_ms", r.min_ms},
                              {"max_ms", r.max_ms},
                              {"ms_per_density", r.ms_per_density}};
        if (o.gpu) {
            row["p90_ms_per_density"] = r.p90_ms_per_density;
            row["frame_ms_per_density"] = r.frame_ms_per_density;
            row["first_frame_ms_per_density"] = r.first_frame_ms_per_density;
            row["shadow_ms_per_density"] = r.shadow_ms_per_density;
            row["background_ms_per_density"] = r.background_ms_per_density;
            if (!r.pass_ms_per_density.empty()) row["pass_ms_per_density"] = r.pass_ms_per_density;
        }
        arr.push_back(row);
    }
    j["results"] = arr;
    return j;
}

std::string table1_to_text(const Table1Options& o, const std::vector<Table1Row>& rows) {
    std::string s = fmt::format(
        "{} Table 1 {}, {}x{}, median of {} frames, min-max over "
        "log_density {}\n",
        o.table,
        o.gpu ? "on the GPU: OpenGL forward pass (GL_TIME_ELAPSED)"
              : "on the CPU: direct integrator",
        o.width, o.height, o.frames, fmt::join(o.log_densities, ", "));
    s += fmt::format("{:<14} {:<14} {:>10} {:>10} {:>14}\n", "scene", "model", "min ms", "max ms",
                     "max/smooth min");
    for (const Table1Row& r : rows) {
        double smooth_ms = 0.0;
        for (const Table1Row& q : rows)
            if (q.scene == r.scene && q.model == "smooth") smooth_ms = q.min_ms;
        s += fmt::format("{:<14} {:<14} {:>10.1f} {:>10.1f} {:>14}", r.scene, r.model, r.min_ms,
                         r.max_ms,
                         smooth_ms > 0.0 ? fmt::format("{:.2f}", r.max_ms / smooth_ms) : "-");
        if (o.gpu && !r.frame_ms_per_density.empty())
            s += fmt::format("   frame (render + glFinish) ms: {:.1f}",
                             fmt::join(r.frame_ms_per_density, " "));
        if (o.gpu && !r.first_frame_ms_per_density.empty())
            s += fmt::format("   first frame (compile + link + draw) ms: {:.0f}",
                             fmt::join(r.first_frame_ms_per_density, " "));
        s += "\n";
    }
    return s;
}

}  // namespace glintlab
