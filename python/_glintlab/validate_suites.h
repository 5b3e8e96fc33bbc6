// glintlab.validate(suite): the suites of `glintlab validate`, from the
// library's one table (glints/validation_suites.h) that the CLI also uses.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace glintlab::python {

std::vector<std::string> validation_suite_names();
// The report's JSON (what `glintlab validate SUITE --json` prints); throws
// glintlab::Error for an unknown suite, listing the known ones.
nlohmann::json run_validation_suite(const std::string& suite, uint64_t seed);

// glintlab.compare(...): compare::run_compare (compare/compare.h) with its
// metrics.json document as the result; writes the files of `glintlab compare
// -o` when `output` is not empty.
struct CompareArgs {
    std::string scene;
    std::vector<std::string> sets;
    std::string material;
    std::vector<std::string> models;
    int realizations = 4, width = 0, height = 0, spp = 0, frames = 8, threads = 0;
    double orbit_deg = 4.0;
    uint64_t seed = 1;
    bool gpu = false;
    std::string output;
    int truth_realizations = 0;                        // 0: realizations
    int flicker_paths = 4;                             // camera paths of the flicker measure
    bool match_facet_extent = true;                    // false: the models' default facet extents
    std::function<void(int, int)> progress = nullptr;  // (done, total) renders, as CompareOptions
};
nlohmann::json run_compare(const CompareArgs& args);

}  // namespace glintlab::python
