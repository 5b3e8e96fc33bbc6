#include "models_binding.h"

#include <string>

#include "glintlab/glints/registry.h"
#if GLINTLAB_WITH_GL
#include "glintlab/realtime/glint_programs.h"
#endif

namespace py = pybind11;

namespace glintlab::python {

py::list models_table() {
    py::list out;
    for (const GlintModelInfo& m : glint_models()) {
        py::list lights;
        if (m.point_lights) lights.append("point");
        if (m.directional_lights) lights.append("directional");
        if (m.sphere_lights) lights.append("sphere");
        if (m.environment_lights) lights.append("environment");
        py::list backends;
        backends.append("cpu");
#if GLINTLAB_WITH_GL
        if (gl::gpu_supports_model(m.id)) backends.append("gpu");
#endif
        py::dict d;
        d["name"] = std::string(m.name);
        d["description"] = std::string(m.description);
        d["lights"] = lights;
        d["backends"] = backends;
        out.append(d);
    }
    return out;
}

}  // namespace glintlab::python
