#include "glintlab/core/json_reader.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "glintlab/core/error.h"
#include "glintlab/core/regular_file.h"

namespace glintlab {
namespace {

std::string range_text(double min, double max) {
    const std::string t = NumberRange{min, max}.text();
    return t.front() == '[' ? "in " + t : t;
}

std::string range_text(const NumberRange& r) {
    const std::string t = r.text();
    return t.front() == '[' || t.front() == '(' ? "in " + t : t;
}

// A key as an error message shows it: a megabyte-long key is cut, not echoed.
std::string shown_key(std::string_view key) {
    if (key.size() <= 64) return std::string(key);
    return fmt::format("{}... ({} bytes)", key.substr(0, 48), key.size());
}

std::string brief(const nlohmann::json& v) {
    std::string s = v.dump();
    if (s.size() > 40) s = s.substr(0, 37) + "...";
    return s;
}

// Tracks the JSON path while nlohmann's parser reports events, to name the
// place of a duplicate key or of a number that overflows double.
class PathTracker {
  public:
    explicit PathTracker(std::string file) : file_(std::move(file)) {}

    bool event(int depth, nlohmann::json::parse_event_t e, const nlohmann::json& parsed) {
        using E = nlohmann::json::parse_event_t;
        (void)depth;
        switch (e) {
            case E::object_start:
            case E::array_start:
                if (frames_.size() >= kMaxJsonNesting)
                    fail("{}: {}: arrays and objects nested deeper than {} levels", file_, path(),
                         kMaxJsonNesting);
                frames_.push_back(Frame{e == E::array_start, 0, {}, {}});
                break;
            case E::key: {
                Frame& f = frames_.back();
                f.key = parsed.get<std::string>();
                if (!f.keys.insert(f.key).second)
                    fail("{}: {}: duplicate key \"{}\" (each key may appear once per object)",
                         file_, path(), shown_key(f.key));
                break;
            }
            case E::object_end:
            case E::array_end:
                frames_.pop_back();
                element_done();
                break;
            case E::value:
                element_done();
                break;
        }
        return true;
    }

    // The path of the value being parsed now ("/" for the root).
    std::string path() const {
        std::string p;
        for (const Frame& f : frames_) {
            p += '/';
            p += f.is_array ? fmt::format("{}", f.index) : shown_key(f.key);
        }
        return p.empty() ? "/" : p;
    }

  private:
    struct Frame {
        bool is_array;
        size_t index;
        std::string key;
        std::set<std::string> keys;
    };
    void element_done() {
        if (!frames_.empty() && frames_.back().is_array) ++frames_.back().index;
    }
    std::string file_;
    std::vector<Frame> frames_;
};

}  // namespace

bool NumberRange::contains(double x) const {
    if (!std::isfinite(x)) return false;
    if (min_open ? !(x > min) : !(x >= min)) return false;
    if (max_open ? !(x < max) : !(x <= max)) return false;
    if (single_precision) {
        const double f = static_cast<double>(static_cast<float>(x));
        if (min_open && !(f > min)) return false;
        if (max_open && !(f < max)) return false;
    }
    return true;
}

std::string NumberRange::text() const {
    const bool lo = std::isfinite(min), hi = std::isfinite(max);
    // %g-style: the documented decimals (0.001, not 0.0010000000474974513).
    if (lo && hi)
        return fmt::format("{}{:.6g}, {:.6g}{}", min_open ? "(" : "[", min, max,
                           max_open ? ")" : "]");
    if (lo) return fmt::format("{} {:.6g}", min_open ? ">" : ">=", min);
    if (hi) return fmt::format("{} {:.6g}", max_open ? "<" : "<=", max);
    return "finite";
}

size_t json_nesting_depth(std::string_view text) {
    size_t depth = 0, deepest = 0;
    bool in_string = false, escaped = false;
    for (const char c : text) {
        if (in_string) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

nlohmann::json parse_json(std::istream& in, const std::string& file) {
    PathTracker tracker(file);
    try {
        return nlohmann::json::parse(
            in, [&tracker](int depth, nlohmann::json::parse_event_t e, nlohmann::json& parsed) {
                return tracker.event(depth, e, parsed);
            });
    } catch (const nlohmann::json::parse_error& e) {
        fail("{}: invalid JSON: {}", file, e.what());
    } catch (const nlohmann::json::out_of_range& e) {
        // nlohmann reports a number beyond double's range (406) this way.
        fail("{}: {}: number out of range (beyond double precision, ~1.8e308): {}", file,
             tracker.path(), e.what());
    }
}

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

void JsonObject::parent_error(std::string_view key, std::string_view message) const {
    const size_t slash = path_.rfind('/');
    const std::string_view parent = slash == std::string::npos
                                        ? std::string_view(path_)
                                        : std::string_view(path_).substr(0, slash);
    fail("{}: {}/{}: {}", file_, parent, key, message);
}

bool JsonObject::has(std::string_view key) const {
    return value_.contains(std::string(key));
}

const nlohmann::json* JsonObject::get(std::string_view key) {
    read_.insert(std::string(key));
    auto it = value_.find(std::string(key));
    return it == value_.end() ? nullptr : &*it;
}

const nlohmann::json* JsonObject::raw(std::string_view key) {
    return get(key);
}

void JsonObject::ignore(std::string_view key) {
    read_.insert(std::string(key));
}

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

double JsonObject::number(std::string_view key, double fallback, const NumberRange& range) {
    const nlohmann::json* v = get(key);
    if (!v) return fallback;
    if (!v->is_number())
        error(key, fmt::format("expected a number {}, got {}", range_text(range), brief(*v)));
    const double x = v->get<double>();
    if (!range.contains(x)) {
        NumberRange as_written = range;
        as_written.single_precision = false;
        error(key, fmt::format("value {} out of range: allowed {}{}", x, range_text(range),
                               as_written.contains(x)
                                   ? fmt::format(" (it is stored as a float and rounds to {})",
                                                 static_cast<float>(x))
                                   : ""));
    }
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

glm::vec3 json_to_vec3(const nlohmann::json& v, const std::string& where, double min, double max) {
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

glm::vec3 JsonObject::vec3(std::string_view key, glm::vec3 fallback, double min, double max) {
    const nlohmann::json* v = get(key);
    if (!v) return fallback;
    return json_to_vec3(*v, fmt::format("{}: {}", file_, key_path(key)), min, max);
}

glm::vec3 JsonObject::required_vec3(std::string_view key, double min, double max) {
    if (!has(key))
        error(key, fmt::format("missing required array of 3 numbers {}", range_text(min, max)));
    return vec3(key, glm::vec3(0.0f), min, max);
}

glm::vec3 JsonObject::color(std::string_view key, glm::vec3 fallback, double min, double max) {
    const nlohmann::json* v = get(key);
    if (!v) return fallback;
    if (v->is_number()) return glm::vec3(static_cast<float>(number(key, 0.0, min, max)));
    if (!v->is_array())
        error(key, fmt::format("expected an RGB array of 3 numbers or one number {}, got {}",
                               range_text(min, max), brief(*v)));
    return vec3(key, fallback, min, max);
}

glm::vec2 JsonObject::vec2(std::string_view key, glm::vec2 fallback, double min, double max) {
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
    if (const std::string problem = regular_file_problem(p); !problem.empty())
        error(key, problem == "does not exist" ? fmt::format("file not found: {}", p.string())
                                               : fmt::format("{} {}", p.string(), problem));
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
    const std::string key = shown_key(unknown.front());
    if (read_.empty())
        fail("{}: {}: unknown key \"{}\" (this object takes no keys)", file_, key_path(key), key);
    fail("{}: {}: unknown key \"{}\" (known keys here: {})", file_, key_path(key), key,
         fmt::join(read_, ", "));
}

}  // namespace glintlab
