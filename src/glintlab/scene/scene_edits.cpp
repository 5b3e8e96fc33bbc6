#include "glintlab/scene/scene_edits.h"

#include <charconv>
#include <fstream>

#include "glintlab/core/error.h"
#include "glintlab/core/json_reader.h"
#include "glintlab/core/regular_file.h"
#include "glintlab/scene/scene_loader.h"

namespace glintlab {

void set_glint_model(nlohmann::json& document, std::string_view model) {
    int switched = 0;
    if (document.is_object() && document.contains("materials") && document["materials"].is_array())
        for (nlohmann::json& m : document["materials"])
            if (m.is_object() && m.value("type", "") == "glint") {
                m["model"] = std::string(model);
                ++switched;
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
