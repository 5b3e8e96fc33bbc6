#include "glintlab/core/shader_assembly.h"

#include <cctype>
#include <optional>
#include <set>
#include <sstream>

#include "glintlab/core/error.h"
#include "glintlab/core/shader_sources.h"

namespace glintlab {
namespace {

std::string_view find_source(std::string_view path) {
    for (const ShaderSource& s : shader_sources()) {
        if (s.path == path) return s.text;
    }
    fail("shader source '{}' not found among the embedded .glsl files", path);
}

// The file named by a line `#include "path"` (spaces allowed around '#'), if it is one.
std::optional<std::string> include_target(std::string_view line) {
    size_t i = 0;
    auto skip_space = [&] {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    };
    skip_space();
    if (i >= line.size() || line[i] != '#') return std::nullopt;
    ++i;
    skip_space();
    if (line.substr(i, 7) != "include") return std::nullopt;
    i += 7;
    skip_space();
    if (i >= line.size() || line[i] != '"') return std::nullopt;
    const size_t close = line.find('"', i + 1);
    if (close == std::string_view::npos) return std::nullopt;
    const std::string_view rest = line.substr(close + 1);
    for (char c : rest)
        if (!std::isspace(static_cast<unsigned char>(c))) return std::nullopt;
    return std::string(line.substr(i + 1, close - i - 1));
}

struct Assembler {
    AssembledShader out;
    std::set<std::string, std::less<>> included;

    void add(std::string_view path, std::string_view text) {
        const int index = static_cast<int>(out.files.size());
        out.files.emplace_back(path);
        out.text += fmt::format("#line 1 {}\n", index);
        std::istringstream lines{std::string(text)};
        std::string line;
        int number = 0;
        while (std::getline(lines, line)) {
            ++number;
            if (const auto target = include_target(line)) {
                if (!included.contains(*target)) {
                    included.insert(*target);
                    add(*target, find_source(*target));
                    out.text += fmt::format("#line {} {}\n", number + 1, index);
                } else {
                    out.text += "\n";
                }
                continue;
            }
            out.text += line;
            out.text += '\n';
        }
    }
};

}  // namespace

std::string glsl_prelude(std::string_view version) {
    return fmt::format(
        "#version {}\n"
        "#define INOUT(T) inout T\n"
        "#define OUT(T) out T\n"
        "#define GLINTLAB_GLSL 1\n",
        version);
}

AssembledShader assemble_shader(std::string_view root, bool root_is_text,
                                std::string_view prelude) {
    Assembler a;
    a.out.text = prelude.empty() ? glsl_prelude() : std::string(prelude);
    if (root_is_text) {
        a.add("<inline>", root);
    } else {
        a.included.insert(std::string(root));
        a.add(root, find_source(root));
    }
    return std::move(a.out);
}

std::string map_shader_log(const AssembledShader& shader, std::string_view log) {
    // Locations "K:N" (glslang: "ERROR: 3:17: ..."; Mesa: "3:17(5): ...") and
    // "K(N)" (NVIDIA: "3(17) : error ...") become "path:N".
    std::string out;
    size_t i = 0;
    auto digits_end = [&](size_t from) {
        size_t j = from;
        while (j < log.size() && std::isdigit(static_cast<unsigned char>(log[j]))) ++j;
        return j;
    };
    while (i < log.size()) {
        const bool starts_number =
            std::isdigit(static_cast<unsigned char>(log[i])) &&
            (i == 0 || !std::isalnum(static_cast<unsigned char>(log[i - 1])));
        if (starts_number) {
            const size_t k_end = digits_end(i);
            if (k_end < log.size() && (log[k_end] == ':' || log[k_end] == '(')) {
                const size_t n_end = digits_end(k_end + 1);
                const bool paren = log[k_end] == '(';
                const bool well_formed =
                    n_end > k_end + 1 && (!paren || (n_end < log.size() && log[n_end] == ')'));
                const size_t k = std::stoul(std::string(log.substr(i, k_end - i)));
                if (well_formed && k < shader.files.size()) {
                    out += shader.files[k] + ":" +
                           std::string(log.substr(k_end + 1, n_end - k_end - 1));
                    i = paren ? n_end + 1 : n_end;
                    continue;
                }
            }
            out.append(log.substr(i, k_end - i));
            i = k_end;
            continue;
        }
        out += log[i++];
    }
    return out;
}

}  // namespace glintlab
