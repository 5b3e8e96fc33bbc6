#include "glintlab/glints/validation_suites.h"

#include <string>

#include "glintlab/compare/validate_compare.h"
#include "glintlab/core/error.h"
#include "glintlab/counting/validate_counting.h"
#include "glintlab/glints/model_list.h"
#include "glintlab/glints/registry.h"
#include "glintlab/validate/robustness_suite.h"

namespace glintlab {

#define GLINTLAB_DECLARE_SUITE(model, Model) ValidationSuiteRunner model##_validation_suite();
GLINTLAB_GLINT_MODELS(GLINTLAB_DECLARE_SUITE)
#undef GLINTLAB_DECLARE_SUITE

const std::map<std::string, ValidationSuiteRunner>& validation_suites() {
    static const std::map<std::string, ValidationSuiteRunner> table = [] {
        std::map<std::string, ValidationSuiteRunner> t;
        t["counting"] = seeded_validation_suite<CountingValidationOptions, validate_counting>();
        t["robustness"] = [](uint64_t seed) { return validate_robustness(seed); };
        t["compare"] = seeded_validation_suite<CompareValidationOptions, validate_compare>();
        // Each model's runner, in the list's order (= glint_models()), under
        // the name its descriptor gives (GlintValidationSuite): the runtime
        // library holds the names, the research library the code. A runner
        // without a name, or a name without a runner, is a programming error:
        // `glintlab validate` would list a suite it cannot run.
#define GLINTLAB_SUITE(model, Model) model##_validation_suite(),
        const ValidationSuiteRunner runners[] = {GLINTLAB_GLINT_MODELS(GLINTLAB_SUITE)};
#undef GLINTLAB_SUITE
        const auto models = glint_models();
        if (models.size() != std::size(runners))
            fail("validation_suites: {} models but {} runners", models.size(), std::size(runners));
        for (size_t i = 0; i < models.size(); ++i) {
            const GlintModelDescriptor& m = models[i];
            if (m.validation.name.empty() != !runners[i])
                fail("validation_suites: model {} {} but its folder {}", m.name,
                     m.validation.name.empty() ? "names no suite" : "names a suite",
                     runners[i] ? "has a runner" : "has no runner");
            if (!m.validation.name.empty()) t[m.validation.name] = runners[i];
        }
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
