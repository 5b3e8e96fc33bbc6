// A material input read from a texture: the mip-mapped texture of the
// input's values (already mapped to the quantity the input is filtered in,
// scene/texture_reader.h) and the uv transform in front of it.
#pragma once

#include <cmath>
#include <memory>
#include <span>
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
        if (rotation_rad == 0.0f) return s;  // the usual case: no cos and sin per lookup
        const float c = std::cos(rotation_rad), n = std::sin(rotation_rad);
        return {c * s.x + n * s.y, -n * s.x + c * s.y};
    }
    glm::vec2 apply(glm::vec2 uv) const { return offset + apply_vector(uv); }
    bool identity() const {
        return scale == glm::vec2(1.0f) && offset == glm::vec2(0.0f) && rotation_rad == 0.0f;
    }

    bool operator==(const TextureUvTransform&) const = default;
};

struct TextureInput {
    std::shared_ptr<const MipTexture> texture;
    TextureUvTransform transform;
    std::string source;  // the file (or "array"), for messages
    // −1: the input is every channel of `texture`. c ≥ 0: the input is one
    // value, channel c of a texture it shares with other one-value inputs
    // of the same size, wrap and uv transform (pack_scalar_inputs): one
    // footprint lookup reads them all.
    int channel = -1;

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
    // The input's own value in a lookup4 of its texture.
    float scalar(glm::vec4 v) const { return v[value_channel()]; }
    // The mean of the whole map (the coarsest level's texel) and its largest
    // texel, of a one-value input.
    float mean() const { return texture->texel(texture->level_count() - 1, 0, 0, value_channel()); }
    float max_value() const { return texture->max_value()[value_channel()]; }
    // True when one lookup4 of this input also gives `other`'s value.
    bool shares_lookup(const TextureInput& other) const {
        return texture == other.texture && transform == other.transform;
    }

  private:
    // The channel a one-value input reads: its own, or the first of an unpacked texture.
    int value_channel() const { return channel < 0 ? 0 : channel; }
    glm::vec3 grey_or_rgb(glm::vec4 v) const {
        if (channel >= 0) return glm::vec3(v[channel]);
        return texture->channels() == 1 ? glm::vec3(v.x) : glm::vec3(v);
    }
};

// Packs one-value inputs that share level 0's size, the wrap and the uv
// transform into one texture of up to 4 channels, so a footprint lookup
// reads them together (the renderers' hot path makes one filtered lookup
// instead of one per input). Each mip level of the packed texture holds, per
// channel, the same box means as the input's own chain (the filter works
// channel by channel), so every value read is bit-identical. The same input
// given twice (an isotropic roughness map on both axes) stays one channel.
// Inputs that are null, already packed or of several channels are left as
// they are; fewer than two distinct candidates: nothing changes.
void pack_scalar_inputs(std::span<std::shared_ptr<const TextureInput>* const> inputs);

// values[i] = inputs[i]'s value over the footprint (TextureInput::lookup),
// with one lookup4 for all the inputs that share a lookup; a null input
// leaves values[i] as it is. At most 8 inputs.
void lookup_scalars(std::span<const TextureInput* const> inputs, glm::vec2 uv,
                    const Footprint* footprint, std::span<float> values);

}  // namespace glintlab
