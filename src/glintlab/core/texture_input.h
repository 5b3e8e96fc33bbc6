// A material input read from a texture: the mip-mapped texture of the
// input's values (already mapped to the quantity the input is filtered in,
// scene/texture_reader.h) and the uv transform in front of it.
#pragma once

#include <cmath>
#include <memory>
#include <string>

#include <glm/glm.hpp>

#include "glintlab/core/footprint.h"
#include "glintlab/core/mip_texture.h"

namespace glintlab {

// KHR_texture_transform's order: uv' = offset + R(rotation) · (scale ⊙ uv),
// R = [[cos, sin], [−sin, cos]] (a positive rotation turns the texture
// counter-clockwise in uv).
struct TextureUvTransform {
    glm::vec2 scale{1.0f}, offset{0.0f};
    float rotation_rad = 0.0f;
    glm::vec2 apply_vector(glm::vec2 d) const {
        const glm::vec2 s = scale * d;
        const float c = std::cos(rotation_rad), n = std::sin(rotation_rad);
        return {c * s.x + n * s.y, -n * s.x + c * s.y};
    }
    glm::vec2 apply(glm::vec2 uv) const { return offset + apply_vector(uv); }
    bool identity() const {
        return scale == glm::vec2(1.0f) && offset == glm::vec2(0.0f) && rotation_rad == 0.0f;
    }
};

struct TextureInput {
    std::shared_ptr<const MipTexture> texture;
    TextureUvTransform transform;
    std::string source;  // the file (or "array"), for messages

    // The mean over the pixel footprint (MipTexture::filtered), or the
    // finest level's bilinear value at uv without a footprint (a path's
    // later bounces carry none).
    // A one-channel texture's value is repeated in all three (a grey colour).
    glm::vec3 lookup(glm::vec2 uv, const Footprint* footprint, float lod_bias = 0.0f) const {
        return grey_or_rgb(lookup4(uv, footprint, lod_bias));
    }
    // Every channel (a 4-channel texture's fourth; unused ones 0).
    glm::vec4 lookup4(glm::vec2 uv, const Footprint* footprint, float lod_bias = 0.0f) const {
        const glm::vec2 st = transform.apply(uv);
        if (!footprint) return texture->bilinear(0, st);
        return texture->filtered(st, transform.apply_vector(footprint->duvdx),
                                 transform.apply_vector(footprint->duvdy), lod_bias);
    }
    // The finest level's bilinear value at uv (the ground truth's per-facet value).
    glm::vec3 at(glm::vec2 uv) const {
        return grey_or_rgb(texture->bilinear(0, transform.apply(uv)));
    }

  private:
    glm::vec3 grey_or_rgb(glm::vec4 v) const {
        return texture->channels() == 1 ? glm::vec3(v.x) : glm::vec3(v);
    }
};

}  // namespace glintlab
