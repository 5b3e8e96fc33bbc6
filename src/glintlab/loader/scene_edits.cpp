#include "glintlab/loader/scene_edits.h"

#include <charconv>
#include <fstream>

#include <fmt/format.h>

#include "glintlab/core/error.h"
#include "glintlab/core/json_reader.h"
#include "glintlab/core/regular_file.h"
#include "glintlab/glints/registry.h"
#include "glintlab/loader/scene_loader.h"

namespace glintlab {

namespace {

// A material switched to another model gets what the model requires, as the
// viewer's switch does (registry.h switch_glint_model): the fields the
// model's fit_material may change (NDF, roughness, log density) are read as
// the loader reads them, fitted, and written back where they changed, each
// change reported. Fields of the wrong type are left to the loader's error.
void fit_switched_material(nlohmann::json& m, const GlintModelDescriptor& model, size_t index) {
    // The reader's rule (glint_reader.cpp): models that shade their lights
    // themselves have no diffuse base.
    if (model.shades_light != nullptr && m.contains("base_albedo")) {
        fmt::print(stderr,
                   "note: switching to {}: /materials/{}/base_albedo removed ({} has no diffuse "
                   "base)\n",
                   model.name, index, model.name);
        m.erase("base_albedo");
    }
    if (model.fit_material == nullptr) return;
    GlintDesc d;
    d.model_id = model.id;
    d.params = model.default_params();
    const nlohmann::json* ndf = m.contains("ndf") ? &m["ndf"] : nullptr;
    const nlohmann::json* roughness = m.contains("roughness") ? &m["roughness"] : nullptr;
    const nlohmann::json* log_density = m.contains("log_density") ? &m["log_density"] : nullptr;
    if (ndf && !ndf->is_string()) return;
    if (log_density && !log_density->is_number()) return;
    if (ndf) d.ndf = ndf->get<std::string>() == "ggx" ? NdfType::GGX : NdfType::Beckmann;
    if (roughness && roughness->is_number()) {
        d.alpha_x = d.alpha_y = roughness->get<float>();
    } else if (roughness && roughness->is_array() && roughness->size() == 2 &&
               (*roughness)[0].is_number() && (*roughness)[1].is_number()) {
        d.alpha_x = (*roughness)[0].get<float>(), d.alpha_y = (*roughness)[1].get<float>();
    } else if (roughness) {
        return;
    }
    if (log_density) d.log_density = log_density->get<float>();
    const GlintDesc before = d;
    model.fit_material(d);
    const auto note = [&](std::string_view key, const nlohmann::json& was,
                          const nlohmann::json& now) {
        fmt::print(stderr, "note: switching to {}: /materials/{}/{}: {} -> {} (what {} accepts)\n",
                   model.name, index, key, was.dump(), now.dump(), model.name);
        m[std::string(key)] = now;
    };
    if (d.ndf != before.ndf)
        note("ndf", ndf ? *ndf : nlohmann::json("beckmann"),
             d.ndf == NdfType::GGX ? "ggx" : "beckmann");
    if (d.alpha_x != before.alpha_x || d.alpha_y != before.alpha_y)
        note("roughness", roughness ? *roughness : nlohmann::json(before.alpha_x),
             d.alpha_x == d.alpha_y ? nlohmann::json(d.alpha_x)
                                    : nlohmann::json::array({d.alpha_x, d.alpha_y}));
    if (d.log_density != before.log_density)
        note("log_density", log_density ? *log_density : nlohmann::json(before.log_density),
             d.log_density);
}

}  // namespace

void set_glint_model(nlohmann::json& document, std::string_view model) {
    const GlintModelDescriptor* descriptor = find_glint_model(model);
    int switched = 0;
    if (document.is_object() && document.contains("materials") && document["materials"].is_array())
        for (size_t i = 0; i < document["materials"].size(); ++i) {
            nlohmann::json& m = document["materials"][i];
            if (m.is_object() && m.value("type", "") == "glint") {
                m["model"] = std::string(model);
                if (descriptor != nullptr) fit_switched_material(m, *descriptor, i);
                ++switched;
            }
        }
    if (switched == 0)
        fail("--model {}: the scene has no glint material (\"type\": \"glint\") to switch", model);
}

void apply_override(nlohmann::json& document, std::string_view pointer,
                    const nlohmann::json& value) {
    const std::string text(pointer);
    nlohmann::json::json_pointer ptr;
    try {
        ptr = nlohmann::json::json_pointer(text);
    } catch (const nlohmann::json::exception&) {
        fail("--set {}: not a JSON pointer (RFC 6901: \"/key/0/key\", ~0 for ~ and ~1 for /)",
             text);
    }
    if (ptr.empty()) fail("--set \"\": replacing the whole document is not an override");
    const std::string last = ptr.back();
    const nlohmann::json::json_pointer parent_ptr = ptr.parent_pointer();
    nlohmann::json* parent = nullptr;
    try {
        parent = &document.at(parent_ptr);
    } catch (const nlohmann::json::exception&) {
        fail("--set {}: {} does not exist (an override sets a value below an existing one)", text,
             parent_ptr.empty() ? "/" : parent_ptr.to_string());
    }
    if (parent->is_object()) {
        (*parent)[last] = value;
    } else if (parent->is_array()) {
        if (last == "-") {
            parent->push_back(value);
            return;
        }
        size_t index = 0;
        const char* end = last.data() + last.size();
        const auto r = std::from_chars(last.data(), end, index);
        if (last.empty() || r.ec != std::errc() || r.ptr != end ||
            (last.size() > 1 && last[0] == '0'))
            fail("--set {}: {} is an array; \"{}\" is not an index", text, parent_ptr.to_string(),
                 last);
        if (index >= parent->size())
            fail("--set {}: {} has {} entries, no index {} (\"-\" appends)", text,
                 parent_ptr.to_string(), parent->size(), index);
        (*parent)[index] = value;
    } else {
        fail("--set {}: {} is neither an object nor an array", text,
             parent_ptr.empty() ? "/" : parent_ptr.to_string());
    }
}

void apply_override_assignment(nlohmann::json& document, std::string_view assignment) {
    const size_t eq = assignment.find('=');
    if (eq == std::string_view::npos || eq == 0)
        fail("--set {}: expected POINTER=VALUE, e.g. /materials/0/log_density=14", assignment);
    const std::string_view pointer = assignment.substr(0, eq);
    const std::string text(assignment.substr(eq + 1));
    nlohmann::json value = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (value.is_discarded()) value = text;  // a bare word: a string
    apply_override(document, pointer, value);
}

Scene load_scene(const std::filesystem::path& file, const SceneEdits& edits) {
    if (const std::string problem = regular_file_problem(file); !problem.empty())
        fail("{}: cannot read the scene file: it {}", file.string(), problem);
    std::ifstream in(file);
    if (!in) fail("{}: cannot open scene file", file.string());
    nlohmann::json document = parse_json(in, file.string());
    if (!edits.model.empty()) set_glint_model(document, edits.model);
    for (const std::string& s : edits.sets) apply_override_assignment(document, s);
    return parse_scene(document, file);
}

}  // namespace glintlab
