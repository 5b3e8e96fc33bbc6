#include "glintlab/realtime/forward_shaders.h"

#include <fmt/format.h>

#include "glintlab/realtime/glint_programs.h"

namespace glintlab::gl {

std::string ProgramKey::name() const {
    const GlintModelInfo* info = find_glint_model(model);
    std::string options;
    if (const GpuModelHooks* hooks = find_gpu_model_hooks(model))
        for (size_t i = 0; i < hooks->options.size(); ++i)
            if ((model_options >> i) & 1u) options += fmt::format(" ({})", hooks->options[i].name);
    return fmt::format(
        "forward[{}{}, {} point, {} directional, {}{}{}]", info ? info->name : "?", options,
        point_lights, directional_lights, environment ? "environment" : "no environment",
        material_textures ? ", textured material" : "",
        std::string(normal_map ? ", normal map" : "") +
            (normal_map_mixture > 1 ? fmt::format(" ({0}x{0} mixture)", normal_map_mixture) : "") +
            (curvature ? ", curvature" : ""));
}

AssembledShader shadow_vertex_shader() {
    return assemble_shader("glintlab/realtime/shaders/shadow.vert.glsl");
}

AssembledShader shadow_fragment_shader() {
    return assemble_shader("glintlab/realtime/shaders/depth_only.frag.glsl");
}

AssembledShader forward_vertex_shader() {
    return assemble_shader("glintlab/realtime/shaders/forward.vert.glsl");
}

AssembledShader forward_fragment_shader(const ProgramKey& key) {
    std::string text = fmt::format(
        "#define GLINTLAB_POINT_LIGHTS {}\n#define GLINTLAB_DIRECTIONAL_LIGHTS {}\n"
        "#define GLINTLAB_ENVIRONMENT {}\n#define GLINTLAB_ENV_SPECULAR_SAMPLES {}\n"
        "#define GLINTLAB_ENV_DIFFUSE_SAMPLES {}\n#define GLINTLAB_ENV_DEFENSIVE_SAMPLES {}\n"
        "#define GLINTLAB_ENV_SOURCE_SAMPLES {}\n",
        key.point_lights, key.directional_lights, key.environment ? 1 : 0,
        kEnvironmentSpecularSamples, kEnvironmentDiffuseSamples, kEnvironmentDefensiveSamples,
        kEnvironmentSourceSamples);
    if (key.material_textures || key.normal_map || key.curvature)
        text += "#define GLINTLAB_MATERIAL_TEXTURES 1\n";
    if (key.normal_map) text += "#define GLINTLAB_NORMAL_MAP 1\n";
    if (key.normal_map && key.normal_map_mixture > 1)
        text += fmt::format("#define GLINTLAB_NORMAL_MAP_MIXTURE {}\n", key.normal_map_mixture);
    if (key.curvature) text += "#define GLINTLAB_GLINT_CURVATURE 1\n";
    // The pass knows each pixel's view differentials (g_glint_view): glues
    // that filter over the half vector's sweep read them.
    text += "#define GLINTLAB_GLINT_VIEW_DIFFERENTIALS 1\n";
    text += glint_model_glsl(key.model, key.model_options);
    text += "#include \"glintlab/realtime/shaders/forward.frag.glsl\"\n";
    return assemble_shader(text, true);
}

AssembledShader background_vertex_shader() {
    return assemble_shader("glintlab/realtime/shaders/fullscreen.vert.glsl");
}
AssembledShader background_fragment_shader() {
    return assemble_shader("glintlab/realtime/shaders/background.frag.glsl");
}
AssembledShader tonemap_fragment_shader() {
    return assemble_shader("glintlab/realtime/shaders/tonemap.frag.glsl");
}

}  // namespace glintlab::gl
