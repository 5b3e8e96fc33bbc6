// Every `glintlab validate` suite by name: each model's suite, named by its
// descriptor and run by its folder's `<model>_validation_suite()`, plus the
// suites that belong to no model. One table for the CLI
// and the Python module, so their suite lists cannot drift apart.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>

#include "glintlab/validate/report.h"

namespace glintlab {

using ValidationSuiteRunner = std::function<ValidationReport(uint64_t seed)>;

// A suite run with its default options and the given seed: what each model's
// `<model>_validation_suite()` returns (model_list.h), beside its suite.
template <typename Options, ValidationReport (*Run)(const Options&)>
ValidationSuiteRunner seeded_validation_suite() {
    return [](uint64_t seed) {
        Options o;
        o.seed = seed;
        return Run(o);
    };
}

const std::map<std::string, ValidationSuiteRunner>& validation_suites();

// Runs the named suite; an unknown name throws glintlab::Error listing the known ones.
ValidationReport run_validation_suite(const std::string& name, uint64_t seed);

}  // namespace glintlab
