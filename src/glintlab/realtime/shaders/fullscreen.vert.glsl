// Full-screen pass, vertex stage (background, viewer tonemap).
// One triangle covering the viewport; v_ndc in [-1, 1]^2.
out vec2 v_ndc;
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    v_ndc = p * 2.0f - 1.0f;
    gl_Position = vec4(v_ndc, 1.0f, 1.0f);
}
