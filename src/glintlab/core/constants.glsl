// Shared numeric constants for the GLSL/C++ shading code.
#ifndef GLINTLAB_CORE_CONSTANTS_GLSL
#define GLINTLAB_CORE_CONSTANTS_GLSL

const float PI = 3.14159265358979323846f;
const float TWO_PI = 6.28318530717958647692f;
const float INV_PI = 0.31830988618379067154f;
const float INV_TWO_PI = 0.15915494309189533577f;
const float SQRT_PI = 1.77245385090551602730f;
const float INV_SQRT_PI = 0.56418958354775628695f;
const float SQRT_TWO = 1.41421356237309504880f;
// Largest float strictly below 1: uniform numbers live in [0, ONE_MINUS_EPSILON].
const float ONE_MINUS_EPSILON = 0.99999994f;

#endif
