// The result of one `glintlab validate <suite>` run. JSON contract shared by
// every suite (docs/VALIDATION.md):
//   {"suite": NAME, "checks": [{"name", "value", "limit", "pass"}...], ...details}
// and the process exits 0 only if every check passes.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace glintlab {

struct ValidationCheck {
    std::string name;
    double value = 0.0;
    double limit = 0.0;
    std::string relation;  // how value compares with limit to pass: "<=", "<", ">=", ">", "=="
    bool pass = false;
};

struct ValidationReport {
    std::string suite;
    std::vector<ValidationCheck> checks;
    nlohmann::json details = nlohmann::json::object();  // merged into the top-level object
    std::string text;  // human-readable tables printed before the checks

    // Adds a check; `pass` is computed from value, relation and limit.
    void check(std::string name, double value, std::string relation, double limit);
    bool passed() const;
    nlohmann::json to_json() const;
    std::string to_text() const;  // `text` followed by a table of the checks
};

}  // namespace glintlab
