#include <functional>
#include <map>

#include <fmt/format.h>

#include "commands.h"
#include "glintlab/counting/validate_counting.h"
#include "glintlab/glints/chermain2020/validate_chermain2020.h"
#include "glintlab/glints/deliot2023/validate_deliot2023.h"
#include "glintlab/glints/explicit/validate_explicit.h"
#include "glintlab/glints/kneiphof2025/validate_kneiphof2025.h"
#include "glintlab/glints/jakob2014/validate_jakob2014.h"
#include "glintlab/glints/wang2020/validate_wang2020.h"
#include "glintlab/glints/zirr2016/validate_zirr2016.h"
#include "glintlab/validate/report.h"
#include "glintlab/validate/robustness_suite.h"

namespace glintlab::cmd {
namespace {

struct ValidateArgs {
    std::string suite;
    bool json = false;
    int64_t seed = 1;
};

using SuiteRunner = std::function<ValidationReport(const ValidateArgs&)>;

// The validation suites, by name. Each model issue adds its own.
const std::map<std::string, SuiteRunner>& suites() {
    static const std::map<std::string, SuiteRunner> table = {
        {"chermain2020",
         [](const ValidateArgs& a) {
             Chermain2020ValidationOptions o;
             o.seed = static_cast<uint64_t>(a.seed);
             return validate_chermain2020(o);
         }},
        {"counting",
         [](const ValidateArgs& a) {
             CountingValidationOptions o;
             o.seed = static_cast<uint64_t>(a.seed);
             return validate_counting(o);
         }},
        {"deliot2023",
         [](const ValidateArgs& a) {
             Deliot2023ValidationOptions o;
             o.seed = static_cast<uint64_t>(a.seed);
             return validate_deliot2023(o);
         }},
        {"explicit",
         [](const ValidateArgs& a) {
             ExplicitValidationOptions o;
             o.seed = static_cast<uint64_t>(a.seed);
             return validate_explicit(o);
         }},
        {"jakob2014",
         [](const ValidateArgs& a) {
             Jakob2014ValidationOptions o;
             o.seed = static_cast<uint64_t>(a.seed);
             return validate_jakob2014(o);
         }},
        {"kneiphof2025",
         [](const ValidateArgs& a) {
             Kneiphof2025ValidationOptions o;
             o.seed = static_cast<uint64_t>(a.seed);
             return validate_kneiphof2025(o);
         }},
        {"robustness",
         [](const ValidateArgs& a) { return validate_robustness(static_cast<uint64_t>(a.seed)); }},
        {"wang2020",
         [](const ValidateArgs& a) {
             Wang2020ValidationOptions o;
             o.seed = static_cast<uint64_t>(a.seed);
             return validate_wang2020(o);
         }},
        {"zirr2016",
         [](const ValidateArgs& a) {
             Zirr2016ValidationOptions o;
             o.seed = static_cast<uint64_t>(a.seed);
             return validate_zirr2016(o);
         }},
    };
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
    sub->add_option("--seed", args->seed, "Random seed")->check(CLI::Range(int64_t{0}, int64_t{1} << 40));
    sub->callback([args, status] {
        const ValidationReport report = suites().at(args->suite)(*args);
        if (args->json) fmt::print("{}\n", report.to_json().dump(2));
        else fmt::print("{}", report.to_text());
        *status = report.passed() ? 0 : 1;
    });
}

}  // namespace glintlab::cmd
