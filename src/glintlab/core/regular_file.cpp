#include "glintlab/core/regular_file.h"

namespace glintlab {

std::string regular_file_problem(const std::filesystem::path& path) {
    std::error_code ec;
    const std::filesystem::file_status s = std::filesystem::status(path, ec);
    if (std::filesystem::is_regular_file(s)) return "";
    if (!std::filesystem::exists(s)) return "does not exist";
    if (std::filesystem::is_directory(s)) return "is a directory";
    return "is a device, FIFO or socket, not a regular file";
}

}  // namespace glintlab
