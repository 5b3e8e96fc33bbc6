#include "glintlab/loader/scene_loader.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <glm/gtc/constants.hpp>

#include "glintlab/core/error.h"
#include "glintlab/core/image.h"
#include "glintlab/core/json_reader.h"
#include "glintlab/core/memory_limit.h"
#include "glintlab/core/regular_file.h"
#include "glintlab/glints/glint_reader.h"
#include "glintlab/glints/registry.h"
#include "glintlab/scene/environment_file.h"
#include "glintlab/scene/gltf_loader.h"
#include "glintlab/scene/mesh_tangents.h"
#include "glintlab/scene/normal_map_reader.h"
#include "glintlab/scene/obj_loader.h"
#include "glintlab/scene/shapes.h"
#include "glintlab/scene/shapes_heightfield.h"
#include "glintlab/scene/texture_reader.h"
#include "glintlab/scene/transform.h"
#include "glintlab/scene/uv_projection.h"

namespace glintlab {
namespace {

// Scene coordinates beyond this are certainly a mistake (and break fp32 traversal).
constexpr float kMaxCoord = 1e6f;

// A dielectric's relative index of refraction, (1, 4]: eta = 1 is no
// interface (and divides by zero in the Fresnel and refraction terms).
const NumberRange kEtaRange{1.0, 4.0, true, false, true};

const std::vector<std::string> kNdfNames = {"beckmann", "ggx"};

NdfType read_ndf(JsonObject& o, NdfType fallback) {
    o.ignore("ndf");  // known even when absent: an unknown key's error lists it
    if (!o.has("ndf")) return fallback;
    return o.string("ndf", "", kNdfNames) == "ggx" ? NdfType::GGX : NdfType::Beckmann;
}

// "roughness": α (slope roughness of Beckmann/GGX), one number (isotropic) or [αx, αy].
// `min` is the documented decimal (a value equal to it is accepted).
void read_roughness(JsonObject& o, double min, float* ax, float* ay) {
    const glm::vec2 a = o.vec2("roughness", glm::vec2(*ax, *ay), min, 1.0f);
    *ax = a.x;
    *ay = a.y;
}

// "roughness" where it may be a texture: a number, [αx, αy] (each a number
// or a texture form) or one texture form (isotropic). Textures hold α²
// (TextureParameter::Filtered::Square); values in [0, min) are clamped to
// `min` with a warning (an 8-bit map's 0).
void read_roughness_or_textures(JsonObject& o, double min, float* ax, float* ay,
                                std::shared_ptr<const TextureInput>* tx,
                                std::shared_ptr<const TextureInput>* ty, TextureFileCache& files) {
    TextureParameter p;
    p.min = min, p.max = 1.0, p.clamp_below = true;
    p.filtered = TextureParameter::Filtered::Square;
    if (is_texture_form(o, "roughness")) {
        *tx = *ty = read_texture_input(o, "roughness", p, files);
        return;
    }
    const nlohmann::json* v = o.has("roughness") ? o.raw("roughness") : nullptr;
    if (v && v->is_array() && v->size() == 2 && ((*v)[0].is_object() || (*v)[1].is_object())) {
        float* a[2] = {ax, ay};
        std::shared_ptr<const TextureInput>* t[2] = {tx, ty};
        for (int i = 0; i < 2; ++i) {
            const std::string where = fmt::format("{}/roughness/{}", o.path(), i);
            const nlohmann::json& e = (*v)[size_t(i)];
            if (e.is_object()) {
                JsonObject block(e, where, o.file());
                *t[i] = read_texture_block(block, p, files);
            } else if (e.is_number() && e.get<double>() >= min && e.get<double>() <= 1.0) {
                *a[i] = e.get<float>();
            } else {
                fail("{}: {}: expected a number in [{:g}, 1] or a texture object, got {}", o.file(),
                     where, min, e.dump());
            }
        }
        return;
    }
    read_roughness(o, min, ax, ay);
}

// A colour parameter that may be a texture form.
glm::vec3 read_colour_or_texture(JsonObject& o, std::string_view key, glm::vec3 fallback,
                                 std::shared_ptr<const TextureInput>* texture,
                                 TextureFileCache& files) {
    if (is_texture_form(o, key)) {
        TextureParameter p;
        p.colour = true;
        *texture = read_texture_input(o, key, p, files);
        return fallback;
    }
    return o.color(key, fallback, 0.0f, 1.0f);
}

struct MetalPreset {
    const char* name;
    glm::vec3 eta, k;
};
// RGB complex indices of refraction of common metals at ~650/550/450 nm.
const MetalPreset kMetals[] = {
    {"gold", {0.143f, 0.374f, 1.442f}, {3.983f, 2.385f, 1.603f}},
    {"silver", {0.155f, 0.116f, 0.138f}, {4.828f, 3.122f, 2.147f}},
    {"copper", {0.200f, 0.924f, 1.102f}, {3.912f, 2.452f, 2.142f}},
    {"aluminium", {1.657f, 0.880f, 0.521f}, {9.224f, 6.270f, 4.837f}},
};

std::vector<std::string> metal_names() {
    std::vector<std::string> n;
    for (const MetalPreset& m : kMetals) n.emplace_back(m.name);
    return n;
}

void read_conductor_ior(JsonObject& o, glm::vec3* eta, glm::vec3* k) {
    if (o.has("metal")) {
        if (o.has("eta") || o.has("k"))
            o.error("metal", "give either \"metal\" or \"eta\"/\"k\", not both");
        const std::string name = o.string("metal", "", metal_names());
        for (const MetalPreset& m : kMetals)
            if (name == m.name) *eta = m.eta, *k = m.k;
        return;
    }
    *eta = o.color("eta", *eta, 0.01f, 100.0f);
    *k = o.color("k", *k, 0.0f, 100.0f);
}

FresnelDesc read_fresnel(JsonObject& parent) {
    FresnelDesc f;
    auto block = parent.object("fresnel");
    if (!block) return f;
    JsonObject& o = *block;
    const std::string type =
        o.required_string("type", {"none", "schlick", "conductor", "dielectric"});
    if (type == "schlick") {
        f.mode = FresnelDesc::Mode::Schlick;
        f.f0 = o.color("f0", glm::vec3(0.04f), 0.0f, 1.0f);
    } else if (type == "conductor") {
        f.mode = FresnelDesc::Mode::Conductor;
        f.eta = glm::vec3(0.2f), f.k = glm::vec3(3.9f);
        read_conductor_ior(o, &f.eta, &f.k);
    } else if (type == "dielectric") {
        f.mode = FresnelDesc::Mode::Dielectric;
        f.eta = glm::vec3(static_cast<float>(o.number("eta", 1.5, kEtaRange)));
    }
    o.finish();
    return f;
}

GlintDesc read_glint(JsonObject& o, TextureFileCache& files) {
    GlintDesc g;
    GlintTextures t;
    g.model_id = read_glint_model_name(o);
    g.ndf = read_ndf(o, NdfType::Beckmann);
    read_roughness_or_textures(o, 1e-3, &g.alpha_x, &g.alpha_y, &t.alpha_x_sq, &t.alpha_y_sq,
                               files);
    if (is_texture_form(o, "log_density")) {
        TextureParameter p;
        p.min = -20.0, p.max = 60.0;
        p.filtered = TextureParameter::Filtered::Exp;
        t.density = read_texture_input(o, "log_density", p, files);
    } else {
        g.log_density = static_cast<float>(o.number("log_density", 20.0, -20.0, 60.0));
    }
    g.fresnel = read_fresnel(o);
    g.color = read_colour_or_texture(o, "color", glm::vec3(1.0f), &t.color, files);
    g.base_albedo =
        read_colour_or_texture(o, "base_albedo", glm::vec3(0.0f), &t.base_albedo, files);
    if ((g.has_base() || t.base_albedo) && g.fresnel.mode != FresnelDesc::Mode::Dielectric)
        o.error("base_albedo",
                "a diffuse base lies under a dielectric coating: it needs \"fresnel\": "
                "{\"type\": \"dielectric\", \"eta\": ...} (the coating's interface)");
    g.seed = static_cast<uint32_t>(o.number("seed", 0.0, 0.0, 4294967295.0));
    g.curvature = o.string("curvature", "none", {"none", "footprint"}) == "footprint";
    // Before the model's own checks, which read the numbers a texture replaces.
    const GlintModelDescriptor& model = glint_model(g.model_id);
    auto refuse = [&](const char* key) {
        o.error(key, fmt::format("model {} cannot take \"{}\" from a texture: {} (give a number)",
                                 model.name, key, model.untextured_reason));
    };
    if (t.density && !model.textured_density) refuse("log_density");
    if ((t.alpha_x_sq || t.alpha_y_sq) && !model.textured_roughness) refuse("roughness");
    // One footprint lookup for density and roughness where their maps line up.
    std::shared_ptr<const TextureInput>* scalars[] = {&t.density, &t.alpha_x_sq, &t.alpha_y_sq};
    pack_scalar_inputs(scalars);
    if (t.density || t.alpha_x_sq || t.alpha_y_sq || t.color || t.base_albedo)
        g.textures = std::make_shared<const GlintTextures>(std::move(t));
    read_glint_model_blocks(o, g);  // the model's block, through its descriptor
    return g;
}

MaterialDesc read_material(JsonObject& o, TextureFileCache& files) {
    MaterialTextures t;
    MaterialDesc m;
    m.name = o.required_string("name");
    const std::string type = o.required_string(
        "type", {"diffuse", "conductor", "dielectric", "plastic", "metallic_roughness", "glint"});
    if (type == "diffuse") {
        m.type = MaterialDesc::Type::Diffuse;
        m.albedo = read_colour_or_texture(o, "albedo", m.albedo, &t.albedo, files);
    } else if (type == "conductor") {
        m.type = MaterialDesc::Type::Conductor;
        m.ndf = read_ndf(o, NdfType::GGX);
        read_roughness_or_textures(o, 0.0, &m.alpha_x, &m.alpha_y, &t.alpha_x_sq, &t.alpha_y_sq,
                                   files);
        m.eta = glm::vec3(0.2f), m.k = glm::vec3(3.9f);
        read_conductor_ior(o, &m.eta, &m.k);
    } else if (type == "dielectric") {
        m.type = MaterialDesc::Type::Dielectric;
        m.ndf = read_ndf(o, NdfType::GGX);
        read_roughness_or_textures(o, 0.0, &m.alpha_x, &m.alpha_y, &t.alpha_x_sq, &t.alpha_y_sq,
                                   files);
        m.eta = glm::vec3(static_cast<float>(o.number("eta", 1.5, kEtaRange)));
    } else if (type == "plastic") {
        m.type = MaterialDesc::Type::Plastic;
        m.albedo = read_colour_or_texture(o, "albedo", m.albedo, &t.albedo, files);
        m.ndf = read_ndf(o, NdfType::GGX);
        read_roughness_or_textures(o, 0.0, &m.alpha_x, &m.alpha_y, &t.alpha_x_sq, &t.alpha_y_sq,
                                   files);
        m.eta = glm::vec3(static_cast<float>(o.number("eta", 1.5, kEtaRange)));
    } else if (type == "metallic_roughness") {
        m.type = MaterialDesc::Type::MetallicRoughness;
        m.albedo = read_colour_or_texture(o, "base_color", glm::vec3(1.0f), &t.albedo, files);
        if (is_texture_form(o, "metallic")) {
            TextureParameter p;  // min 0, max 1, filtered as itself (the lobes mix linearly)
            t.metallic = read_texture_input(o, "metallic", p, files);
        } else {
            m.metallic = static_cast<float>(o.number("metallic", 1.0, 0.0, 1.0));
        }
        m.ndf = read_ndf(o, NdfType::GGX);
        m.alpha_x = m.alpha_y = 1.0f;  // glTF's roughness factor 1
        read_roughness_or_textures(o, 0.0, &m.alpha_x, &m.alpha_y, &t.alpha_x_sq, &t.alpha_y_sq,
                                   files);
        m.eta = glm::vec3(static_cast<float>(o.number("eta", 1.5, kEtaRange)));
    } else {
        m.type = MaterialDesc::Type::Glint;
        m.glint = read_glint(o, files);
    }
    if (o.has("normal_map")) m.normal_map = read_normal_map(o, "normal_map", files);
    o.finish();
    std::shared_ptr<const TextureInput>* scalars[] = {&t.metallic, &t.alpha_x_sq, &t.alpha_y_sq};
    pack_scalar_inputs(scalars);
    if (t.albedo || t.alpha_x_sq || t.alpha_y_sq || t.metallic)
        m.textures = std::make_shared<const MaterialTextures>(std::move(t));
    return m;
}

Transform read_transform(JsonObject& parent) {
    auto block = parent.object("transform");
    if (!block) return Transform();
    JsonObject& o = *block;
    // Applied in the order scale, rotate, translate (the usual TRS).
    Transform t;
    if (o.has("scale")) {
        const nlohmann::json* s = o.raw("scale");
        glm::vec3 f = s->is_number()
                          ? glm::vec3(static_cast<float>(o.number("scale", 1.0, 1e-6, 1e6)))
                          : o.vec3("scale", glm::vec3(1.0f), -1e6f, 1e6f);
        for (int i = 0; i < 3; ++i)
            if (std::abs(f[i]) < 1e-6f) o.error("scale", "scale factors must be non-zero");
        t = Transform::scale(f) * t;
    }
    if (auto r = o.object("rotate")) {
        const glm::vec3 axis = r->required_vec3("axis", -1.0f, 1.0f);
        if (glm::length(axis) < 1e-6f) r->error("axis", "rotation axis must be non-zero");
        const float deg = static_cast<float>(r->required_number("deg", -360.0, 360.0));
        r->finish();
        t = Transform::rotate(deg, axis) * t;
    }
    t = Transform::translate(o.vec3("translate", glm::vec3(0.0f), -kMaxCoord, kMaxCoord)) * t;
    o.finish();
    return t;
}

// The generated grid meshes (torus, head, heightfield) of a × b cells hold
// (a+1)(b+1) vertices of 32 bytes (position, normal, uv; `extra` more per
// vertex while building, e.g. the heightfield's heights) and 2ab triangles
// of 12 bytes. Checked against the memory limit (core/memory_limit.h) before
// they are built: an 8192² torus needs about 3.7 GiB.
void require_grid_memory(const JsonObject& o, const char* what, int a, int b, int extra = 0) {
    const uint64_t vertices = uint64_t(a + 1) * uint64_t(b + 1);
    const uint64_t triangles = 2 * uint64_t(a) * uint64_t(b);
    require_memory({{fmt::format("{} vertices", vertices), vertices * uint64_t(32 + extra)},
                    {fmt::format("{} triangles", triangles), triangles * 12}},
                   fmt::format("{}: {} ({} {}x{})", o.file(), o.path(), what, a, b));
}

struct LoadContext {
    std::map<std::string, int> material_index;
    Scene* scene;
    TextureFileCache* texture_files;
};

TriangleMesh read_heightfield(JsonObject& o) {
    HeightfieldSettings s;
    s.size = o.vec2("size", s.size, 1e-4f, kMaxCoord);
    s.resolution = o.integer("resolution", s.resolution, 1, 4096);
    s.amplitude = static_cast<float>(o.number("amplitude", s.amplitude, -1e3, 1e3));
    s.frequency = static_cast<float>(o.number("frequency", s.frequency, 1e-3, 1e4));
    s.octaves = o.integer("octaves", s.octaves, 1, 16);
    s.seed = static_cast<uint32_t>(o.number("seed", 1.0, 0.0, 4294967295.0));
    s.uv_scale = o.vec2("uv_scale", s.uv_scale, 1e-6f, 1e6f);
    require_grid_memory(o, "heightfield of resolution", s.resolution, s.resolution, 4);
    if (o.has("file")) {
        // Height image: luminance in [0, 1] mapped to [-1, 1], bilinear.
        const std::filesystem::path file = o.file_path("file");
        auto image = std::make_shared<Image>(read_image(file));
        // Outside [0, 1] the mapping leaves the documented [-1, 1] × amplitude
        // (an HDR image of 1e30 made the geometry vanish): an error, naming
        // the first pixel outside.
        for (int y = 0; y < image->height; ++y)
            for (int x = 0; x < image->width; ++x)
                if (const float l = luminance(image->at(x, y)); !(l >= 0.0f && l <= 1.0f))
                    o.error("file", fmt::format("{}: height image luminance {:g} at pixel ({}, {}) "
                                                "out of range: heights must lie in [0, 1]",
                                                file.string(), l, x, y));
        return make_heightfield(s, [image](glm::vec2 uv) {
            const int w = image->width, h = image->height;
            const float fx = std::clamp(uv.x, 0.0f, 1.0f) * static_cast<float>(w - 1);
            const float fy = std::clamp(uv.y, 0.0f, 1.0f) * static_cast<float>(h - 1);
            const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
            const int x1 = std::min(x0 + 1, w - 1), y1 = std::min(y0 + 1, h - 1);
            const float tx = fx - static_cast<float>(x0), ty = fy - static_cast<float>(y0);
            const float a =
                glm::mix(luminance(image->at(x0, y0)), luminance(image->at(x1, y0)), tx);
            const float b =
                glm::mix(luminance(image->at(x0, y1)), luminance(image->at(x1, y1)), tx);
            return 2.0f * glm::mix(a, b, ty) - 1.0f;
        });
    }
    return make_heightfield(s);
}

// "uv": a generated parameterization (uv_projection.h), in the shape's
// object space (before "transform"); it replaces the mesh's own uvs.
UvProjection read_uv_projection(JsonObject& o) {
    UvProjection p;
    const std::string type =
        o.required_string("projection", {"box", "planar", "cylindrical", "spherical"});
    p.type = type == "box"           ? UvProjection::Type::Box
             : type == "planar"      ? UvProjection::Type::Planar
             : type == "cylindrical" ? UvProjection::Type::Cylindrical
                                     : UvProjection::Type::Spherical;
    p.scale = static_cast<float>(o.number("scale", 1.0, 1e-6, 1e6));
    if (p.type != UvProjection::Type::Box) {
        const std::string axis = o.string("axis", "y", {"x", "y", "z"});
        p.axis = axis[0] - 'x';
    }
    p.center = o.vec3("center", glm::vec3(0.0f), -kMaxCoord, kMaxCoord);
    if (p.type == UvProjection::Type::Cylindrical || p.type == UvProjection::Type::Spherical)
        p.radius = static_cast<float>(o.number("radius", 0.0, 0.0, kMaxCoord));
    o.finish();
    return p;
}

// A mesh in world space with the checks and tangents its material needs.
// `uv_source`: where the uvs were to come from (a glTF file's TEXCOORD_n),
// named in the error when the mesh lacks them; empty for other sources.
void finish_mesh(JsonObject& o, LoadContext& ctx, TriangleMesh& mesh, int material,
                 const Transform& transform, const std::optional<UvProjection>& uv,
                 const std::string& where, const std::string& uv_source = "") {
    if (uv) {
        project_uvs(mesh, *uv);
        mesh.tangents.clear();  // a file's tangents follow its own uvs
    }
    transform_mesh(mesh, transform);
    mesh.validate(where);
    const MaterialDesc& m = ctx.scene->materials[static_cast<size_t>(material)];
    if (m.needs_uv() && !mesh.has_uvs())
        o.error(o.has("material") ? "material" : "file",
                fmt::format("material \"{}\" {} and needs a uv parameterization, but this mesh "
                            "has no uvs{} (give it one with \"uv\": {{\"projection\": ...}})",
                            m.name,
                            m.type == MaterialDesc::Type::Glint
                                ? "is a glint material"
                                : fmt::format("reads {} from textures", textured_keys(m)),
                            uv_source.empty() ? std::string() : fmt::format(" ({})", uv_source)));
    // The file's tangents (glTF TANGENT) when it has them; else MikkTSpace's
    // convention, generated.
    if (m.normal_map && mesh.tangents.empty()) {
        const size_t fixed = generate_vertex_tangents(mesh);
        if (fixed > 0)
            fmt::print(stderr,
                       "warning: {}: {} vertices have degenerate uvs (no direction of u): "
                       "their normal map's tangent is an arbitrary one\n",
                       where, fixed);
    }
}

// A glTF shape without "material": one shape per material its primitives
// use, each shaded by the file's material (docs/SCENE_FORMAT.md, "glTF
// materials") or by the shape's "material_overrides" entry for its name.
void read_gltf_shape_with_file_materials(JsonObject& o, LoadContext& ctx, const Shape& base,
                                         const Transform& transform,
                                         const std::optional<UvProjection>& uv) {
    const std::filesystem::path path = o.file_path("file");
    GltfScene gltf = load_gltf_scene(path);
    for (auto& [name, image] : gltf.images) ctx.texture_files->emplace(name, image);
    std::map<std::string, const nlohmann::json*> overrides;
    const nlohmann::json* raw_overrides =
        o.has("material_overrides") ? o.raw("material_overrides") : nullptr;
    if (raw_overrides && !raw_overrides->is_object())
        o.error("material_overrides",
                "expected an object {\"FILE MATERIAL NAME\": {...a material...}}");
    std::optional<JsonObject> override_block;
    if (raw_overrides) {
        override_block.emplace(*raw_overrides, o.path() + "/material_overrides", o.file());
        for (const auto& [name, value] : raw_overrides->items()) {
            bool found = false;
            for (const GltfMaterial& m : gltf.materials) found = found || m.name == name;
            if (!found) {
                std::string names;
                for (const GltfMaterial& m : gltf.materials)
                    names += fmt::format("{}\"{}\"", names.empty() ? "" : ", ", m.name);
                override_block->error(
                    name, fmt::format("{} has no material named \"{}\" (its materials: {})",
                                      path.string(), name, names.empty() ? "none" : names));
            }
            override_block->ignore(name);
            overrides[name] = &value;
        }
        override_block->finish();
    }
    for (GltfScene::Part& part : gltf.parts) {
        const GltfMaterial& file_material = part.material >= 0
                                                ? gltf.materials[static_cast<size_t>(part.material)]
                                                : gltf.default_material;
        std::vector<std::string> notes = file_material.unread;
        nlohmann::json block = file_material.block;
        std::string path_in_json =
            fmt::format("{} material \"{}\"", path.string(), file_material.name);
        std::string json_file = path.string();
        if (const auto it = overrides.find(file_material.name); it != overrides.end()) {
            block = apply_material_override(file_material, *it->second, &notes);
            path_in_json = fmt::format("{}/material_overrides/{}", o.path(), file_material.name);
            json_file = o.file();
        }
        if (!block.is_object()) fail("{}: {}: expected a material object", json_file, path_in_json);
        block["name"] = fmt::format("{}:{}", base.name, file_material.name);
        if (!notes.empty())
            fmt::print(stderr, "warning: {}: material \"{}\": not read: {}\n", path.string(),
                       file_material.name, fmt::join(notes, "; "));
        JsonObject material_object(block, path_in_json, json_file);
        ctx.scene->materials.push_back(read_material(material_object, *ctx.texture_files));
        Shape shape = base;
        shape.name = ctx.scene->materials.back().name;
        shape.material = static_cast<int>(ctx.scene->materials.size()) - 1;
        const std::string where = fmt::format("{}: {} ({})", o.file(), o.path(), shape.name);
        finish_mesh(o, ctx, part.mesh, shape.material, transform, uv, where,
                    fmt::format("{} has no TEXCOORD_{}, the set its material reads", path.string(),
                                file_material.uv_set));
        shape.geometry = std::move(part.mesh);
        ctx.scene->shapes.push_back(std::move(shape));
    }
}

void read_shape(JsonObject& o, LoadContext& ctx) {
    Shape shape;
    const std::string type = o.required_string(
        "type", {"quad", "sphere", "torus", "head", "heightfield", "obj", "gltf"});
    shape.name = o.string("name", fmt::format("{}", o.path()));
    const Transform transform = read_transform(o);
    if (type == "gltf" && !o.has("material")) {
        std::optional<UvProjection> uv;
        if (auto block = o.object("uv")) uv = read_uv_projection(*block);
        read_gltf_shape_with_file_materials(o, ctx, shape, transform, uv);
        o.finish();
        return;
    }
    if (o.has("material_overrides"))
        o.error("material_overrides",
                type == "gltf" ? "overrides change a glTF file's own materials; this shape's "
                                 "\"material\" replaces them all (leave \"material\" out)"
                               : "only glTF shapes have materials of their own to override");
    const std::string material = o.required_string("material");
    const auto it = ctx.material_index.find(material);
    if (it == ctx.material_index.end())
        o.error("material",
                fmt::format("unknown material \"{}\" (define it under /materials)", material));
    shape.material = it->second;
    const std::string where = fmt::format("{}: {}", o.file(), o.path());

    if (type == "sphere") {
        SphereGeometry s;
        const glm::vec3 center = o.vec3("center", glm::vec3(0.0f), -kMaxCoord, kMaxCoord);
        const float radius = static_cast<float>(o.number("radius", 1.0, 1e-6, kMaxCoord));
        // Spheres stay analytic: the transform must be a similarity
        // (rotation, uniform scale, translation).
        const glm::mat3 m(transform.m);
        const float sx = glm::length(m[0]), sy = glm::length(m[1]), sz = glm::length(m[2]);
        const float tol = 1e-4f * sx;
        if (std::abs(sx - sy) > tol || std::abs(sx - sz) > tol ||
            std::abs(glm::dot(m[0], m[1])) > tol * sx ||
            std::abs(glm::dot(m[0], m[2])) > tol * sx ||
            std::abs(glm::dot(m[1], m[2])) > tol * sx || glm::determinant(m) <= 0.0f)
            o.error("transform",
                    "a sphere's transform must be a rotation, a uniform positive "
                    "scale and a translation (use a mesh for ellipsoids)");
        s.center = transform.apply_point(center);
        s.radius = radius * sx;
        s.rotation = m / sx;
        shape.geometry = s;
        if (o.has("uv"))
            o.error("uv",
                    "spheres are analytic with their own uvs (u = φ/2π, v = θ/π); a uv "
                    "projection applies to mesh shapes");
    } else {
        TriangleMesh mesh;
        if (type == "quad") {
            mesh = make_quad(o.vec2("size", glm::vec2(2.0f), 1e-6f, kMaxCoord),
                             o.vec2("uv_scale", glm::vec2(1.0f), 1e-6f, 1e6f));
        } else if (type == "torus") {
            const float major = static_cast<float>(o.number("major_radius", 1.0, 1e-6, kMaxCoord));
            const float minor = static_cast<float>(o.number("minor_radius", 0.3, 1e-6, kMaxCoord));
            if (minor >= major)
                o.error("minor_radius", fmt::format("must be < major_radius = {}", major));
            const int seg_major = o.integer("segments_major", 256, 3, 8192);
            const int seg_minor = o.integer("segments_minor", 128, 3, 8192);
            require_grid_memory(o, "torus of segments", seg_major, seg_minor);
            mesh = make_torus(major, minor, seg_major, seg_minor,
                              o.vec2("uv_scale", glm::vec2(1.0f), 1e-6f, 1e6f));
        } else if (type == "head") {
            const int segments = o.integer("segments_phi", 256, 3, 8192);
            const int rings = o.integer("rings_theta", 128, 2, 8192);
            require_grid_memory(o, "head of segments x rings", segments, rings);
            mesh = make_head(segments, rings, o.vec2("uv_scale", glm::vec2(1.0f), 1e-6f, 1e6f));
        } else if (type == "heightfield") {
            mesh = read_heightfield(o);
        } else if (type == "obj") {
            mesh = load_obj(o.file_path("file"));
        } else {
            const std::filesystem::path file = o.file_path("file");
            size_t file_materials = 0;
            mesh = load_gltf(file, &file_materials);
            // Said once per shape: an older scene's "material" hides the
            // file's own (textured) materials.
            if (file_materials > 0)
                fmt::print(stderr,
                           "note: {}: the shape's material \"{}\" replaces the file's {} "
                           "material{} (leave \"material\" out to render them: "
                           "docs/SCENE_FORMAT.md, \"glTF materials\")\n",
                           file.string(), material, file_materials, file_materials == 1 ? "" : "s");
        }
        std::optional<UvProjection> uv;
        if (auto block = o.object("uv")) uv = read_uv_projection(*block);
        finish_mesh(o, ctx, mesh, shape.material, transform, uv, where);
        shape.geometry = std::move(mesh);
    }
    o.finish();
    ctx.scene->shapes.push_back(std::move(shape));
}

void read_light(JsonObject& o, Scene& scene) {
    const std::string type =
        o.required_string("type", {"point", "directional", "sphere", "environment"});
    if (type == "point") {
        PointLight l;
        l.position = o.required_vec3("position", -kMaxCoord, kMaxCoord);
        l.intensity = o.color("intensity", l.intensity, 0.0f, 1e9f);
        scene.lights.emplace_back(l);
    } else if (type == "directional") {
        DirectionalLight l;
        const glm::vec3 d = o.required_vec3("direction", -kMaxCoord, kMaxCoord);
        if (glm::length(d) < 1e-6f) o.error("direction", "direction must be non-zero");
        l.direction = glm::normalize(d);
        l.irradiance = o.color("irradiance", l.irradiance, 0.0f, 1e9f);
        l.solid_angle = static_cast<float>(o.number("solid_angle_sr", 0.0, 0.0, 1.0));
        // Below 1e-12 sr the cone's radiance E / Ω (up to 1e9 / 1e-12) and its
        // products with sharp BSDFs would leave single precision.
        if (l.solid_angle > 0.0f && l.solid_angle < 1e-12f)
            o.error("solid_angle_sr",
                    fmt::format("value {:g} out of range: allowed 0 (a delta light) or [1e-12, 1]",
                                l.solid_angle));
        if (l.solid_angle > 0.0f) {
            l.one_minus_cos_max = l.solid_angle / (2.0f * glm::pi<float>());
            l.cos_max = 1.0f - l.one_minus_cos_max;
            // sin² = (1 − cos)(1 + cos), exact for the smallest cones.
            const float sin2 = l.one_minus_cos_max * (2.0f - l.one_minus_cos_max);
            // Uniform radiance over the cone giving irradiance E at normal
            // incidence: E = L·π sin²θmax.
            l.radiance = l.irradiance / (glm::pi<float>() * sin2);
        }
        scene.lights.emplace_back(l);
    } else if (type == "sphere") {
        SphereLight l;
        l.center = o.required_vec3("center", -kMaxCoord, kMaxCoord);
        l.radius = static_cast<float>(o.required_number("radius", 1e-6, kMaxCoord));
        l.radiance = o.color("radiance", l.radiance, 0.0f, 1e9f);
        Shape shape;
        shape.name = fmt::format("{}", o.path());
        shape.geometry = SphereGeometry{l.center, l.radius, glm::mat3(1.0f)};
        shape.area_light = static_cast<int>(scene.lights.size());
        scene.shapes.push_back(std::move(shape));
        scene.lights.emplace_back(l);
    } else {
        if (scene.environment >= 0) o.error("type", "only one environment light is allowed");
        EnvironmentLight l;
        const float scale = static_cast<float>(o.number("scale", 1.0, 0.0, 1e6));
        const float rotation = static_cast<float>(o.number("rotation_deg", 0.0, -360.0, 360.0));
        if (o.has("file") == o.has("radiance"))
            o.error("file",
                    "an environment light needs exactly one of \"file\" (lat-long .exr/.hdr) or "
                    "\"radiance\"");
        if (o.has("file")) {
            l.file = o.file_path("file");
            Image image = read_environment_image(l.file, scale);
            l.map = std::make_shared<EnvironmentMap>(std::move(image), scale, rotation);
        } else {
            l.map = std::make_shared<EnvironmentMap>(
                EnvironmentMap::constant(scale * o.color("radiance", glm::vec3(1.0f), 0.0f, 1e9f)));
        }
        scene.environment = static_cast<int>(scene.lights.size());
        scene.lights.emplace_back(l);
    }
    o.finish();
}

Camera read_camera(JsonObject& o) {
    Camera c;
    const std::string type = o.string("type", "perspective", {"perspective", "orthographic"});
    c.type = type == "perspective" ? Camera::Type::Perspective : Camera::Type::Orthographic;
    c.eye = o.vec3("eye", c.eye, -kMaxCoord, kMaxCoord);
    c.target = o.vec3("target", c.target, -kMaxCoord, kMaxCoord);
    c.up = o.vec3("up", c.up, -kMaxCoord, kMaxCoord);
    if (glm::length(c.target - c.eye) < 1e-6f) o.error("target", "target must differ from eye");
    if (glm::length(glm::cross(glm::normalize(c.target - c.eye), c.up)) < 1e-4f)
        o.error("up", "up must not be parallel to the viewing direction");
    if (c.type == Camera::Type::Perspective)
        c.fov_deg = static_cast<float>(o.number("fov_deg", 40.0, 0.01, 179.0));
    else
        c.ortho_height = static_cast<float>(o.number("height", 2.0, 1e-6, kMaxCoord));
    o.finish();
    return c;
}

GlintLightType glint_light_type(const Light& l) {
    if (std::holds_alternative<PointLight>(l)) return GlintLightType::Point;
    if (std::holds_alternative<DirectionalLight>(l)) return GlintLightType::Directional;
    if (std::holds_alternative<SphereLight>(l)) return GlintLightType::Sphere;
    return GlintLightType::Environment;
}

// Each glint material's model must declare every light type of the scene
// (lights[i] is /lights/i: every light entry adds exactly one light).
void check_model_lights(const Scene& scene) {
    for (size_t mi = 0; mi < scene.materials.size(); ++mi) {
        const MaterialDesc& m = scene.materials[mi];
        if (m.type != MaterialDesc::Type::Glint) continue;
        for (size_t li = 0; li < scene.lights.size(); ++li) {
            const GlintLightType type = glint_light_type(scene.lights[li]);
            if (glint_model_shades(m.glint.model_id, type)) continue;
            fail(
                "{}: /lights/{} (type \"{}\"): glint model \"{}\" of material \"{}\" "
                "(/materials/{}) cannot shade {} lights; models that can: {}",
                scene.file.string(), li, glint_light_type_name(type),
                glint_model_name(m.glint.model_id), m.name, mi, glint_light_type_name(type),
                glint_models_shading_names(type));
        }
    }
}

}  // namespace

Scene parse_scene(const nlohmann::json& document, const std::filesystem::path& file) {
    return parse_scene(document, file, {});
}

Scene parse_scene(const nlohmann::json& document, const std::filesystem::path& file,
                  TextureFileCache arrays) {
    Scene scene;
    scene.file = file;
    JsonObject root(document, "", file.string());

    if (auto film = root.object("film")) {
        scene.camera.width = film->integer("width", 512, 1, 16384);
        scene.camera.height = film->integer("height", 512, 1, 16384);
        scene.film.exposure = static_cast<float>(film->number("exposure", 0.0, -20.0, 20.0));
        if (auto bloom = film->object("bloom")) {
            scene.film.bloom.strength =
                static_cast<float>(bloom->number("strength", 0.1, 0.0, 1.0));
            scene.film.bloom.radius_px =
                static_cast<float>(bloom->number("radius_px", 8.0, 0.5, 1024.0));
            scene.film.bloom.threshold =
                static_cast<float>(bloom->number("threshold", 1.0, 0.0, 1e9));
            scene.film.bloom_exr = bloom->boolean("apply_to_exr", false);
            bloom->finish();
        }
        film->finish();
    }
    {
        const int w = scene.camera.width, h = scene.camera.height;
        auto cam = root.object("camera");
        if (!cam) root.error("camera", "missing required object");
        scene.camera = read_camera(*cam);
        scene.camera.width = w, scene.camera.height = h;
    }
    if (auto render = root.object("render")) {
        const std::string integrator = render->string("integrator", "path", {"path", "direct"});
        scene.render.integrator = integrator == "path" ? RenderSettings::Integrator::Path
                                                       : RenderSettings::Integrator::Direct;
        scene.render.spp = render->integer("spp", scene.render.spp, 1, 1 << 20);
        scene.render.max_depth = render->integer("max_depth", scene.render.max_depth, 1, 128);
        scene.render.rr_depth = render->integer("rr_depth", scene.render.rr_depth, 1, 128);
        scene.render.seed = static_cast<uint64_t>(render->number("seed", 0.0, 0.0, 4294967295.0));
        render->finish();
    }
    TextureFileCache texture_files = std::move(arrays);
    LoadContext ctx{{}, &scene, &texture_files};
    for (JsonObject& m : root.object_array("materials")) {
        MaterialDesc desc = read_material(m, texture_files);
        if (ctx.material_index.contains(desc.name))
            m.error("name", fmt::format("duplicate material name \"{}\"", desc.name));
        ctx.material_index[desc.name] = static_cast<int>(scene.materials.size());
        scene.materials.push_back(std::move(desc));
    }
    for (JsonObject& s : root.object_array("shapes")) read_shape(s, ctx);
    for (JsonObject& l : root.object_array("lights")) read_light(l, scene);
    root.ignore("comment");  // free text, for humans
    root.finish();
    if (scene.shapes.empty() && scene.lights.empty())
        fail("{}: the scene has neither shapes nor lights", file.string());
    check_model_lights(scene);
    return scene;
}

Scene load_scene(const std::filesystem::path& file) {
    if (const std::string problem = regular_file_problem(file); !problem.empty())
        fail("{}: cannot read the scene file: it {}", file.string(), problem);
    std::ifstream in(file);
    if (!in) fail("{}: cannot open scene file", file.string());
    const nlohmann::json document = parse_json(in, file.string());
    return parse_scene(document, file);
}

}  // namespace glintlab
