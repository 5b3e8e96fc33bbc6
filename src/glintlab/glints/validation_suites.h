// Every `glintlab validate` suite by name: each model's suite from its
// descriptor plus the suites that belong to no model. One table for the CLI
// and the Python module, so their suite lists cannot drift apart.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>

#include "glintlab/validate/report.h"

namespace glintlab {

using ValidationSuiteRunner = std::function<ValidationReport(uint64_t seed)>;

const std::map<std::string, ValidationSuiteRunner>& validation_suites();

// Runs the named suite; an unknown name throws glintlab::Error listing the known ones.
ValidationReport run_validation_suite(const std::string& name, uint64_t seed);

}  // namespace glintlab
