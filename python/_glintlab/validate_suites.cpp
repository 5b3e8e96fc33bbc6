#include "validate_suites.h"

#include "glintlab/compare/compare.h"
#include "glintlab/glints/validation_suites.h"

namespace glintlab::python {

std::vector<std::string> validation_suite_names() {
    std::vector<std::string> names;
    for (const auto& [name, _] : validation_suites()) names.push_back(name);
    return names;
}

nlohmann::json run_validation_suite(const std::string& suite, uint64_t seed) {
    return glintlab::run_validation_suite(suite, seed).to_json();
}

nlohmann::json run_compare(const CompareArgs& a) {
    compare::CompareOptions o;
    o.scene = a.scene;
    o.sets = a.sets;
    o.material = a.material;
    o.models = a.models;
    o.realizations = a.realizations;
    o.truth_realizations = a.truth_realizations;
    o.flicker_paths = a.flicker_paths;
    o.match_facet_extent = a.match_facet_extent;
    o.width = a.width, o.height = a.height;
    o.spp = a.spp;
    o.frames = a.frames;
    o.orbit_deg = a.orbit_deg;
    o.seed = a.seed;
    o.gpu = a.gpu;
    o.threads = a.threads;
    o.progress = a.progress;
    const compare::CompareResult r = compare::run_compare(o);
    if (!a.output.empty()) compare::write_compare_outputs(r, a.output);
    return r.to_json();
}

}  // namespace glintlab::python
