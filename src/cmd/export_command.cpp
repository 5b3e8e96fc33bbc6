// `glintlab export MODEL --lang glsl|glsles|hlsl [-o DIR] [--env FILE]
//  [--scene SCENE.json [--material NAME]]`
// (export/shader_export.h, docs/INTEGRATION.md).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "commands.h"
#include "glintlab/export/shader_export.h"

namespace glintlab::cmd {

void add_export_command(CLI::App& app, int* status) {
    struct Args {
        std::string model, lang = "glsl", out = "export", env, scene, material;
        bool quiet = false, shaders_only = false;
    };
    auto args = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand(
        "export",
        fmt::format("Write one GPU glint model as a standalone shader with its resources and a "
                    "JSON manifest (docs/INTEGRATION.md). Models: {}",
                    fmt::join(exportable_models(), ", ")));
    sub->add_option("model", args->model, "Model name")->required();
    sub->add_option("--lang", args->lang, "glsl (4.50), glsles (3.00, WebGL2) or hlsl (SM 5.0)")
        ->check(CLI::IsMember({"glsl", "glsles", "hlsl"}));
    sub->add_option("-o,--output", args->out, "Output directory (created)");
    sub->add_option("--env", args->env,
                    "Environment map (EXR/HDR/PNG, lat-long): kneiphof2025 also writes its "
                    "prefiltered maps for it");
    sub->add_option("--scene", args->scene,
                    "Scene file (JSON): export the resources and parameter values of one of its "
                    "glint materials instead of the model's defaults (its environment too, "
                    "unless --env)");
    sub->add_option("--material", args->material,
                    "Name of the --scene material (default: the scene's first glint material of "
                    "MODEL)");
    sub->add_flag("--shaders-only", args->shaders_only,
                  "Write the shaders and the manifest only (no resource files)");
    sub->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
    sub->callback([args, status] {
        ExportOptions o;
        o.model = args->model;
        o.language = parse_export_language(args->lang);
        o.out_dir = args->out;
        o.environment = args->env;
        o.scene = args->scene;
        o.material = args->material;
        o.resources = !args->shaders_only;
        const std::vector<ExportedFile> files = export_model(o);
        if (!args->quiet)
            for (const ExportedFile& f : files)
                fmt::print("{}/{}  ({}, {} bytes)\n", args->out, f.name, f.kind, f.bytes);
        *status = 0;
    });
}

}  // namespace glintlab::cmd
