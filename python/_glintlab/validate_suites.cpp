#include "validate_suites.h"

#include "glintlab/glints/validation_suites.h"

namespace glintlab::python {

std::vector<std::string> validation_suite_names() {
    std::vector<std::string> names;
    for (const auto& [name, _] : validation_suites()) names.push_back(name);
    return names;
}

nlohmann::json run_validation_suite(const std::string& suite, uint64_t seed) {
    return glintlab::run_validation_suite(suite, seed).to_json();
}

}  // namespace glintlab::python
