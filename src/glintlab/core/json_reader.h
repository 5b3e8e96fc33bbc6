// Strict reading of JSON scene descriptions: every value is checked for type
// and range, every key must be known, and every error names the file, the
// JSON path of the value and what is allowed (ARCHITECTURE.md "Errors").
#pragma once

#include <filesystem>
#include <istream>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "glintlab/core/json_depth.h"

namespace glintlab {

// An allowed interval of numbers. Bounds are the documented decimals and are
// compared with the value as written (double): a value equal to a closed
// bound is accepted, an open end excludes exactly its bound. For values
// stored as float (`single_precision`) an open end also rejects values that
// round onto it (e.g. eta = 1 + 1e-9 is 1.0f, the excluded end).
struct NumberRange {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool min_open = false, max_open = false;
    bool single_precision = false;

    bool contains(double x) const;
    // "[0.001, 1]", "(1, 4]", ">= 0", "< 1", "finite" (%g-style bounds).
    std::string text() const;
};

// Parses a JSON document strictly: syntax errors, duplicate keys in an
// object and numbers beyond double's range are errors naming `file` and (for
// the last two) the JSON path.
nlohmann::json parse_json(std::istream& in, const std::string& file);

// A JSON object being read: remembers which keys were read so that finish()
// can reject the ones nobody asked for.
class JsonObject {
  public:
    JsonObject(const nlohmann::json& value, std::string path, std::string file);

    const std::string& path() const { return path_; }
    const std::string& file() const { return file_; }
    bool has(std::string_view key) const;

    // Numbers: in [min, max]; the error names the key and the range.
    double number(std::string_view key, double fallback, double min, double max);
    double number(std::string_view key, double fallback, const NumberRange& range);
    double required_number(std::string_view key, double min, double max);
    int integer(std::string_view key, int fallback, int min, int max);
    bool boolean(std::string_view key, bool fallback);
    std::string string(std::string_view key, std::string fallback,
                       const std::vector<std::string>& allowed = {});
    std::string required_string(std::string_view key, const std::vector<std::string>& allowed = {});
    // Components in [min, max] (doubles: pass the documented decimals).
    glm::vec3 vec3(std::string_view key, glm::vec3 fallback, double min, double max);
    glm::vec3 required_vec3(std::string_view key, double min, double max);
    // A colour: an RGB triple or a single number meaning grey, each in [min, max].
    glm::vec3 color(std::string_view key, glm::vec3 fallback, double min, double max);
    glm::vec2 vec2(std::string_view key, glm::vec2 fallback, double min, double max);
    // A path relative to the scene file; must name an existing file.
    std::filesystem::path file_path(std::string_view key);

    std::optional<JsonObject> object(std::string_view key);
    JsonObject required_object(std::string_view key);
    // An array of objects (empty if absent).
    std::vector<JsonObject> object_array(std::string_view key);
    // Raw access for values read elsewhere (marks the key as used).
    const nlohmann::json* raw(std::string_view key);

    // Marks a key as known without reading it.
    void ignore(std::string_view key);
    // Throws if a key was present but never read, listing the known keys.
    void finish() const;

    [[noreturn]] void error(std::string_view key, std::string_view message) const;
    // An error at `key` of the object enclosing this one (a model's block
    // checking a key of its material: "/materials/0/log_density").
    [[noreturn]] void parent_error(std::string_view key, std::string_view message) const;

  private:
    const nlohmann::json* get(std::string_view key);
    std::string key_path(std::string_view key) const;

    const nlohmann::json& value_;
    std::string path_;
    std::string file_;
    std::set<std::string, std::less<>> read_;
};

// "array of 3 numbers" → vec3, with the same error conventions.
glm::vec3 json_to_vec3(const nlohmann::json& v, const std::string& where, double min, double max);

}  // namespace glintlab
