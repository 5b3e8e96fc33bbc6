// The nesting limit of every JSON document glintlab reads, apart from the
// JSON library's types: the glTF loader includes it beside tinygltf's own
// copy of nlohmann::json.
#pragma once

#include <cstddef>
#include <string_view>

namespace glintlab {

// Arrays and objects nested deeper than this are refused (parse_json, the
// glTF loader): every later walk of a value (dump, tinygltf's recursive
// readers) then stays far inside the stack.
inline constexpr size_t kMaxJsonNesting = 256;

// The deepest nesting of arrays and objects in JSON text, strings skipped;
// an iterative scan, so any text is safe to measure (malformed text gives
// some depth, and its parser reports the syntax).
size_t json_nesting_depth(std::string_view text);

}  // namespace glintlab
