#include <functional>
#include <map>

#include <fmt/format.h>

#include "commands.h"
#include "glintlab/counting/validate_counting.h"
#include "glintlab/glints/registry.h"
#include "glintlab/validate/report.h"

namespace glintlab::cmd {
namespace {

struct ValidateArgs {
    std::string suite;
    bool json = false;
    int64_t seed = 1;
};

using SuiteRunner = std::function<ValidationReport(const ValidateArgs&)>;

// The validation suites, by name: every model's suite from its descriptor,
// plus the suites that belong to no model.
const std::map<std::string, SuiteRunner>& suites() {
    static const std::map<std::string, SuiteRunner> table = [] {
        std::map<std::string, SuiteRunner> t;
        t["counting"] = [](const ValidateArgs& a) {
            CountingValidationOptions o;
            o.seed = static_cast<uint64_t>(a.seed);
            return validate_counting(o);
        };
        for (const GlintModelDescriptor& m : glint_models()) {
            if (m.validation.run == nullptr) continue;
            auto run = m.validation.run;
            t[m.validation.name] = [run](const ValidateArgs& a) {
                return run(static_cast<uint64_t>(a.seed));
            };
        }
        return t;
    }();
    return table;
}

}  // namespace

void add_validate_command(CLI::App& app, int* status) {
    auto args = std::make_shared<ValidateArgs>();
    CLI::App* sub = app.add_subcommand(
        "validate", "Run a validation suite; exit status 0 only if every check passes");
    std::vector<std::string> names;
    for (const auto& [name, _] : suites()) names.push_back(name);
    sub->add_option("suite", args->suite, "Suite name")->required()->check(CLI::IsMember(names));
    sub->add_flag("--json", args->json, "Print one JSON object (docs/VALIDATION.md)");
    sub->add_option("--seed", args->seed, "Random seed")
        ->check(CLI::Range(int64_t{0}, int64_t{1} << 40));
    sub->callback([args, status] {
        const ValidationReport report = suites().at(args->suite)(*args);
        if (args->json)
            fmt::print("{}\n", report.to_json().dump(2));
        else
            fmt::print("{}", report.to_text());
        *status = report.passed() ? 0 : 1;
    });
}

}  // namespace glintlab::cmd
