#include "glintlab/scene/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <utility>

#include <fmt/format.h>

#include "glintlab/core/error.h"

namespace glintlab {
namespace {

constexpr const char* kTextureTransform = "KHR_texture_transform";
constexpr const char* kIor = "KHR_materials_ior";
constexpr const char* kEmissiveStrength = "KHR_materials_emissive_strength";

// `key` of `o` when it holds a value of the wanted kind, else null.
const nlohmann::json* member(const nlohmann::json& o, const char* key) {
    if (!o.is_object()) return nullptr;
    const auto it = o.find(key);
    return it == o.end() ? nullptr : &*it;
}
double number_or(const nlohmann::json& o, const char* key, double fallback) {
    const nlohmann::json* v = member(o, key);
    return v && v->is_number() ? v->get<double>() : fallback;
}
int integer_or(const nlohmann::json& o, const char* key, int fallback) {
    const nlohmann::json* v = member(o, key);
    return v && v->is_number_integer() ? v->get<int>() : fallback;
}
// An array of `n` numbers, or `fallback`.
std::vector<double> numbers_or(const nlohmann::json& o, const char* key, size_t n,
                               std::vector<double> fallback) {
    const nlohmann::json* v = member(o, key);
    if (!v || !v->is_array() || v->size() != n) return fallback;
    std::vector<double> out;
    for (const nlohmann::json& e : *v) {
        if (!e.is_number()) return fallback;
        out.push_back(e.get<double>());
    }
    return out;
}

const char* wrap_name(int gl_wrap) {
    switch (gl_wrap) {
        case 33071:
            return "clamp";  // CLAMP_TO_EDGE
        case 33648:
            return "mirror";  // MIRRORED_REPEAT
        default:
            return "repeat";  // REPEAT (10497), glTF's default
    }
}

class Translator {
  public:
    Translator(const nlohmann::json& gltf, const std::vector<std::string>& image_names,
               std::string file, GltfMaterial& out)
        : gltf_(gltf), image_names_(image_names), file_(std::move(file)), out_(out) {}

    // A textureInfo (baseColorTexture, normalTexture, ...) as a texture block
    // with its uv transform and wrap; null when it names no readable image
    // (said in out_.unread).
    nlohmann::json texture(const nlohmann::json& info, const char* what) {
        const int index = integer_or(info, "index", -1);
        const nlohmann::json* textures = member(gltf_, "textures");
        if (index < 0 || !textures || !textures->is_array() || size_t(index) >= textures->size())
            fail("{}: material \"{}\": {} names texture {}, out of range [0, {})", file_, out_.name,
                 what, index, textures && textures->is_array() ? textures->size() : 0);
        const nlohmann::json& texture = (*textures)[size_t(index)];
        const int source = integer_or(texture, "source", -1);
        if (source < 0 || size_t(source) >= image_names_.size()) {
            // KHR_texture_basisu, EXT_texture_webp, ...: images in the
            // texture's extensions only.
            out_.unread.push_back(fmt::format(
                "{} (texture {} has no PNG/JPEG source: its factor is used alone)", what, index));
            return nullptr;
        }
        nlohmann::json block = {{"texture", image_names_[size_t(source)]}};
        if (std::find(out_.images.begin(), out_.images.end(), source) == out_.images.end())
            out_.images.push_back(source);
        int tex_coord = integer_or(info, "texCoord", 0);
        if (const nlohmann::json* ext = member(info, "extensions"))
            if (const nlohmann::json* t = member(*ext, kTextureTransform)) {
                nlohmann::json uv;
                const std::vector<double> s = numbers_or(*t, "scale", 2, {1.0, 1.0});
                const std::vector<double> o = numbers_or(*t, "offset", 2, {0.0, 0.0});
                const double rotation = number_or(*t, "rotation", 0.0);
                if (s != std::vector<double>{1.0, 1.0}) uv["scale"] = s;
                if (o != std::vector<double>{0.0, 0.0}) uv["offset"] = o;
                if (rotation != 0.0)
                    uv["rotation_deg"] = std::fmod(rotation * 180.0 / std::numbers::pi, 360.0);
                if (!uv.empty()) block["uv_transform"] = uv;
                tex_coord = integer_or(*t, "texCoord", tex_coord);
            }
        use_uv_set(tex_coord, what);
        const int sampler = integer_or(texture, "sampler", -1);
        const nlohmann::json* samplers = member(gltf_, "samplers");
        const bool listed =
            sampler >= 0 && samplers && samplers->is_array() && size_t(sampler) < samplers->size();
        if (sampler >= 0 && !listed)
            out_.unread.push_back(
                fmt::format("{}: sampler {} is not in the file's samplers; read as glTF's default "
                            "(repeat, filtered)",
                            what, sampler));
        if (listed) {
            const nlohmann::json& smp = (*samplers)[size_t(sampler)];
            const int s = integer_or(smp, "wrapS", 10497), t = integer_or(smp, "wrapT", 10497);
            for (const auto& [axis, mode] : {std::pair{"wrapS", s}, std::pair{"wrapT", t}})
                if (mode != 10497 && mode != 33071 && mode != 33648)
                    out_.unread.push_back(fmt::format(
                        "{}: sampler {} {} {} is not a glTF wrap mode (10497, 33071, 33648); "
                        "read as repeat",
                        what, sampler, axis, mode));
            // Every input is filtered over the pixel footprint (mip-mapped,
            // anisotropic): a density map's footprint mean is the facet count
            // the models need, which a nearest or unmipmapped lookup is not.
            const int mag = integer_or(smp, "magFilter", 9729);
            const int min = integer_or(smp, "minFilter", 9987);
            if (mag == 9728 || min == 9728 || min == 9729)
                out_.unread.push_back(fmt::format(
                    "{}: sampler {} asks for {} filtering (magFilter {}, minFilter {}); glintlab "
                    "filters every texture over the pixel footprint (linear, mip-mapped)",
                    what, sampler, mag == 9728 || min == 9728 ? "nearest" : "unmipmapped", mag,
                    min));
            if (std::string_view(wrap_name(s)) != wrap_name(t))
                block["wrap"] = nlohmann::json::array({wrap_name(s), wrap_name(t)});
            else if (std::string_view(wrap_name(s)) != "repeat")
                block["wrap"] = wrap_name(s);
        }
        return block;
    }

  private:
    void use_uv_set(int set, const char* what) {
        if (set < 0 || set > 7)
            fail("{}: material \"{}\": {} reads TEXCOORD_{} (glintlab reads sets 0-7)", file_,
                 out_.name, what, set);
        if (uv_set_ >= 0 && uv_set_ != set)
            fail(
                "{}: material \"{}\" reads its textures through TEXCOORD_{} and TEXCOORD_{} ({}); "
                "a glintlab mesh carries one uv set: give every texture one texCoord",
                file_, out_.name, uv_set_, set, what);
        uv_set_ = set;
        out_.uv_set = set;
    }

    const nlohmann::json& gltf_;
    const std::vector<std::string>& image_names_;
    std::string file_;
    GltfMaterial& out_;
    int uv_set_ = -1;
};

}  // namespace

GltfMaterial translate_gltf_material(const nlohmann::json& gltf, int index,
                                     const std::vector<std::string>& image_names,
                                     const std::string& file) {
    GltfMaterial out;
    out.block = {{"type", "metallic_roughness"}};
    if (index < 0) {
        // glTF 2.0 §3.9.6: primitives without a material get a default one.
        out.name = "default";
        out.block["base_color"] = {1.0, 1.0, 1.0};
        out.block["metallic"] = 1.0;
        out.block["roughness"] = 1.0;
        return out;
    }
    const nlohmann::json* materials = member(gltf, "materials");
    if (!materials || !materials->is_array() || size_t(index) >= materials->size())
        fail("{}: material index {} out of range [0, {})", file, index,
             materials && materials->is_array() ? materials->size() : 0);
    const nlohmann::json& m = (*materials)[size_t(index)];
    const nlohmann::json* name = member(m, "name");
    out.name = name && name->is_string() && !name->get<std::string>().empty()
                   ? name->get<std::string>()
                   : fmt::format("material {}", index);
    Translator t(gltf, image_names, file, out);

    static const nlohmann::json kEmpty = nlohmann::json::object();
    const nlohmann::json* pbr_member = member(m, "pbrMetallicRoughness");
    const nlohmann::json& pbr = pbr_member ? *pbr_member : kEmpty;
    const std::vector<double> base = numbers_or(pbr, "baseColorFactor", 4, {1, 1, 1, 1});
    const double metallic = number_or(pbr, "metallicFactor", 1.0);
    const double roughness = number_or(pbr, "roughnessFactor", 1.0);
    out.metallic = metallic >= 0.5;

    nlohmann::json base_color = {base[0], base[1], base[2]};
    if (const nlohmann::json* info = member(pbr, "baseColorTexture")) {
        nlohmann::json block = t.texture(*info, "baseColorTexture");
        if (!block.is_null()) {
            if (base[0] != 1.0 || base[1] != 1.0 || base[2] != 1.0)
                block["scale"] = nlohmann::json{base[0], base[1], base[2]};
            base_color = block;
        }
    }
    out.block["base_color"] = base_color;

    nlohmann::json metallic_value = metallic, roughness_value = roughness * roughness;
    if (const nlohmann::json* info = member(pbr, "metallicRoughnessTexture")) {
        nlohmann::json block = t.texture(*info, "metallicRoughnessTexture");
        if (!block.is_null()) {
            // glTF: metalness in B, perceptual roughness in G, α = roughness².
            metallic_value = block;
            metallic_value["channel"] = "b";
            if (metallic != 1.0) metallic_value["scale"] = metallic;
            roughness_value = block;
            roughness_value["channel"] = "g";
            if (roughness != 1.0) roughness_value["scale"] = roughness;
            roughness_value["power"] = 2;
        }
    }
    out.block["metallic"] = metallic_value;
    out.block["roughness"] = roughness_value;

    if (const nlohmann::json* info = member(m, "normalTexture")) {
        nlohmann::json block = t.texture(*info, "normalTexture");
        if (!block.is_null()) {
            const double scale = number_or(*info, "scale", 1.0);
            if (scale != 1.0) block["scale"] = scale;
            out.block["normal_map"] = block;
        }
    }

    const nlohmann::json* ext = member(m, "extensions");
    if (ext && ext->is_object()) {
        for (const auto& [key, value] : ext->items()) {
            if (key == kIor) {
                const double ior = number_or(value, "ior", 1.5);
                if (ior > 1.0 && ior <= 4.0)
                    out.block["eta"] = ior;
                else
                    out.unread.push_back(fmt::format(
                        "{} ior {:g} (outside (1, 4]: the dielectric keeps IOR 1.5)", kIor, ior));
            } else if (key != kEmissiveStrength) {
                out.unread.push_back(key);
            }
        }
    }
    const std::vector<double> emissive = numbers_or(m, "emissiveFactor", 3, {0, 0, 0});
    if (emissive != std::vector<double>{0, 0, 0} || member(m, "emissiveTexture"))
        out.unread.push_back("emission (glintlab's meshes do not emit)");
    if (const nlohmann::json* mode = member(m, "alphaMode");
        mode && mode->is_string() && mode->get<std::string>() != "OPAQUE")
        out.unread.push_back(
            fmt::format("alphaMode {} (rendered opaque)", mode->get<std::string>()));
    return out;
}

nlohmann::json apply_material_override(const GltfMaterial& file_material,
                                       const nlohmann::json& override_block,
                                       std::vector<std::string>* notes) {
    const nlohmann::json& file = file_material.block;
    if (!override_block.is_object()) return override_block;  // the reader's error names it
    const nlohmann::json* type_member = member(override_block, "type");
    if (!type_member) {
        nlohmann::json merged = file;
        for (const auto& [key, value] : override_block.items()) merged[key] = value;
        return merged;
    }
    nlohmann::json out = override_block;
    const std::string type = type_member->is_string() ? type_member->get<std::string>() : "";
    auto inherit = [&](const char* from, const char* to) {
        if (file.contains(from) && !out.contains(to)) out[to] = file[from];
    };
    if (type == "metallic_roughness") {
        for (const auto& [key, value] : file.items())
            if (!out.contains(key)) out[key] = value;
        return out;
    }
    inherit("normal_map", "normal_map");
    if (type == "diffuse" || type == "plastic") inherit("base_color", "albedo");
    if (type == "diffuse") return out;
    if (type == "glint" && !out.contains("roughness") && file["roughness"].is_number()) {
        // glint roughness starts at 1e-3: a mirror-smooth file material is as smooth as allowed.
        out["roughness"] = std::max(file["roughness"].get<double>(), 1e-3);
    }
    inherit("roughness", "roughness");
    if (type != "glint") return out;
    const nlohmann::json& metallic = file["metallic"];
    if (metallic.is_object() ||
        (metallic.is_number() && metallic.get<double>() > 0.0 && metallic.get<double>() < 1.0))
        notes->push_back(fmt::format(
            "metallic {} is not carried into a glint material (no metal/dielectric mix): it "
            "takes the {} side",
            metallic.is_object() ? "map" : fmt::format("{:g}", metallic.get<double>()),
            file_material.metallic ? "metal" : "dielectric"));
    if (file_material.metallic) {
        inherit("base_color", "color");
        return out;
    }
    const nlohmann::json* fresnel = member(out, "fresnel");
    const bool dielectric_coat =
        !fresnel || (fresnel->is_object() && fresnel->value("type", "") == "dielectric");
    if (dielectric_coat && !out.contains("base_albedo")) {
        out["base_albedo"] = file["base_color"];
        if (!fresnel) out["fresnel"] = {{"type", "dielectric"}, {"eta", file.value("eta", 1.5)}};
    }
    return out;
}

}  // namespace glintlab
