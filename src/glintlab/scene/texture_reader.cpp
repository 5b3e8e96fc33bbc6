#include "glintlab/scene/texture_reader.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "glintlab/core/error.h"
#include "glintlab/core/image.h"

namespace glintlab {
namespace {

const std::vector<std::string> kChannels = {"r", "g", "b", "a", "rgb", "luminance"};
const std::vector<std::string> kWraps = {"repeat", "clamp", "mirror"};

std::shared_ptr<const TextureImage> load(const std::filesystem::path& path,
                                         TextureFileCache& files) {
    auto it = files.find(path);
    if (it != files.end()) return it->second;
    auto image = std::make_shared<const TextureImage>(read_texture_image(path));
    files.emplace(path, image);
    return image;
}

}  // namespace

TextureUvTransform read_uv_transform(JsonObject& parent) {
    TextureUvTransform t;
    auto block = parent.object("uv_transform");
    if (!block) return t;
    JsonObject& o = *block;
    if (o.has("scale")) {
        const nlohmann::json* s = o.raw("scale");
        t.scale = s->is_number() ? glm::vec2(float(o.number("scale", 1.0, -1e6, 1e6)))
                                 : o.vec2("scale", glm::vec2(1.0f), -1e6, 1e6);
        if (t.scale.x == 0.0f || t.scale.y == 0.0f)
            o.error("scale", "uv scale factors must be non-zero (in [-1e6, 1e6])");
    }
    t.offset = o.vec2("offset", glm::vec2(0.0f), -1e6, 1e6);
    t.rotation_rad = float(o.number("rotation_deg", 0.0, -360.0, 360.0) * std::numbers::pi / 180.0);
    o.finish();
    return t;
}

TextureSource read_texture_source(JsonObject& b, TextureFileCache& files) {
    // An image handed over in memory (the Python module's NumPy arrays,
    // "<array N>"; a glTF file's embedded images, "<file.glb image N>") or a file.
    TextureSource source;
    if (const nlohmann::json* v = b.has("texture") ? b.raw("texture") : nullptr;
        v && v->is_string() && v->get<std::string>().starts_with(kInMemoryPrefix)) {
        source.file = v->get<std::string>();
        const auto it = files.find(source.file);
        if (it == files.end())
            b.error("texture",
                    fmt::format("{} names no image handed to the loader (names in <...> are "
                                "the Python module's arrays and glTF files' embedded images)",
                                source.file.string()));
        source.image = it->second;
    } else {
        source.file = b.file_path("texture");
        try {
            source.image = load(source.file, files);
        } catch (const Error& e) {
            b.error("texture", e.what());  // the image's own error, under the JSON path
        }
    }
    return source;
}

TextureWraps read_texture_wrap(JsonObject& b) {
    auto mode = [](const std::string& name) {
        return name == "clamp"    ? TextureWrap::Clamp
               : name == "mirror" ? TextureWrap::Mirror
                                  : TextureWrap::Repeat;
    };
    const nlohmann::json* v = b.has("wrap") ? b.raw("wrap") : nullptr;
    if (!v || !v->is_array()) return mode(b.string("wrap", "repeat", kWraps));
    auto known = [](const nlohmann::json& e) {
        return e.is_string() &&
               std::find(kWraps.begin(), kWraps.end(), e.get<std::string>()) != kWraps.end();
    };
    if (v->size() != 2 || !known((*v)[0]) || !known((*v)[1]))
        b.error("wrap", fmt::format("got {}: allowed one of {} or a list of two of them "
                                    "([along u, along v])",
                                    v->dump(), fmt::join(kWraps, ", ")));
    return {mode((*v)[0].get<std::string>()), mode((*v)[1].get<std::string>())};
}

bool is_texture_form(JsonObject& o, std::string_view key) {
    if (!o.has(key)) return false;
    const nlohmann::json* v = o.raw(key);
    o.ignore(key);
    return v->is_object();
}

std::shared_ptr<const TextureInput> read_texture_block(JsonObject& b, const TextureParameter& p,
                                                       TextureFileCache& files) {
    const TextureSource source = read_texture_source(b, files);
    const std::filesystem::path& file = source.file;
    const std::shared_ptr<const TextureImage>& image = source.image;
    const std::string where = fmt::format("{} ({})", b.path(), file.string());

    if (!b.has("channel") && !p.colour && !image->grey())
        b.error("channel", fmt::format("{} has colour texels: say which channel holds the value, "
                                       "\"channel\": \"r\", \"g\", \"b\", \"a\" or \"luminance\"",
                                       file.string()));
    const std::string channel = b.string("channel", p.colour ? "rgb" : "r", kChannels);
    if (channel == "rgb" && !p.colour)
        b.error("channel",
                "\"rgb\" needs a colour parameter; this one takes a single value: \"r\", \"g\", "
                "\"b\", \"a\" or \"luminance\"");
    // glTF's convention: colour textures are sRGB-encoded, data (roughness,
    // density) linear; EXR and HDR texels are linear values.
    const std::string colorspace =
        b.string("colorspace", image->codes && p.colour ? "srgb" : "linear", {"srgb", "linear"});
    if (b.has("colorspace")) {
        if (colorspace == "srgb" && !image->codes)
            b.error("colorspace",
                    fmt::format("{} holds linear values (EXR/HDR): \"srgb\" applies to the codes "
                                "of PNG and JPEG files only",
                                file.string()));
    }
    // A colour's scale may be one factor a channel (glTF's baseColorFactor).
    glm::dvec3 scale(1.0);
    if (b.has("scale") && b.raw("scale")->is_array()) {
        if (!p.colour)
            b.error("scale",
                    "one factor a channel needs a colour parameter; this one takes a "
                    "single value: give one number");
        scale = glm::dvec3(b.vec3("scale", glm::vec3(1.0f), -1e6f, 1e6f));
    } else {
        scale = glm::dvec3(b.number("scale", 1.0, -1e6, 1e6));
    }
    const double offset = b.number("offset", 0.0, -1e6, 1e6);
    // value = (offset + scale x texel)^power: 2 turns glTF's perceptual
    // roughness maps into α.
    const int power = b.integer("power", 1, 1, 2);
    const TextureWraps wrap = read_texture_wrap(b);
    auto input = std::make_shared<TextureInput>();
    input->transform = read_uv_transform(b);
    input->source = file.string();
    b.finish();

    const bool srgb = colorspace == "srgb";
    auto decode = [&](float code) { return srgb ? srgb_decode(code) : code; };
    const int out_channels = channel == "rgb" ? 3 : 1;
    const int out_width = image->width;
    std::vector<float> texels;
    texels.reserve(image->texels.size() * size_t(out_channels));
    size_t clamped = 0;
    for (size_t i = 0; i < image->texels.size(); ++i) {
        const glm::vec4& t = image->texels[i];
        float values[3];
        if (channel == "rgb") {
            for (int c = 0; c < 3; ++c) values[c] = decode(t[c]);
        } else if (channel == "luminance") {
            values[0] = luminance(glm::vec3(decode(t.x), decode(t.y), decode(t.z)));
        } else if (channel == "a") {
            values[0] = t.w;  // alpha is linear coverage in every format
        } else {
            values[0] = decode(t[channel == "r" ? 0 : channel == "g" ? 1 : 2]);
        }
        for (int c = 0; c < out_channels; ++c) {
            const double linear = offset + scale[c] * double(values[c]);
            double v = power == 2 ? linear * linear : linear;
            if (!(v >= p.min && v <= p.max)) {
                if (p.clamp_below && v < p.min && v >= 0.0) {
                    v = p.min;
                    ++clamped;
                } else {
                    fail(
                        "{}: texel (x={}, y={}) maps to {:g} = ({:g} + {:g} x {:g})^{}, outside "
                        "the parameter's range [{:g}, {:g}] (set \"scale\" and \"offset\" so "
                        "that value = (offset + scale x texel)^power stays inside)",
                        where, i % size_t(out_width), i / size_t(out_width), v, offset, scale[c],
                        double(values[c]), power, p.min, p.max);
                }
            }
            switch (p.filtered) {
                case TextureParameter::Filtered::Value:
                    break;
                case TextureParameter::Filtered::Square:
                    v = v * v;
                    break;
                case TextureParameter::Filtered::Exp:
                    v = std::exp(v);
                    break;
            }
            texels.push_back(float(v));
        }
    }
    if (clamped > 0)
        fmt::print(stderr, "warning: {}: {} texel value{} below {:g} clamped to {:g}\n", where,
                   clamped, clamped == 1 ? "" : "s", p.min, p.min);
    input->texture = std::make_shared<const MipTexture>(image->width, image->height, out_channels,
                                                        std::move(texels), wrap);
    return input;
}

std::shared_ptr<const TextureInput> read_texture_input(JsonObject& o, std::string_view key,
                                                       const TextureParameter& p,
                                                       TextureFileCache& files) {
    std::optional<JsonObject> block = o.object(key);
    if (!block) o.error(key, "expected a texture object {\"texture\": \"file\", ...}");
    return read_texture_block(*block, p, files);
}

}  // namespace glintlab
