// Strict reading of JSON scene descriptions: every value is checked for type
// and range, every key must be known, and every error names the file, the
// JSON path of the value and what is allowed (ARCHITECTURE.md §5).
#pragma once

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace glintlab {

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
    double required_number(std::string_view key, double min, double max);
    int integer(std::string_view key, int fallback, int min, int max);
    bool boolean(std::string_view key, bool fallback);
    std::string string(std::string_view key, std::string fallback,
                       const std::vector<std::string>& allowed = {});
    std::string required_string(std::string_view key, const std::vector<std::string>& allowed = {});
    glm::vec3 vec3(std::string_view key, glm::vec3 fallback, float min, float max);
    glm::vec3 required_vec3(std::string_view key, float min, float max);
    // A colour: an RGB triple or a single number meaning grey, each in [min, max].
    glm::vec3 color(std::string_view key, glm::vec3 fallback, float min, float max);
    glm::vec2 vec2(std::string_view key, glm::vec2 fallback, float min, float max);
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

private:
    const nlohmann::json* get(std::string_view key);
    std::string key_path(std::string_view key) const;

    const nlohmann::json& value_;
    std::string path_;
    std::string file_;
    std::set<std::string, std::less<>> read_;
};

// "array of 3 numbers" → vec3, with the same error conventions.
glm::vec3 json_to_vec3(const nlohmann::json& v, const std::string& where, float min, float max);

}  // namespace glintlab
