#include "models_binding.h"

#include <string>

#include "glintlab/glints/model_docs.h"
#include "glintlab/glints/registry.h"

namespace py = pybind11;

namespace glintlab::python {

// Every model's descriptor exactly as `glintlab info --json` prints it (name,
// description, citations, lights, back ends, parameter table with ranges,
// validation suite): one generator, so Python and the CLI cannot disagree.
py::list models_table() {
    const py::object loads = py::module_::import("json").attr("loads");
    py::list out;
    for (const GlintModelDescriptor& m : glint_models())
        out.append(loads(glint_model_to_json(m).dump()));
    return out;
}

}  // namespace glintlab::python
