#include <embree3/rtcore.h>
#include <tbb/version.h>

#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "glintlab/core/error.h"
#include "glintlab/core/shader_sources.h"
#include "glintlab/glints/model_docs.h"
#include "glintlab/glints/registry.h"

namespace glintlab::cmd {
namespace {

struct InfoArgs {
    bool json = false;
    std::string markdown;
    std::vector<std::string> update_docs;
};

// (name, text) of every enabled feature, for the text and JSON forms.
std::vector<std::pair<std::string, std::string>> features() {
    std::vector<std::pair<std::string, std::string>> f = {
        {"cpu renderer", fmt::format("Embree {} + oneTBB {}.{}, integrators: direct, path",
                                     RTC_VERSION_STRING, TBB_VERSION_MAJOR, TBB_VERSION_MINOR)},
        {"image formats", "read .exr (any compression), .hdr, .png, .jpg; write .exr, .png, .hdr"},
        {"scene shapes", "quad, sphere, torus, heightfield, obj, gltf/glb"},
        {"lights", "point, directional (optional solid angle), sphere, environment"},
        {"shared shaders",
         fmt::format("{} .glsl files (C++ and GLSL 4.50)", shader_sources().size())},
#if GLINTLAB_WITH_GL
        {"gpu renderer",
         "OpenGL 4.5 core: headless EGL (render --gpu, bench --gpu), GLFW viewer (view)"},
#else
        {"gpu renderer", "not built (configured with -DGLINTLAB_WITH_GL=OFF)"},
#endif
    };
    return f;
}

// Back ends a model has in this build (gpu needs GLINTLAB_WITH_GL).
std::string backends(const GlintModelDescriptor& m) {
#if GLINTLAB_WITH_GL
    const bool gpu = m.gpu;
#else
    const bool gpu = false;
#endif
    return m.cpu && gpu ? "cpu+gpu" : gpu ? "gpu" : "cpu";
}

void print_text() {
    fmt::print("glintlab {}\n", GLINTLAB_VERSION);
    fmt::print("features:\n");
    for (const auto& [name, text] : features()) fmt::print("  {:<16} {}\n", name, text);
    fmt::print("glint models:\n");
    for (const GlintModelDescriptor& m : glint_models())
        fmt::print("  {:<14} {:<8} {}\n", m.name, backends(m), m.description);
    fmt::print(
        "texture inputs (a map in place of the number; docs/SCENE_FORMAT.md \"Textures\"):\n");
    for (const GlintModelDescriptor& m : glint_models()) {
        const GlintTextureInputs t = glint_texture_inputs(m);
        fmt::print("  {:<14} {}\n", m.name, fmt::join(t.keys, ", "));
        if (!t.refused.empty())
            fmt::print("  {:<14} not {}: {}\n", "", fmt::join(t.refused, ", "), t.reason);
    }
}

void print_json() {
    nlohmann::json j;
    j["version"] = GLINTLAB_VERSION;
    j["features"] = nlohmann::json::object();
    for (const auto& [name, text] : features()) j["features"][name] = text;
#if GLINTLAB_WITH_GL
    j["gpu_built"] = true;
#else
    j["gpu_built"] = false;
#endif
    j["models"] = nlohmann::json::array();
    for (const GlintModelDescriptor& m : glint_models())
        j["models"].push_back(glint_model_to_json(m));
    fmt::print("{}\n", j.dump(2));
}

void update_docs(const std::vector<std::string>& files) {
    for (const std::string& file : files) {
        std::ifstream in(file);
        if (!in) fail("{}: cannot open", file);
        std::stringstream buffer;
        buffer << in.rdbuf();
        const std::string old_text = buffer.str();
        const std::string new_text = update_generated_sections(old_text, file);
        if (new_text == old_text) {
            fmt::print("{}: up to date\n", file);
            continue;
        }
        std::ofstream out(file);
        out << new_text;
        if (!out) fail("{}: cannot write", file);
        fmt::print("{}: updated\n", file);
    }
}

}  // namespace

void add_info_command(CLI::App& app, int* status) {
    auto args = std::make_shared<InfoArgs>();
    CLI::App* sub =
        app.add_subcommand("info", "Print the version, the enabled features and the glint models");
    sub->add_flag("--json", args->json,
                  "Print one JSON object: version, features, every model's descriptor");
    sub->add_option("--markdown", args->markdown,
                    "Print a documentation section generated from the model descriptors")
        ->check(CLI::IsMember(model_doc_sections()));
    sub->add_option("--update-docs", args->update_docs,
                    "Rewrite the generated sections of these Markdown files (docs/MODELS.md, "
                    "docs/SCENE_FORMAT.md)");
    sub->callback([args, status] {
        if (!args->update_docs.empty())
            update_docs(args->update_docs);
        else if (!args->markdown.empty())
            fmt::print("{}", model_doc_markdown(args->markdown));
        else if (args->json)
            print_json();
        else
            print_text();
        *status = 0;
    });
}

}  // namespace glintlab::cmd
