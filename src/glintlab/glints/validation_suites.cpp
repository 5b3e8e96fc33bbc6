#include "glintlab/glints/validation_suites.h"

#include <string>

#include "glintlab/compare/validate_compare.h"
#include "glintlab/core/error.h"
#include "glintlab/counting/validate_counting.h"
#include "glintlab/glints/chermain2020/validate_chermain2020.h"
#include "glintlab/glints/deliot2023/validate_deliot2023.h"
#include "glintlab/glints/explicit/validate_explicit.h"
#include "glintlab/glints/jakob2014/validate_jakob2014.h"
#include "glintlab/glints/kneiphof2025/validate_kneiphof2025.h"
#include "glintlab/glints/registry.h"
#include "glintlab/glints/wang2020/validate_wang2020.h"
#include "glintlab/glints/zirr2016/validate_zirr2016.h"
#include "glintlab/validate/robustness_suite.h"

namespace glintlab {
namespace {

// A suite whose options are its defaults with the given seed.
template <typename Options, ValidationReport (*Run)(const Options&)>
ValidationSuiteRunner seeded() {
    return [](uint64_t seed) {
        Options o;
        o.seed = seed;
        return Run(o);
    };
}

}  // namespace

const std::map<std::string, ValidationSuiteRunner>& validation_suites() {
    static const std::map<std::string, ValidationSuiteRunner> table = [] {
        // Keyed by the names the model descriptors give (GlintValidationSuite):
        // the runtime library holds the names, this research table the code.
        std::map<std::string, ValidationSuiteRunner> t = {
            {"counting", seeded<CountingValidationOptions, validate_counting>()},
            {"chermain2020", seeded<Chermain2020ValidationOptions, validate_chermain2020>()},
            {"deliot2023", seeded<Deliot2023ValidationOptions, validate_deliot2023>()},
            {"explicit", seeded<ExplicitValidationOptions, validate_explicit>()},
            {"jakob2014", seeded<Jakob2014ValidationOptions, validate_jakob2014>()},
            {"kneiphof2025", seeded<Kneiphof2025ValidationOptions, validate_kneiphof2025>()},
            {"wang2020", seeded<Wang2020ValidationOptions, validate_wang2020>()},
            {"zirr2016", seeded<Zirr2016ValidationOptions, validate_zirr2016>()},
        };
        t["robustness"] = [](uint64_t seed) { return validate_robustness(seed); };
        t["compare"] = seeded<CompareValidationOptions, validate_compare>();
        // A descriptor naming a suite this table lacks is a programming
        // error: `glintlab validate` would list a suite it cannot run.
        for (const GlintModelDescriptor& m : glint_models())
            if (!m.validation.name.empty() && t.count(m.validation.name) == 0)
                fail("validation_suites: model {} names suite \"{}\", which has no runner", m.name,
                     m.validation.name);
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
