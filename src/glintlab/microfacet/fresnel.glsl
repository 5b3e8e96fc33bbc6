// Fresnel reflectance: Schlick 1994 "An Inexpensive BRDF Model for
// Physically-based Rendering" (F_Schlick); exact unpolarised Fresnel equations
// for a dielectric interface and for a conductor with complex IOR eta + i k
// (Born & Wolf, Principles of Optics §1.5 / §14.2; same cases as pbrt-v4
// FrDielectric / FrComplex), here in real arithmetic.
#ifndef GLINTLAB_MICROFACET_FRESNEL_GLSL
#define GLINTLAB_MICROFACET_FRESNEL_GLSL

float F_Schlick(float F0, float cos_theta) {
    float c = clamp(1.0f - cos_theta, 0.0f, 1.0f);
    float c2 = c * c;
    return F0 + (1.0f - F0) * (c2 * c2 * c);
}

vec3 F_Schlick(vec3 F0, float cos_theta) {
    float c = clamp(1.0f - cos_theta, 0.0f, 1.0f);
    float c2 = c * c;
    return F0 + (vec3(1.0f) - F0) * (c2 * c2 * c);
}

// eta = eta_transmitted / eta_incident for a direction on the side the normal
// points to (cos_i > 0). cos_i < 0 means the light arrives from inside, so the
// relative IOR inverts. Returns 1 under total internal reflection.
float F_Dielectric(float cos_i, float eta) {
    cos_i = clamp(cos_i, -1.0f, 1.0f);
    if (cos_i < 0.0f) {
        eta = 1.0f / eta;
        cos_i = -cos_i;
    }
    float sin2_i = 1.0f - cos_i * cos_i;
    float sin2_t = sin2_i / (eta * eta);  // Snell's law
    if (sin2_t >= 1.0f) return 1.0f;
    float cos_t = sqrt(1.0f - sin2_t);
    float r_par = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    float r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5f * (r_par * r_par + r_perp * r_perp);
}

// Conductor, one wavelength: IOR eta + i k relative to the outside medium.
// Writing eta_c^2 cos^2(theta_t) = eta_c^2 - sin^2(theta_i) = t0 + i 2 eta k with
// t0 = eta^2 - k^2 - sin^2(theta_i), its square root u + i v has
// u^2 + v^2 = sqrt(t0^2 + 4 eta^2 k^2) and u = sqrt((|.| + t0) / 2). Then
//   R_s = |cos - (u + iv)|^2 / |cos + (u + iv)|^2
//       = (u^2 + v^2 + cos^2 - 2 u cos) / (u^2 + v^2 + cos^2 + 2 u cos),
//   R_p = R_s (|.| cos^2 + sin^4 - 2 u cos sin^2) / (|.| cos^2 + sin^4 + 2 u cos sin^2),
// (the p/s ratio identity of Born & Wolf), and F = (R_s + R_p) / 2.
float F_ConductorScalar(float cos_i, float eta, float k) {
    cos_i = clamp(cos_i, 0.0f, 1.0f);
    float cos2 = cos_i * cos_i;
    float sin2 = 1.0f - cos2;
    // eta^2 - k^2 - sin^2 written with cos^2: sin2 = 1 - cos2 rounds to 1
    // below cos ~ 2e-4, which made eta = 1, k = 0 (no interface) reflect
    // everything at grazing angles.
    float t0 = (eta * eta - k * k - 1.0f) + cos2;
    float uv2 = sqrt(t0 * t0 + 4.0f * eta * eta * k * k);
    float u = sqrt(max(0.0f, 0.5f * (uv2 + t0)));
    float two_u_cos = 2.0f * u * cos_i;
    float a = uv2 + cos2;
    // Both numerators are >= 0 exactly (a - 2u cos >= (u - cos)^2 and
    // b - c >= (u cos - sin^2)^2, since u^2 + v^2 >= u^2), but cancel to
    // rounding noise where the interface vanishes (eta = 1, k = 0: u = cos),
    // which would leak negative radiance: clamp them at 0. There, at
    // cos_i = 0, a + 2u cos = 0 too: no interface reflects nothing.
    float den_s = a + two_u_cos;
    float r_s = den_s > 0.0f ? max(a - two_u_cos, 0.0f) / den_s : 0.0f;
    float b = uv2 * cos2 + sin2 * sin2;
    float c = two_u_cos * sin2;
    float r_p = r_s * max(b - c, 0.0f) / (b + c);
    // cos_i = 0 (with an interface): r_s = 1 and b + c = sin^4 = 1 > 0.
    return 0.5f * (r_s + r_p);
}

vec3 F_Conductor(float cos_i, vec3 eta, vec3 k) {
    return vec3(F_ConductorScalar(cos_i, eta.x, k.x), F_ConductorScalar(cos_i, eta.y, k.y),
                F_ConductorScalar(cos_i, eta.z, k.z));
}

#endif
