// GlintBxdf's hooks of wang2020 (glints/glint_kernel.h): none. wang2020
// shades the lights it can shade itself (its descriptor's light_radiance,
// 001 Eq. 21); as a BRDF (later bounces) it is its smooth limit D.
#pragma once

namespace glintlab {

struct Wang2020Kernel {};

}  // namespace glintlab
