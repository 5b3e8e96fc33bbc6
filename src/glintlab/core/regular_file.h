// Input files are read only when they are regular files: a directory, a
// device (/dev/zero reads forever) or a FIFO (an open blocks until a writer
// comes) is refused with what it is, not reported as "not found".
#pragma once

#include <filesystem>
#include <string>

namespace glintlab {

// "" when `path` is a regular file (or a link to one); otherwise what it is:
// "does not exist", "is a directory", "is a device, FIFO or socket, not a
// regular file".
std::string regular_file_problem(const std::filesystem::path& path);

}  // namespace glintlab
