#include "validate_suites.h"

#include <functional>
#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "glintlab/core/error.h"
#include "glintlab/counting/validate_counting.h"
#include "glintlab/glints/chermain2020/validate_chermain2020.h"
#include "glintlab/glints/deliot2023/validate_deliot2023.h"
#include "glintlab/glints/explicit/validate_explicit.h"
#include "glintlab/glints/jakob2014/validate_jakob2014.h"
#include "glintlab/glints/kneiphof2025/validate_kneiphof2025.h"
#include "glintlab/glints/wang2020/validate_wang2020.h"
#include "glintlab/glints/zirr2016/validate_zirr2016.h"
#include "glintlab/validate/report.h"

namespace glintlab::python {
namespace {

template <typename Options, typename Fn>
std::function<ValidationReport(uint64_t)> suite(Fn fn) {
    return [fn](uint64_t seed) {
        Options o;
        o.seed = seed;
        return fn(o);
    };
}

const std::map<std::string, std::function<ValidationReport(uint64_t)>>& table() {
    static const std::map<std::string, std::function<ValidationReport(uint64_t)>> t = {
        {"chermain2020", suite<Chermain2020ValidationOptions>(validate_chermain2020)},
        {"counting", suite<CountingValidationOptions>(validate_counting)},
        {"deliot2023", suite<Deliot2023ValidationOptions>(validate_deliot2023)},
        {"explicit", suite<ExplicitValidationOptions>(validate_explicit)},
        {"jakob2014", suite<Jakob2014ValidationOptions>(validate_jakob2014)},
        {"kneiphof2025", suite<Kneiphof2025ValidationOptions>(validate_kneiphof2025)},
        {"wang2020", suite<Wang2020ValidationOptions>(validate_wang2020)},
        {"zirr2016", suite<Zirr2016ValidationOptions>(validate_zirr2016)},
    };
    return t;
}

}  // namespace

std::vector<std::string> validation_suite_names() {
    std::vector<std::string> names;
    for (const auto& [name, _] : table()) names.push_back(name);
    return names;
}

nlohmann::json run_validation_suite(const std::string& suite_name, uint64_t seed) {
    const auto it = table().find(suite_name);
    if (it == table().end())
        fail("validate: unknown suite \"{}\" (known: {})", suite_name,
             fmt::join(validation_suite_names(), ", "));
    return it->second(seed).to_json();
}

}  // namespace glintlab::python
