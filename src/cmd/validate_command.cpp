#include <fmt/format.h>

#include "commands.h"
#include "glintlab/compare/validate_compare.h"
#include "glintlab/core/error.h"
#include "glintlab/glints/validation_suites.h"
#include "glintlab/validate/report.h"
#include "glintlab/validate/robustness_suite.h"

namespace glintlab::cmd {
namespace {

struct ValidateArgs {
    std::string suite;
    bool json = false;
    int64_t seed = 1;
    std::vector<std::string> models;  // robustness and compare: a subset of the models
    std::vector<std::string> scenes;  // compare only: a subset of scenes/compare/
};

}  // namespace

void add_validate_command(CLI::App& app, int* status) {
    auto args = std::make_shared<ValidateArgs>();
    CLI::App* sub = app.add_subcommand(
        "validate", "Run a validation suite; exit status 0 only if every check passes");
    std::vector<std::string> names;
    for (const auto& [name, _] : validation_suites()) names.push_back(name);
    sub->add_option("suite", args->suite, "Suite name")->required()->check(CLI::IsMember(names));
    sub->add_flag("--json", args->json, "Print one JSON object (docs/VALIDATION.md)");
    sub->add_option("--seed", args->seed, "Random seed")
        ->check(CLI::Range(int64_t{0}, int64_t{1} << 40));
    sub->add_option("--models", args->models,
                    "robustness: only these models, each with its full-suite share of the "
                    "10^7 evaluations (per-model runs add up to the full suite); compare: only "
                    "these models (the ground truth is always rendered); comma- or "
                    "space-separated")
        ->delimiter(',');
    sub->add_option("--scenes", args->scenes,
                    "compare: only these scenes of scenes/compare/, by stem (e.g. sphere_city); "
                    "comma- or space-separated")
        ->delimiter(',');
    sub->callback([args, status] {
        if (!args->models.empty() && args->suite != "robustness" && args->suite != "compare")
            fail("validate {}: --models applies to the robustness and compare suites only",
                 args->suite);
        if (!args->scenes.empty() && args->suite != "compare")
            fail("validate {}: --scenes applies to the compare suite only", args->suite);
        ValidationReport report;
        if (args->suite == "compare" && (!args->models.empty() || !args->scenes.empty())) {
            CompareValidationOptions o;
            o.seed = static_cast<uint64_t>(args->seed);
            o.models = args->models;
            o.scenes = args->scenes;
            report = validate_compare(o);
        } else if (args->models.empty()) {
            report = run_validation_suite(args->suite, static_cast<uint64_t>(args->seed));
        } else {
            RobustnessSuiteOptions o;
            o.seed = static_cast<uint64_t>(args->seed);
            o.models = args->models;
            report = validate_robustness(o);
        }
        if (args->json)
            fmt::print("{}\n", report.to_json().dump(2));
        else
            fmt::print("{}", report.to_text());
        *status = report.passed() ? 0 : 1;
    });
}

}  // namespace glintlab::cmd
