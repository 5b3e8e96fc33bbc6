#include "glintlab/realtime/gpu_bloom.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <epoxy/gl.h>

#include "glintlab/core/error.h"
#include "glintlab/core/shader_assembly.h"
#include "glintlab/realtime/gl_handles.h"

namespace glintlab::gl {
namespace {

// core/image.cpp luminance (BT.709 Y).
constexpr const char* kExtract = R"(
layout(local_size_x = 16, local_size_y = 16) in;
layout(rgba32f, binding = 0) uniform readonly image2D u_in;
layout(rgba32f, binding = 1) uniform writeonly image2D u_bright;
uniform float u_threshold;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(u_in)))) return;
    vec3 c = imageLoad(u_in, p).rgb;
    float y = 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
    vec3 b = y > u_threshold ? c * ((y - u_threshold) / y) : vec3(0.0f);
    imageStore(u_bright, p, vec4(b, 0.0f));
}
)";

// One axis of core/bloom_blur.cpp gaussian_blur_conserving: each source
// pixel is scaled by 1 / (its taps inside the image), then convolved.
// u_axis = 0: rows (x), 1: columns (y). Accumulates u_weight * result into
// u_out when u_accumulate.
constexpr const char* kBlur = R"(
layout(local_size_x = 16, local_size_y = 16) in;
layout(rgba32f, binding = 0) uniform readonly image2D u_src;
layout(rgba32f, binding = 1) uniform image2D u_out;
layout(std430, binding = 0) readonly buffer Taps { float u_taps[]; };
layout(std430, binding = 1) readonly buffer Scales { float u_scales[]; };
uniform int u_radius;
uniform int u_axis;
uniform bool u_accumulate;
uniform float u_weight;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_src);
    if (any(greaterThanEqual(p, size))) return;
    int n = u_axis == 0 ? size.x : size.y;
    int i = u_axis == 0 ? p.x : p.y;
    vec3 sum = vec3(0.0f);
    for (int k = -u_radius; k <= u_radius; ++k) {
        int s = i - k;  // source index; tap k
        if (s < 0 || s >= n) continue;
        ivec2 q = u_axis == 0 ? ivec2(s, p.y) : ivec2(p.x, s);
        sum += (u_taps[k + u_radius] * u_scales[s]) * imageLoad(u_src, q).rgb;
    }
    vec3 prev = u_accumulate ? imageLoad(u_out, p).rgb : vec3(0.0f);
    imageStore(u_out, p, vec4(prev + u_weight * sum, 0.0f));
}
)";

// out = image + strength (glow - bright).
constexpr const char* kComposite = R"(
layout(local_size_x = 16, local_size_y = 16) in;
layout(rgba32f, binding = 0) uniform readonly image2D u_in;
layout(rgba32f, binding = 1) uniform readonly image2D u_bright;
layout(rgba32f, binding = 2) uniform readonly image2D u_glow;
layout(rgba32f, binding = 3) uniform writeonly image2D u_result;
uniform float u_strength;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(u_in)))) return;
    vec3 c = imageLoad(u_in, p).rgb + u_strength * (imageLoad(u_glow, p).rgb - imageLoad(u_bright, p).rgb);
    imageStore(u_result, p, vec4(c, 1.0f));
}
)";

GLuint compute_program(const char* source, const char* what) {
    const AssembledShader s = assemble_shader(source, true);
    Shader shader(glCreateShader(GL_COMPUTE_SHADER));
    const char* text = s.text.c_str();
    glShaderSource(shader.get(), 1, &text, nullptr);
    glCompileShader(shader.get());
    GLint ok = 0;
    glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        glGetShaderInfoLog(shader.get(), sizeof(log), nullptr, log);
        fail("{}: compute shader does not compile:\n{}", what, map_shader_log(s, log));
    }
    Program program(glCreateProgram());
    glAttachShader(program.get(), shader.get());
    glLinkProgram(program.get());
    glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (!ok) fail("{}: compute program does not link", what);
    return program.release();
}

// core/bloom_blur.cpp gaussian_taps and source_scales, in the same precision.
std::vector<float> gaussian_taps(float sigma) {
    const int radius = std::max(1, static_cast<int>(std::ceil(4.0f * sigma)));
    std::vector<float> taps(static_cast<size_t>(2 * radius + 1));
    double sum = 0.0;
    for (int k = -radius; k <= radius; ++k) {
        const double w = std::exp(-0.5 * double(k) * double(k) / (double(sigma) * sigma));
        taps[static_cast<size_t>(k + radius)] = static_cast<float>(w);
        sum += w;
    }
    for (float& w : taps) w = static_cast<float>(double(w) / sum);
    return taps;
}

std::vector<float> source_scales(const std::vector<float>& taps, int n) {
    const int radius = static_cast<int>(taps.size() / 2);
    std::vector<float> scale(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
        double inside = 0.0;
        for (int k = -radius; k <= radius; ++k)
            if (i + k >= 0 && i + k < n) inside += taps[static_cast<size_t>(k + radius)];
        scale[static_cast<size_t>(i)] = static_cast<float>(1.0 / inside);
    }
    return scale;
}

Texture rgba32f(int w, int h) {
    Texture t = make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(t.get(), 1, GL_RGBA32F, w, h);
    return t;
}

}  // namespace

struct GpuBloom::Impl {
    Program extract, blur, composite;
    Texture bright, temp, glow, result;
    Buffer taps, scales;
    int width = 0, height = 0;
};

GpuBloom::GpuBloom() : impl_(std::make_unique<Impl>()) {
    impl_->extract = Program(compute_program(kExtract, "bloom extract"));
    impl_->blur = Program(compute_program(kBlur, "bloom blur"));
    impl_->composite = Program(compute_program(kComposite, "bloom composite"));
}

GpuBloom::~GpuBloom() = default;

unsigned GpuBloom::apply(unsigned hdr, int w, int h, const BloomSettings& settings) {
    validate(settings);
    if (settings.strength == 0.0f) return hdr;
    Impl& r = *impl_;
    if (w != r.width || h != r.height) {
        r.bright = rgba32f(w, h);
        r.temp = rgba32f(w, h);
        r.glow = rgba32f(w, h);
        r.result = rgba32f(w, h);
        r.width = w;
        r.height = h;
    }
    const GLuint gx = static_cast<GLuint>((w + 15) / 16), gy = static_cast<GLuint>((h + 15) / 16);
    auto barrier = [] { glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT); };

    glUseProgram(r.extract.get());
    glProgramUniform1f(r.extract.get(), glGetUniformLocation(r.extract.get(), "u_threshold"),
                       settings.threshold);
    glBindImageTexture(0, hdr, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, r.bright.get(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(gx, gy, 1);
    barrier();

    // bloom_blur: the mean of Gaussians of sigma = radius x {1/4, 1/2, 1, 2}.
    const GLuint b = r.blur.get();
    glUseProgram(b);
    const float octaves[] = {0.25f, 0.5f, 1.0f, 2.0f};
    for (int o = 0; o < 4; ++o) {
        const std::vector<float> taps = gaussian_taps(octaves[o] * settings.radius_px);
        const int radius = static_cast<int>(taps.size() / 2);
        glProgramUniform1i(b, glGetUniformLocation(b, "u_radius"), radius);
        r.taps = make_buffer();
        glNamedBufferStorage(r.taps.get(), static_cast<GLsizeiptr>(taps.size() * sizeof(float)),
                             taps.data(), 0);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, r.taps.get());
        for (int axis = 0; axis < 2; ++axis) {
            const std::vector<float> scales = source_scales(taps, axis == 0 ? w : h);
            r.scales = make_buffer();
            glNamedBufferStorage(r.scales.get(),
                                 static_cast<GLsizeiptr>(scales.size() * sizeof(float)),
                                 scales.data(), 0);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, r.scales.get());
            glProgramUniform1i(b, glGetUniformLocation(b, "u_axis"), axis);
            // Rows: bright -> temp; columns: temp -> glow, accumulated with weight 1/4.
            glProgramUniform1i(b, glGetUniformLocation(b, "u_accumulate"),
                               axis == 1 && o > 0 ? 1 : 0);
            glProgramUniform1f(b, glGetUniformLocation(b, "u_weight"), axis == 0 ? 1.0f : 0.25f);
            glBindImageTexture(0, axis == 0 ? r.bright.get() : r.temp.get(), 0, GL_FALSE, 0,
                               GL_READ_ONLY, GL_RGBA32F);
            glBindImageTexture(1, axis == 0 ? r.temp.get() : r.glow.get(), 0, GL_FALSE, 0,
                               GL_READ_WRITE, GL_RGBA32F);
            glDispatchCompute(gx, gy, 1);
            barrier();
        }
    }

    const GLuint c = r.composite.get();
    glUseProgram(c);
    glProgramUniform1f(c, glGetUniformLocation(c, "u_strength"), settings.strength);
    glBindImageTexture(0, hdr, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, r.bright.get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(2, r.glow.get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(3, r.result.get(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(gx, gy, 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(0);
    return r.result.get();
}

}  // namespace glintlab::gl
