// glintlab.models(): the one place the Python module reads the glint model
// table, so that it can follow the registry's form without touching the rest
// of the binding.
#pragma once

#include <pybind11/pybind11.h>

namespace glintlab::python {

// A list of dicts {name, description, lights: [...], backends: [...]}.
pybind11::list models_table();

}  // namespace glintlab::python
