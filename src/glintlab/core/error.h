// The one exception type of glintlab: a message meant for the user, naming
// the file, the key and the allowed range where they apply.
#pragma once

#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace glintlab {

class Error : public std::runtime_error {
  public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

template <typename... Args>
[[noreturn]] void fail(fmt::format_string<Args...> format, Args&&... args) {
    throw Error(fmt::format(format, std::forward<Args>(args)...));
}

}  // namespace glintlab
