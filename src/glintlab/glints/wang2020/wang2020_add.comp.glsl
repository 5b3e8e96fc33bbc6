// wang2020 post-process, last pass: target.rgb += src.rgb (the blurred
// glints into the image).
layout(local_size_x = 16, local_size_y = 16) in;
layout(rgba32f, binding = 0) uniform readonly image2D u_src;
layout(rgba32f, binding = 1) uniform image2D u_target;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(u_target)))) return;
    vec4 t = imageLoad(u_target, p);
    imageStore(u_target, p, vec4(t.rgb + imageLoad(u_src, p).rgb, t.a));
}
