// pack_scalar_inputs and lookup_scalars: one-value inputs whose maps line
// up are read by one footprint lookup, and every value read stays
// bit-identical to the input's own texture.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "glintlab/core/rng.h"
#include "glintlab/core/texture_input.h"

namespace glintlab {
namespace {

std::shared_ptr<const TextureInput> random_input(int w, int h, uint64_t seed,
                                                 TextureWrap wrap = TextureWrap::Repeat) {
    Pcg32 rng(seed, 0);
    std::vector<float> t(size_t(w) * size_t(h));
    for (float& v : t) v = rng.next_float() * 10.0f;
    auto in = std::make_shared<TextureInput>();
    in->texture = std::make_shared<const MipTexture>(w, h, 1, std::move(t), wrap);
    in->transform.scale = glm::vec2(3.0f, 2.0f);
    in->transform.rotation_rad = 0.3f;
    in->source = "random";
    return in;
}

TEST(TextureInput, PackedInputsReadBitIdenticalValuesInOneLookup) {
    const auto density = random_input(7, 5, 1), alpha = random_input(7, 5, 2);
    std::shared_ptr<const TextureInput> d = density, ax = alpha, ay = alpha;  // isotropic
    std::shared_ptr<const TextureInput>* inputs[] = {&d, &ax, &ay};
    pack_scalar_inputs(inputs);
    ASSERT_EQ(d->texture, ax->texture);
    EXPECT_EQ(ax, ay);  // one input on both axes stays one channel
    EXPECT_EQ(d->texture->channels(), 2);
    EXPECT_EQ(d->channel, 0);
    EXPECT_EQ(ax->channel, 1);
    EXPECT_EQ(d->transform, density->transform);
    // Every level holds each input's own box means, bit for bit.
    ASSERT_EQ(d->texture->level_count(), density->texture->level_count());
    for (int l = 0; l < d->texture->level_count(); ++l)
        for (int y = 0; y < d->texture->height(l); ++y)
            for (int x = 0; x < d->texture->width(l); ++x) {
                EXPECT_EQ(d->texture->texel(l, x, y, 0), density->texture->texel(l, x, y, 0));
                EXPECT_EQ(d->texture->texel(l, x, y, 1), alpha->texture->texel(l, x, y, 0));
            }
    EXPECT_EQ(d->mean(), density->mean());
    EXPECT_EQ(ax->max_value(), alpha->max_value());
    // Footprint lookups of every shape, and the bilinear value: the same.
    Pcg32 rng(7, 0);
    for (int i = 0; i < 200; ++i) {
        const glm::vec2 uv(rng.next_float() * 4.0f - 2.0f, rng.next_float() * 4.0f - 2.0f);
        const float scale = std::exp2(rng.next_float() * 12.0f - 10.0f);
        const Footprint fp{uv, glm::vec2(rng.next_float() - 0.5f, rng.next_float() - 0.5f) * scale,
                           glm::vec2(rng.next_float() - 0.5f, rng.next_float() * 0.1f) * scale};
        const TextureInput* packed[] = {d.get(), ax.get(), ay.get()};
        float values[3] = {-1.0f, -1.0f, -1.0f};
        lookup_scalars(packed, uv, &fp, values);
        EXPECT_EQ(values[0], density->lookup(uv, &fp).x);
        EXPECT_EQ(values[1], alpha->lookup(uv, &fp).x);
        EXPECT_EQ(values[2], values[1]);
        EXPECT_EQ(d->lookup(uv, &fp), density->lookup(uv, &fp));
        EXPECT_EQ(ax->at(uv), alpha->at(uv));
    }
}

TEST(TextureInput, InputsThatDoNotLineUpStayApart) {
    const auto a = random_input(8, 8, 1), other_size = random_input(8, 4, 2);
    const auto other_wrap = random_input(8, 8, 3, TextureWrap::Clamp);
    auto moved = std::make_shared<TextureInput>(*random_input(8, 8, 4));
    moved->transform.offset = glm::vec2(0.5f, 0.0f);
    std::shared_ptr<const TextureInput> x = a, y = other_size, z = other_wrap, w = moved;
    std::shared_ptr<const TextureInput>* inputs[] = {&x, &y, &z, &w};
    pack_scalar_inputs(inputs);
    EXPECT_EQ(x, a);
    EXPECT_EQ(y, other_size);
    EXPECT_EQ(z, other_wrap);
    EXPECT_EQ(w, moved);
    // A colour input and a null one are left alone; the two that line up pack.
    auto colour = std::make_shared<TextureInput>();
    colour->texture = std::make_shared<const MipTexture>(8, 8, 3, std::vector<float>(192, 0.5f),
                                                         TextureWrap::Repeat);
    const auto b = random_input(8, 8, 5);
    std::shared_ptr<const TextureInput> c = colour, n, p = a, q = b;
    std::shared_ptr<const TextureInput>* mixed[] = {&c, &n, &p, &q};
    pack_scalar_inputs(mixed);
    EXPECT_EQ(c, colour);
    EXPECT_EQ(n, nullptr);
    EXPECT_EQ(p->texture, q->texture);
    EXPECT_EQ(q->channel, 1);
    // Unpacked inputs each get their own lookup, with the same values.
    const Footprint fp{{0.3f, 0.7f}, {0.01f, 0.0f}, {0.0f, 0.2f}};
    const TextureInput* apart[] = {x.get(), y.get()};
    float values[2] = {0.0f, 0.0f};
    lookup_scalars(apart, fp.uv, &fp, values);
    EXPECT_EQ(values[0], a->lookup(fp.uv, &fp).x);
    EXPECT_EQ(values[1], other_size->lookup(fp.uv, &fp).x);
}

}  // namespace
}  // namespace glintlab
