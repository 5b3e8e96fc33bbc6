#include "glintlab/scene/json_reader.h"

#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "glintlab/core/error.h"

namespace glintlab {
namespace {

std::string range_text(double min, double max) {
    const bool lo = std::isfinite(min), hi = std::isfinite(max);
    // %g-style: ranges that came from floats print as 0.001, not 0.0010000000474974513.
    if (lo && hi) return fmt::format("in [{:.6g}, {:.6g}]", min, max);
    if (lo) return fmt::format(">= {:.6g}", min);
    if (hi) return fmt::format("<= {:.6g}", max);
    return "finite";
}

std::string brief(const nlohmann::json& v) {
    std::string s = v.dump();
    if (s.size() > 40) s = s.substr(0, 37) + "...";
    return s;
}

}  // namespace

JsonObject::JsonObject(const nlohmann::json& value, std::string path, std::string file)
    : value_(value), path_(std::move(path)), file_(std::move(file)) {
    if (!value_.is_object())
        fail("{}: {}: expected an object, got {}", file_, path_.empty() ? "/" : path_,
             brief(value_));
}

std::string JsonObject::key_path(std::string_view key) const {
    return fmt::format("{}/{}", path_, key);
}

void JsonObject::error(std::string_view key, std::string_view message) const {
    fail("{}: {}: {}", file_, key.empty() ? path_ : key_path(key), message);
}

bool JsonObject::has(std::string_view key) const { return value_.contains(std::string(key)); }

const nlohmann::json* JsonObject::get(std::string_view key) {
    read_.insert(std::string(key));
    auto it = value_.find(std::string(key));
    return it == value_.end() ? nullptr : &*it;
}

const nlohmann::json* JsonObject::raw(std::string_view key) { return get(key); }

void JsonObject::ignore(std::string_view key) { read_.insert(std::string(key)); }

double JsonObject::number(std::string_view key, double fallback, double min, double max) {
    const nlohmann::json* v = get(key);
    if (!v) return fallback;
    if (!v->is_number())
        error(key, fmt::format("expected a number {}, got {}", range_text(min, max), brief(*v)));
    const double x = v->get<double>();
    if (!std::isfinite(x) || x < min || x > max)
        error(key, fmt::format("value {} out of range: allowed {}", x, range_text(min, max)));
    return x;
}

double JsonObject::required_number(std::string_view key, double min, double max) {
    if (!has(key)) error(key, fmt::format("missing required number {}", range_text(min, max)));
    return number(key, 0.0, min, max);
}

int JsonObject::integer(std::string_view key, int fallback, int min, int max) {
    const nlohmann::json* v = get(key);
    if (!v) return fallback;
    if (!v->is_number_integer())
        error(key, fmt::format("expected an integer in [{}, {}], got {}", min, max, brief(*v)));
    const auto x = v->get<int64_t>();
    if (x < min || x > max)
        error(key, fmt::format("value {} out of range: allowed [{}, {}]", x, min, max));
    return static_cast<int>(x);
}

bool JsonObject::boolean(std::string_view key, bool fallback) {
    const nlohmann::json* v = get(key);
    if (!v) return fallback;
    if (!v->is_boolean()) error(key, fmt::format("expected true or false, got {}", brief(*v)));
    return v->get<bool>();
}

std::string JsonObject::string(std::string_view key, std::string fallback,
                               const std::vector<std::string>& allowed) {
    const nlohmann::json* v = get(key);
    if (!v) return fallback;
    if (!v->is_string()) error(key, fmt::format("expected a string, got {}", brief(*v)));
    std::string s = v->get<std::string>();
    if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), s) == allowed.end())
        error(key, fmt::format("unknown value \"{}\": allowed {}", s, fmt::join(allowed, ", ")));
    return s;
}

std::string JsonObject::required_string(std::string_view key,
                                        const std::vector<std::string>& allowed) {
    if (!has(key)) {
        if (allowed.empty()) error(key, "missing required string");
        error(key, fmt::format("missing required string, one of {}", fmt::join(allowed, ", ")));
    }
    return string(key, "", allowed);
}

glm::vec3 json_to_vec3(const nlohmann::json& v, const std::string& where, float min, float max) {
    if (!v.is_array() || v.size() != 3)
        fail("{}: expected an array of 3 numbers {}, got {}", where, range_text(min, max),
             brief(v));
    glm::vec3 r;
    for (int i = 0; i < 3; ++i) {
        if (!v[i].is_number())
            fail("{}: expected an array of 3 numbers {}, got {}", where, range_text(min, max),
                 brief(v));
        const double x = v[i].get<double>();
        if (!std::isfinite(x) || x < min || x > max)
            fail("{}: component {} = {} out of range: allowed {}", where, i, x,
                 range_text(min, max));
        r[i] = static_cast<float>(x);
    }
    return r;
}

glm::vec3 JsonObject::vec3(std::string_view key, glm::vec3 fallback, float min, float max) {
    const nlohmann::json* v = get(key);
    if (!v) return fallback;
    return json_to_vec3(*v, fmt::format("{}: {}", file_, key_path(key)), min, max);
}

glm::vec3 JsonObject::required_vec3(std::string_view key, float min, float max) {
    if (!has(key))
        error(key, fmt::format("missing required array of 3 numbers {}", range_text(min, max)));
    return vec3(key, glm::vec3(0.0f), min, max);
}

glm::vec3 JsonObject::color(std::string_view key, glm::vec3 fallback, float min, float max) {
    const nlohmann::json* v = get(key);
    if (!v) return fallback;
    if (v->is_number()) return glm::vec3(static_cast<float>(number(key, 0.0, min, max)));
    if (!v->is_array())
        error(key, fmt::format("expected an RGB array of 3 numbers or one number {}, got {}",
                               range_text(min, max), brief(*v)));
    return vec3(key, fallback, min, max);
}

glm::vec2 JsonObject::vec2(std::string_view key, glm::vec2 fallback, float min, float max) {
    const nlohmann::json* v = get(key);
    if (!v) return fallback;
    if (v->is_number()) return glm::vec2(static_cast<float>(number(key, 0.0, min, max)));
    if (!v->is_array() || v->size() != 2 || !(*v)[0].is_number() || !(*v)[1].is_number())
        error(key, fmt::format("expected one number or an array of 2 numbers {}, got {}",
                               range_text(min, max), brief(*v)));
    glm::vec2 r;
    for (int i = 0; i < 2; ++i) {
        const double x = (*v)[i].get<double>();
        if (!std::isfinite(x) || x < min || x > max)
            error(key, fmt::format("component {} = {} out of range: allowed {}", i, x,
                                   range_text(min, max)));
        r[i] = static_cast<float>(x);
    }
    return r;
}

std::filesystem::path JsonObject::file_path(std::string_view key) {
    const std::string name = required_string(key);
    std::filesystem::path p(name);
    if (p.is_relative()) p = std::filesystem::path(file_).parent_path() / p;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec))
        error(key, fmt::format("file not found: {}", p.string()));
    return p;
}

std::optional<JsonObject> JsonObject::object(std::string_view key) {
    const nlohmann::json* v = get(key);
    if (!v) return std::nullopt;
    if (!v->is_object()) error(key, fmt::format("expected an object, got {}", brief(*v)));
    return JsonObject(*v, key_path(key), file_);
}

JsonObject JsonObject::required_object(std::string_view key) {
    if (!has(key)) error(key, "missing required object");
    return *object(key);
}

std::vector<JsonObject> JsonObject::object_array(std::string_view key) {
    const nlohmann::json* v = get(key);
    std::vector<JsonObject> out;
    if (!v) return out;
    if (!v->is_array()) error(key, fmt::format("expected an array of objects, got {}", brief(*v)));
    for (size_t i = 0; i < v->size(); ++i)
        out.emplace_back((*v)[i], fmt::format("{}/{}", key_path(key), i), file_);
    return out;
}

void JsonObject::finish() const {
    std::vector<std::string> unknown;
    for (const auto& [k, _] : value_.items())
        if (!read_.contains(k)) unknown.push_back(k);
    if (unknown.empty()) return;
    fail("{}: {}: unknown key \"{}\" (known keys here: {})", file_, key_path(unknown.front()),
         unknown.front(), fmt::join(read_, ", "));
}

}  // namespace glintlab
