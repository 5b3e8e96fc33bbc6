#include "glintlab/glints/validation_suites.h"

#include <string>

#include "glintlab/core/error.h"
#include "glintlab/counting/validate_counting.h"
#include "glintlab/glints/registry.h"
#include "glintlab/validate/robustness_suite.h"

namespace glintlab {

const std::map<std::string, ValidationSuiteRunner>& validation_suites() {
    static const std::map<std::string, ValidationSuiteRunner> table = [] {
        std::map<std::string, ValidationSuiteRunner> t;
        t["counting"] = [](uint64_t seed) {
            CountingValidationOptions o;
            o.seed = seed;
            return validate_counting(o);
        };
        t["robustness"] = [](uint64_t seed) { return validate_robustness(seed); };
        for (const GlintModelDescriptor& m : glint_models())
            if (m.validation.run != nullptr) t[m.validation.name] = m.validation.run;
        return t;
    }();
    return table;
}

ValidationReport run_validation_suite(const std::string& name, uint64_t seed) {
    const auto& suites = validation_suites();
    const auto it = suites.find(name);
    if (it == suites.end()) {
        std::string known;
        for (const auto& [n, _] : suites) known += (known.empty() ? "" : ", ") + n;
        fail("validate: unknown suite \"{}\" (known: {})", name, known);
    }
    return it->second(seed);
}

}  // namespace glintlab
