#include "glintlab/validate/report.h"

#include <cmath>

#include <fmt/format.h>

#include "glintlab/core/error.h"

namespace glintlab {

void ValidationReport::check(std::string name, double value, std::string relation, double limit) {
    bool pass = false;
    if (relation == "<=")
        pass = value <= limit;
    else if (relation == "<")
        pass = value < limit;
    else if (relation == ">=")
        pass = value >= limit;
    else if (relation == ">")
        pass = value > limit;
    else if (relation == "==")
        pass = value == limit;
    else
        fail("validation check '{}': unknown relation '{}'", name, relation);
    // A NaN value never passes (every comparison above is false for NaN).
    checks.push_back({std::move(name), value, limit, std::move(relation), pass});
}

bool ValidationReport::passed() const {
    for (const ValidationCheck& c : checks)
        if (!c.pass) return false;
    return !checks.empty();
}

nlohmann::json ValidationReport::to_json() const {
    nlohmann::json j = details.is_object() ? details : nlohmann::json::object();
    j["suite"] = suite;
    nlohmann::json arr = nlohmann::json::array();
    for (const ValidationCheck& c : checks) {
        // JSON has no NaN/Inf: such values are written as null (and fail).
        const auto num = [](double v) {
            return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
        };
        arr.push_back({{"name", c.name},
                       {"value", num(c.value)},
                       {"limit", num(c.limit)},
                       {"relation", c.relation},
                       {"pass", c.pass}});
    }
    j["checks"] = std::move(arr);
    j["pass"] = passed();
    return j;
}

std::string ValidationReport::to_text() const {
    std::string out = text;
    if (!out.empty() && out.back() != '\n') out += '\n';
    out += fmt::format("\n{} checks:\n", suite);
    for (const ValidationCheck& c : checks) {
        out += fmt::format("  [{}] {:<34} {:>12.6g} {:>2} {:<12.6g}\n", c.pass ? "PASS" : "FAIL",
                           c.name, c.value, c.relation, c.limit);
    }
    out += fmt::format("{}: {}\n", suite, passed() ? "all checks passed" : "FAILED");
    return out;
}

}  // namespace glintlab
