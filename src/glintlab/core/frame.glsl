// An orthonormal tangent frame (t, b, n) around a unit vector n, branchless
// but for the sign of n.z: Duff et al., "Building an Orthonormal Basis,
// Revisited", JCGT 6(1), 2017, Listing 3. Shared by the models that shade in
// a local frame (kneiphof2025's cone quadrature and lobe estimate, wang2020's
// prefiltered tables).
#ifndef GLINTLAB_CORE_FRAME_GLSL
#define GLINTLAB_CORE_FRAME_GLSL

void tangent_frame(vec3 n, OUT(vec3) t, OUT(vec3) b) {
    float s = n.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (s + n.z);
    float c = n.x * n.y * a;
    t = vec3(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
    b = vec3(c, s + n.y * n.y * a, -n.y);
}

#endif
