#include "glintlab/core/texture_input.h"

#include <array>
#include <vector>

#include "glintlab/core/error.h"

namespace glintlab {

namespace {

bool packable(const TextureInput& in) {
    return in.channel < 0 && in.texture->channels() == 1;
}

bool same_layout(const TextureInput& a, const TextureInput& b) {
    return a.texture->width() == b.texture->width() && a.texture->height() == b.texture->height() &&
           a.texture->wrap() == b.texture->wrap() && a.transform == b.transform;
}

}  // namespace

void pack_scalar_inputs(std::span<std::shared_ptr<const TextureInput>* const> inputs) {
    // The distinct candidates, in the order given (the first one's layout
    // decides; a candidate of another layout is left alone).
    std::vector<std::shared_ptr<const TextureInput>> distinct;
    for (std::shared_ptr<const TextureInput>* slot : inputs) {
        const std::shared_ptr<const TextureInput>& in = *slot;
        if (!in || !packable(*in)) continue;
        bool seen = false;
        for (const auto& d : distinct) seen = seen || d == in;
        if (seen || (!distinct.empty() && !same_layout(*distinct.front(), *in))) continue;
        if (distinct.size() < 4) distinct.push_back(in);
    }
    if (distinct.size() < 2) return;
    const MipTexture& first = *distinct.front()->texture;
    const size_t texels = size_t(first.width()) * size_t(first.height());
    const size_t channels = distinct.size();
    std::vector<float> packed(texels * channels);
    for (size_t c = 0; c < channels; ++c) {
        const std::vector<float>& level0 = distinct[c]->texture->level_texels(0);
        for (size_t i = 0; i < texels; ++i) packed[i * channels + c] = level0[i];
    }
    const auto texture = std::make_shared<const MipTexture>(
        first.width(), first.height(), int(channels), std::move(packed), first.wrap());
    std::vector<std::shared_ptr<const TextureInput>> replaced(channels);
    for (size_t c = 0; c < channels; ++c) {
        TextureInput in = *distinct[c];
        in.texture = texture;
        in.channel = int(c);
        replaced[c] = std::make_shared<const TextureInput>(std::move(in));
    }
    for (std::shared_ptr<const TextureInput>* slot : inputs)
        for (size_t c = 0; c < channels; ++c)
            if (*slot == distinct[c]) {
                *slot = replaced[c];
                break;
            }
}

void lookup_scalars(std::span<const TextureInput* const> inputs, glm::vec2 uv,
                    const Footprint* footprint, std::span<float> values) {
    std::array<glm::vec4, 8> looked_up{};
    if (inputs.size() > looked_up.size() || values.size() < inputs.size())
        fail("lookup_scalars: {} inputs, {} values (at most {} inputs)", inputs.size(),
             values.size(), looked_up.size());
    for (size_t i = 0; i < inputs.size(); ++i) {
        const TextureInput* in = inputs[i];
        if (!in) continue;
        size_t j = 0;
        while (j < i && !(inputs[j] && inputs[j]->shares_lookup(*in))) ++j;
        looked_up[i] = j < i ? looked_up[j] : in->lookup4(uv, footprint);
        values[i] = in->scalar(looked_up[i]);
    }
}

}  // namespace glintlab
