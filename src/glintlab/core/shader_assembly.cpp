#include "glintlab/core/shader_assembly.h"

#include <regex>
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
        static const std::regex include_re(R"(^\s*#\s*include\s+\"([^\"]+)\"\s*$)");
        while (std::getline(lines, line)) {
            ++number;
            std::smatch m;
            if (std::regex_match(line, m, include_re)) {
                const std::string target = m[1];
                if (!included.contains(target)) {
                    included.insert(target);
                    add(target, find_source(target));
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
    // glslang: "ERROR: 3:17: ..."; Mesa: "3:17(5): error: ..."; NVIDIA: "3(17) : error ...".
    static const std::regex loc_re(R"((\b)(\d+)(?::(\d+)|\((\d+)\)))");
    std::string text(log);
    std::string result;
    auto begin = text.cbegin();
    std::smatch m;
    while (std::regex_search(begin, text.cend(), m, loc_re)) {
        result.append(begin, m[0].first);
        const size_t k = std::stoul(m[2]);
        const std::string line = m[3].matched ? m[3].str() : m[4].str();
        if (k < shader.files.size()) {
            result += shader.files[k] + ":" + line;
        } else {
            result += m[0].str();
        }
        begin = m[0].second;
    }
    result.append(begin, text.cend());
    return result;
}

}  // namespace glintlab
