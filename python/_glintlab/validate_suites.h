// glintlab.validate(suite): the validation suites of `glintlab validate`,
// called through the same library functions (src/cmd/validate_command.cpp
// holds the CLI's table; python/tests/test_module.py checks both list the
// same suite names).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace glintlab::python {

std::vector<std::string> validation_suite_names();
// The report's JSON (what `glintlab validate SUITE --json` prints); throws
// glintlab::Error for an unknown suite, listing the known ones.
nlohmann::json run_validation_suite(const std::string& suite, uint64_t seed);

}  // namespace glintlab::python
