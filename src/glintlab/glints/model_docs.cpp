#include "glintlab/glints/model_docs.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "glintlab/core/error.h"
#include "glintlab/glints/registry.h"

namespace glintlab {
namespace {

nlohmann::json value_json(const GlintParamValue& v) {
    if (const double* x = std::get_if<double>(&v)) return *x;
    if (const int* x = std::get_if<int>(&v)) return *x;
    if (const bool* x = std::get_if<bool>(&v)) return *x;
    return std::get<std::string>(v);
}

std::string lights_text(const GlintModelDescriptor& m) {
    std::vector<std::string> names;
    for (GlintLightType t : m.lights) names.emplace_back(glint_light_type_name(t));
    return fmt::format("{}", fmt::join(names, ", "));
}

std::string backends_text(const GlintModelDescriptor& m) {
    std::vector<std::string> b;
    if (m.cpu) b.emplace_back("cpu");
    if (m.gpu) b.emplace_back("gpu");
    return fmt::format("{}", fmt::join(b, ", "));
}

std::string citation_short(const GlintCitation& c) {
    // "Deliot & Belcour 2023 (000)", "Jakob et al. 2014 (002)".
    std::vector<std::string> authors;
    size_t start = 0;
    while (start <= c.authors.size()) {
        size_t comma = c.authors.find(", ", start);
        if (comma == std::string::npos) comma = c.authors.size();
        authors.push_back(c.authors.substr(start, comma - start));
        start = comma + 2;
    }
    std::string who = authors.size() == 1   ? authors[0]
                      : authors.size() == 2 ? authors[0] + " & " + authors[1]
                                            : authors[0] + " et al.";
    std::string s = fmt::format("{} {}", who, c.year);
    if (!c.key.empty()) s += fmt::format(" ({})", c.key);
    return s;
}

std::string citations_text(const GlintModelDescriptor& m) {
    std::vector<std::string> c;
    for (const GlintCitation& x : m.citations) c.push_back(citation_short(x));
    return fmt::format("{}", fmt::join(c, "; "));
}

std::string models_table() {
    std::string s = "| model | paper | lights | back ends | description |\n|---|---|---|---|---|\n";
    for (const GlintModelDescriptor& m : glint_models())
        s += fmt::format("| `{}` | {} | {} | {} | {} |\n", m.name, citations_text(m),
                         lights_text(m), backends_text(m), m.description);
    return s;
}

std::string param_table(const GlintModelDescriptor& m) {
    if (m.params.empty() && m.extra_keys.empty()) return "No parameters of its own.\n";
    std::string s =
        "| key | type | default | range | unit | meaning |\n|---|---|---|---|---|---|\n";
    for (const GlintParam& p : m.params)
        s +=
            fmt::format("| `{}` | {} | {} | {} | {} | {} |\n", p.key, glint_param_type_name(p.type),
                        glint_param_value_text(m.default_value(p)), p.range_text(), p.unit, p.doc);
    for (const GlintExtraKey& k : m.extra_keys)
        s += fmt::format("| `{}` | array | (none) | see meaning | | {} |\n", k.key, k.doc);
    return s;
}

std::string parameters_section() {
    std::string s;
    for (const GlintModelDescriptor& m : glint_models()) {
        if (!s.empty()) s += "\n";
        s += fmt::format("#### `{}`\n\n{}", m.name, param_table(m));
    }
    return s;
}

std::string citations_section() {
    // Each paper once, in key order, then those without a key.
    std::vector<const GlintCitation*> seen;
    for (const GlintModelDescriptor& m : glint_models())
        for (const GlintCitation& c : m.citations) {
            bool dup = false;
            for (const GlintCitation* x : seen) dup |= x->title == c.title;
            if (!dup) seen.push_back(&c);
        }
    std::stable_sort(seen.begin(), seen.end(), [](const GlintCitation* a, const GlintCitation* b) {
        if (a->key.empty() != b->key.empty()) return b->key.empty();
        return a->key < b->key;
    });
    std::string s = "| key | citation |\n|---|---|\n";
    for (const GlintCitation* c : seen)
        s += fmt::format("| {} | {} ({}). *{}*. {}. |\n", c->key.empty() ? "—" : c->key, c->authors,
                         c->year, c->title, c->venue);
    return s;
}

std::string scene_format_row() {
    std::string s =
        "`model` (required) names the glint model; an unknown name is an error listing the "
        "known ones. Each model's own keys go in a block named after it (docs/MODELS.md):\n\n"
        "| model | lights it can shade | back ends |\n|---|---|---|\n";
    for (const GlintModelDescriptor& m : glint_models())
        s += fmt::format("| `{}` | {} | {} |\n", m.name, lights_text(m), backends_text(m));
    return s;
}

}  // namespace

nlohmann::json glint_model_to_json(const GlintModelDescriptor& m) {
    nlohmann::json j;
    j["name"] = m.name;
    j["description"] = m.description;
    j["citations"] = nlohmann::json::array();
    for (const GlintCitation& c : m.citations)
        j["citations"].push_back({{"key", c.key},
                                  {"authors", c.authors},
                                  {"year", c.year},
                                  {"venue", c.venue},
                                  {"title", c.title}});
    j["lights"] = nlohmann::json::array();
    for (GlintLightType t : m.lights) j["lights"].push_back(glint_light_type_name(t));
    j["backends"] = nlohmann::json::array();
    if (m.cpu) j["backends"].push_back("cpu");
    if (m.gpu) j["backends"].push_back("gpu");
    j["parameters"] = nlohmann::json::array();
    for (const GlintParam& p : m.params) {
        nlohmann::json q = {{"key", p.key},
                            {"type", glint_param_type_name(p.type)},
                            {"default", value_json(m.default_value(p))},
                            {"range", p.range_text()},
                            {"unit", p.unit},
                            {"doc", p.doc}};
        if (p.type == GlintParamType::Number || p.type == GlintParamType::Integer) {
            q["min"] = p.min;
            q["max"] = p.max;
            q["min_open"] = p.min_open;
            q["max_open"] = p.max_open;
        }
        if (!p.integer_values.empty()) q["values"] = p.integer_values;
        if (!p.choices.empty()) q["choices"] = p.choices;
        j["parameters"].push_back(q);
    }
    j["extra_keys"] = nlohmann::json::array();
    for (const GlintExtraKey& k : m.extra_keys)
        j["extra_keys"].push_back({{"key", k.key}, {"doc", k.doc}});
    const GlintTextureInputs textures = glint_texture_inputs(m);
    j["texture_inputs"] = textures.keys;
    if (!textures.refused.empty())
        j["texture_refused"] = {{"keys", textures.refused}, {"reason", textures.reason}};
    j["validation_suite"] =
        m.validation.name.empty() ? nlohmann::json() : nlohmann::json(m.validation.name);
    return j;
}

GlintTextureInputs glint_texture_inputs(const GlintModelDescriptor& m) {
    GlintTextureInputs t;
    auto take = [&](const char* key, bool reads) { (reads ? t.keys : t.refused).push_back(key); };
    take("log_density", m.textured_density);
    take("roughness", m.textured_roughness);
    take("color", true);
    // Models that shade lights themselves have no diffuse base (glint_reader.cpp refuses one).
    take("base_albedo", m.shades_light == nullptr);
    take("normal_map", true);
    std::vector<std::string> reasons;
    if (!m.textured_density || !m.textured_roughness) reasons.push_back(m.untextured_reason);
    if (m.shades_light != nullptr) reasons.push_back("it shades its lights without a diffuse base");
    t.reason = fmt::format("{}", fmt::join(reasons, "; "));
    return t;
}

std::vector<std::string> model_doc_sections() {
    return {"models", "parameters", "citations", "scene-format"};
}

std::string model_doc_markdown(std::string_view section) {
    if (section == "models") return models_table();
    if (section == "parameters") return parameters_section();
    if (section == "citations") return citations_section();
    if (section == "scene-format") return scene_format_row();
    fail("unknown documentation section \"{}\": known sections are {}", section,
         fmt::join(model_doc_sections(), ", "));
}

std::string update_generated_sections(const std::string& text, const std::string& file) {
    static constexpr std::string_view kBegin = "<!-- BEGIN generated: glintlab info --markdown ";
    static constexpr std::string_view kEnd = "<!-- END generated -->";
    std::string out;
    size_t pos = 0;
    while (true) {
        const size_t b = text.find(kBegin, pos);
        if (b == std::string::npos) break;
        const size_t name_end = text.find(" -->", b);
        const size_t line_end = text.find('\n', b);
        if (name_end == std::string::npos || line_end == std::string::npos || name_end > line_end)
            fail("{}: malformed generated-section marker at byte {}", file, b);
        const std::string section(text.substr(b + kBegin.size(), name_end - b - kBegin.size()));
        const size_t e = text.find(kEnd, line_end);
        if (e == std::string::npos)
            fail("{}: generated section \"{}\" has no \"{}\"", file, section, kEnd);
        out += text.substr(pos, line_end + 1 - pos);
        out += model_doc_markdown(section);
        pos = e;
    }
    out += text.substr(pos);
    return out;
}

}  // namespace glintlab
