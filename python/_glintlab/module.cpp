// The C++ half of the `glintlab` Python package (python/glintlab/ is the
// other half): scene parsing, CPU/GPU rendering to NumPy arrays, the glint
// model table, direct BRDF / footprint-NDF evaluation, validation suites and
// image I/O, all through the library (not the CLI). docs/PYTHON.md.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <memory>
#include <optional>
#include <string>

#include "glintlab/core/error.h"
#include "glintlab/core/image.h"
#include "glintlab/core/memory_limit.h"
#include "glintlab/export/shader_export.h"
#include "glintlab/glints/glint_bxdf.h"
#include "glintlab/glints/registry.h"
#include "glintlab/loader/scene_edits.h"
#include "glintlab/loader/scene_loader.h"
#include "glintlab/render/render_memory.h"
#include "glintlab/render/renderer.h"
#if GLINTLAB_WITH_GL
#include "glintlab/realtime/gpu_renderer.h"
#endif
#include "models_binding.h"
#include "validate_suites.h"

namespace py = pybind11;
using namespace glintlab;

namespace {

static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "Image pixels must be packed RGB floats");

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

py::array_t<float> to_numpy(const Image& image) {
    py::array_t<float> out({static_cast<py::ssize_t>(image.height),
                            static_cast<py::ssize_t>(image.width), py::ssize_t{3}});
    if (!image.pixels.empty())
        std::memcpy(out.mutable_data(), image.pixels.data(),
                    image.pixels.size() * sizeof(glm::vec3));
    return out;
}

Image from_numpy(const FloatArray& a, const std::string& what) {
    if (a.ndim() != 3 || a.shape(2) != 3)
        throw py::value_error(what + ": expected a float array of shape (H, W, 3)");
    if (a.shape(0) < 1 || a.shape(1) < 1) throw py::value_error(what + ": empty image");
    Image image(static_cast<int>(a.shape(1)), static_cast<int>(a.shape(0)));
    std::memcpy(image.pixels.data(), a.data(), image.pixels.size() * sizeof(glm::vec3));
    return image;
}

// (N, 3) or (N, 2) float arrays of equal N.
FloatArray rows(const FloatArray& a, py::ssize_t cols, const char* name) {
    if (a.ndim() != 2 || a.shape(1) != cols)
        throw py::value_error(std::string(name) + ": expected an array of shape (N, " +
                              std::to_string(cols) + ")");
    return a;
}

// glintlab.SceneError, set from parse_scene's glintlab::Error.
py::object& scene_error_type() {
    static py::object type;
    return type;
}

// A NumPy texture (float32, (H, W), (H, W, 1), (H, W, 3) or (H, W, 4),
// linear values; the Python side has checked the shape and finiteness and
// names the JSON path in its errors) as the loader's RGBA texels.
std::shared_ptr<const TextureImage> texture_of_array(const FloatArray& a) {
    if (a.ndim() < 2 || a.ndim() > 3 || a.shape(0) < 1 || a.shape(1) < 1 ||
        (a.ndim() == 3 && a.shape(2) != 1 && a.shape(2) != 3 && a.shape(2) != 4))
        throw py::value_error(
            "texture array: expected shape (H, W), (H, W, 1), (H, W, 3) or (H, W, 4)");
    const py::ssize_t h = a.shape(0), w = a.shape(1);
    const py::ssize_t c = a.ndim() == 3 ? a.shape(2) : 1;
    TextureImage t;
    t.width = static_cast<int>(w), t.height = static_cast<int>(h);
    t.texels.resize(static_cast<size_t>(w * h));
    const float* p = a.data();
    for (size_t i = 0; i < t.texels.size(); ++i) {
        const float* v = p + i * static_cast<size_t>(c);
        t.texels[i] = c == 1   ? glm::vec4(v[0], v[0], v[0], 1.0f)
                      : c == 3 ? glm::vec4(v[0], v[1], v[2], 1.0f)
                               : glm::vec4(v[0], v[1], v[2], v[3]);
    }
    return std::make_shared<const TextureImage>(std::move(t));
}

Scene parse(const std::string& text, const std::string& file,
            const std::vector<FloatArray>& arrays) {
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        PyErr_SetString(scene_error_type().ptr(), (file + ": invalid JSON: " + e.what()).c_str());
        throw py::error_already_set();
    }
    try {
        TextureFileCache textures;
        for (size_t i = 0; i < arrays.size(); ++i)
            textures[std::string(kArrayPrefix) + std::to_string(i) + ">"] =
                texture_of_array(arrays[i]);
        return parse_scene(document, file, std::move(textures));
    } catch (const Error& e) {
        PyErr_SetString(scene_error_type().ptr(), e.what());
        throw py::error_already_set();
    }
}

py::array_t<float> render(const Scene& parsed, bool gpu, std::optional<int> spp,
                          std::optional<int64_t> seed, std::optional<int> width,
                          std::optional<int> height, int threads, py::object progress) {
    Scene scene = parsed;
    if (spp) {
        if (*spp < 1 || *spp > (1 << 20)) throw py::value_error("spp: must be in [1, 1048576]");
        scene.render.spp = *spp;
    }
    if (seed) {
        if (*seed < 0 || *seed > 4294967295LL)
            throw py::value_error("seed: must be in [0, 4294967295]");
        scene.render.seed = static_cast<uint64_t>(*seed);
    }
    if (width || height) {
        if (!width || !height || *width < 1 || *height < 1 || *width > 16384 || *height > 16384)
            throw py::value_error("res: expected (W, H) with W and H in [1, 16384]");
        scene.camera.width = *width, scene.camera.height = *height;
    }
    if (threads < 0 || threads > 1024) throw py::value_error("threads: must be in [0, 1024]");
    // The CLI's memory check (its --memory-limit; by default the machine's
    // available memory): a 16384² render must fail here, not grow to gigabytes.
    require_memory(estimate_render_memory(scene, gpu), "render of " + scene.file.string() + " at " +
                                                           std::to_string(scene.camera.width) +
                                                           "x" +
                                                           std::to_string(scene.camera.height));
    Image image;
    if (gpu) {
#if GLINTLAB_WITH_GL
        uint64_t cut = 0;
        {
            py::gil_scoped_release release;
            image = render_scene_gpu(scene, &cut);
        }
        // A RuntimeWarning, which notebooks show (stderr they may not).
        if (cut > 0 &&
            PyErr_WarnEx(PyExc_RuntimeWarning, cut_fragments_warning(cut).c_str(), 1) != 0)
            throw py::error_already_set();
#else
        throw py::value_error(
            "gpu=True: this glintlab was built without OpenGL (GLINTLAB_WITH_GL=OFF)");
#endif
    } else {
        RenderOptions options;
        options.threads = threads;
        options.quiet = true;
        // The first exception the callback raises; later calls are skipped
        // and it is re-raised once the render is over. Every access to it
        // holds the GIL.
        std::unique_ptr<py::error_already_set> callback_error;
        if (!progress.is_none()) {
            options.progress = [&progress, &callback_error](double fraction) {
                py::gil_scoped_acquire acquire;
                if (callback_error) return;
                try {
                    progress(fraction);
                } catch (py::error_already_set& e) {
                    callback_error = std::make_unique<py::error_already_set>(std::move(e));
                }
            };
        }
        {
            py::gil_scoped_release release;
            image = render_scene(scene, options);
        }
        if (callback_error) throw std::move(*callback_error);
    }
    return to_numpy(image);
}

// f(wo, wi) (what = false) or D_P(h) per channel (what = true) of material
// `index` of `scene`, a glint material; directions in its shading frame.
py::array_t<float> eval_glint(const Scene& scene, int index, const FloatArray& wo_in,
                              const FloatArray& wi_in, const std::optional<FloatArray>& uv_in,
                              const std::optional<FloatArray>& dx_in,
                              const std::optional<FloatArray>& dy_in, bool ndf) {
    if (index < 0 || index >= static_cast<int>(scene.materials.size()))
        throw py::index_error("material index out of range");
    const MaterialDesc& material = scene.materials[static_cast<size_t>(index)];
    if (material.type != MaterialDesc::Type::Glint)
        throw py::value_error("material \"" + material.name + "\" is not a glint material");
    const FloatArray wo = rows(wo_in, 3, "wo"), wi = rows(wi_in, 3, "wi");
    const py::ssize_t n = wo.shape(0);
    if (wi.shape(0) != n) throw py::value_error("wi: must have as many rows as wo");
    const bool has_fp = uv_in.has_value();
    if (has_fp != dx_in.has_value() || has_fp != dy_in.has_value())
        throw py::value_error("footprint: give all of uv, duvdx and duvdy, or none");
    FloatArray uv, dx, dy;
    if (has_fp) {
        uv = rows(*uv_in, 2, "footprint uv"), dx = rows(*dx_in, 2, "footprint duvdx"),
        dy = rows(*dy_in, 2, "footprint duvdy");
        if (uv.shape(0) != n || dx.shape(0) != n || dy.shape(0) != n)
            throw py::value_error("footprint: uv, duvdx and duvdy must have N rows like wo");
    }
    // Without a footprint D_P is the smooth limit D, as in GlintBxdf::f
    // (secondary bounces): the smooth model's evaluation of the same NDF.
    GlintDesc limit = material.glint;
    limit.model_id = GlintModelId::Smooth;
    const GlintDesc* desc = (ndf && !has_fp) ? &limit : &material.glint;
    py::array_t<float> out({n, py::ssize_t{3}});
    float* o = out.mutable_data();
    const float* pwo = wo.data();
    const float* pwi = wi.data();
    const float* puv = has_fp ? uv.data() : nullptr;
    const float* pdx = has_fp ? dx.data() : nullptr;
    const float* pdy = has_fp ? dy.data() : nullptr;
    {
        py::gil_scoped_release release;
        for (py::ssize_t i = 0; i < n; ++i) {
            GlintBxdf bxdf;
            bxdf.desc = desc;
            bxdf.has_footprint = has_fp;
            if (has_fp) {
                bxdf.footprint.uv = {puv[2 * i], puv[2 * i + 1]};
                bxdf.footprint.duvdx = {pdx[2 * i], pdx[2 * i + 1]};
                bxdf.footprint.duvdy = {pdy[2 * i], pdy[2 * i + 1]};
            }
            const glm::vec3 a =
                glm::normalize(glm::vec3(pwo[3 * i], pwo[3 * i + 1], pwo[3 * i + 2]));
            const glm::vec3 b =
                glm::normalize(glm::vec3(pwi[3 * i], pwi[3 * i + 1], pwi[3 * i + 2]));
            glm::vec3 v(0.0f);
            if (ndf) {
                const glm::vec3 h = a + b;
                if (glm::dot(h, h) > 0.0f) v = bxdf.footprint_ndf_rgb(a, b, glm::normalize(h));
            } else {
                v = bxdf.f(a, b);
            }
            o[3 * i] = v.x, o[3 * i + 1] = v.y, o[3 * i + 2] = v.z;
        }
    }
    return out;
}

}  // namespace

PYBIND11_MODULE(_glintlab, m) {
    m.doc() = "glintlab's C++ library (use the `glintlab` package, docs/PYTHON.md)";
    // glintlab::Error from any call (image I/O, validation, rendering).
    const py::exception<Error>& error =
        py::register_exception<Error>(m, "Error", PyExc_RuntimeError);
    scene_error_type() = py::reinterpret_borrow<py::object>(PyErr_NewExceptionWithDoc(
        "glintlab._glintlab.SceneError",
        "A scene document the strict loader rejects; the message names the file and JSON path.",
        py::make_tuple(error, py::handle(PyExc_ValueError)).ptr(), nullptr));
    Py_DECREF(scene_error_type().ptr());  // PyErr_NewException returned a new reference
    m.attr("SceneError") = scene_error_type();

    py::class_<Scene>(m, "Scene", "A parsed, validated scene (glintlab::Scene)")
        .def_property_readonly("file", [](const Scene& s) { return s.file.string(); })
        .def_property_readonly("width", [](const Scene& s) { return s.camera.width; })
        .def_property_readonly("height", [](const Scene& s) { return s.camera.height; })
        .def_property_readonly("spp", [](const Scene& s) { return s.render.spp; })
        .def_property_readonly("seed", [](const Scene& s) { return s.render.seed; })
        .def_property_readonly("materials",
                               [](const Scene& s) {
                                   std::vector<std::string> names;
                                   for (const MaterialDesc& mat : s.materials)
                                       names.push_back(mat.name);
                                   return names;
                               })
        .def("__repr__", [](const Scene& s) {
            return "<glintlab.Scene " + s.file.string() + " " + std::to_string(s.camera.width) +
                   "x" + std::to_string(s.camera.height) + ">";
        });

    m.def(
        "set_glint_model",
        [](const std::string& text, const std::string& model) {
            nlohmann::json document = nlohmann::json::parse(text);
            set_glint_model(document, model);
            return document.dump();
        },
        py::arg("text"), py::arg("model"),
        "scene_edits.h set_glint_model on a JSON text: the model set and fitted");
    m.def("parse_scene", &parse, py::arg("text"), py::arg("file"),
          py::arg("arrays") = std::vector<FloatArray>{},
          "Parses a JSON text strictly; raises SceneError naming the file and JSON path");
    m.def("render", &render, py::arg("scene"), py::arg("gpu") = false, py::arg("spp") = py::none(),
          py::arg("seed") = py::none(), py::arg("width") = py::none(),
          py::arg("height") = py::none(), py::arg("threads") = 0, py::arg("progress") = py::none(),
          "Renders to a float32 (H, W, 3) array, releasing the GIL");
    m.def("eval_glint", &eval_glint, py::arg("scene"), py::arg("material"), py::arg("wo"),
          py::arg("wi"), py::arg("uv") = py::none(), py::arg("duvdx") = py::none(),
          py::arg("duvdy") = py::none(), py::arg("ndf") = false);
    m.def("models", &glintlab::python::models_table,
          "Every glint model: name, description, "
          "lights, backends");
    m.def("validation_suites", &glintlab::python::validation_suite_names);
    m.def(
        "validate_json",
        [](const std::string& suite, uint64_t seed) {
            nlohmann::json j;
            {
                py::gil_scoped_release release;
                j = glintlab::python::run_validation_suite(suite, seed);
            }
            return j.dump();
        },
        py::arg("suite"), py::arg("seed") = 1);
    m.def(
        "compare_json",
        [](const std::string& scene, const std::vector<std::string>& sets,
           const std::string& material, const std::vector<std::string>& models, int realizations,
           int width, int height, int spp, int frames, double orbit_deg, uint64_t seed, bool gpu,
           int threads, const std::string& output, int truth_realizations, bool match_facet_extent,
           int flicker_paths, py::object progress) {
            glintlab::python::CompareArgs a{scene,     sets,   material, models, realizations,
                                            width,     height, spp,      frames, threads,
                                            orbit_deg, seed,   gpu,      output};
            a.truth_realizations = truth_realizations;
            a.match_facet_extent = match_facet_extent;
            a.flicker_paths = flicker_paths;
            // As render's callback: the first exception it raises is kept,
            // later calls are skipped, and it is re-raised after the run.
            std::unique_ptr<py::error_already_set> callback_error;
            if (!progress.is_none()) {
                a.progress = [&progress, &callback_error](int done, int total) {
                    py::gil_scoped_acquire acquire;
                    if (callback_error) return;
                    try {
                        progress(done, total);
                    } catch (py::error_already_set& e) {
                        callback_error = std::make_unique<py::error_already_set>(std::move(e));
                    }
                };
            }
            nlohmann::json j;
            {
                py::gil_scoped_release release;
                j = glintlab::python::run_compare(a);
            }
            if (callback_error) throw std::move(*callback_error);
            return j.dump();
        },
        py::arg("scene"), py::arg("sets"), py::arg("material"), py::arg("models"),
        py::arg("realizations"), py::arg("width"), py::arg("height"), py::arg("spp"),
        py::arg("frames"), py::arg("orbit_deg"), py::arg("seed"), py::arg("gpu"),
        py::arg("threads"), py::arg("output"), py::arg("truth_realizations") = 0,
        py::arg("match_facet_extent") = true, py::arg("flicker_paths") = 4,
        py::arg("progress") = py::none(),
        "glintlab compare: the metrics.json document (docs/VALIDATION.md \"compare\")");
    m.def(
        "export_model",
        [](const std::string& model, const std::string& output, const std::string& lang,
           const std::string& scene, const std::string& material, const std::string& env,
           bool resources) {
            glintlab::ExportOptions o;
            o.model = model;
            o.language = glintlab::parse_export_language(lang);
            o.out_dir = output;
            o.scene = scene;
            o.material = material;
            o.environment = env;
            o.resources = resources;
            std::vector<std::string> files;
            {
                py::gil_scoped_release release;
                for (const glintlab::ExportedFile& f : glintlab::export_model(o))
                    files.push_back(f.name);
            }
            return files;
        },
        py::arg("model"), py::arg("output"), py::arg("lang"), py::arg("scene"), py::arg("material"),
        py::arg("env"), py::arg("resources"),
        "glintlab export: writes one model's shader, resources and manifest; returns the file "
        "names (docs/INTEGRATION.md)");
    m.def(
        "read_image", [](const std::string& path) { return to_numpy(read_image(path)); },
        py::arg("path"), "Reads .exr/.hdr/.png/.jpg to a linear float32 (H, W, 3) array");
    m.def(
        "write_image",
        [](const std::string& path, const FloatArray& array, float exposure) {
            write_image(from_numpy(array, "write_image"), path, exposure);
        },
        py::arg("path"), py::arg("array"), py::arg("exposure") = 0.0f,
        "Writes .exr/.hdr/.png (sRGB, exposure in stops) from a linear (H, W, 3) array");
#if GLINTLAB_WITH_GL
    m.attr("with_gl") = true;
#else
    m.attr("with_gl") = false;
#endif
    m.attr("__version__") = GLINTLAB_VERSION;
}
