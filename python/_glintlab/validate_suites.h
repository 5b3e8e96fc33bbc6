// glintlab.validate(suite): the suites of `glintlab validate`, from the
// library's one table (glints/validation_suites.h) that the CLI also uses.
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
