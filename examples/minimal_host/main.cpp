// minimal_host: the smallest program that draws a glint material from the
// files of `glintlab export MODEL --lang glsl` alone — no glintlab library,
// no glintlab header (docs/INTEGRATION.md "Minimal host"). It renders the PLANE_25
// view of Deliot & Belcour 2023's Table 1 (an 8 x 8 quad with uv scale 8,
// camera 25 degrees above it at distance 3, a directional light; the
// material is the manifest's: export with --scene of a PLANE_25 scene file
// for its silver conductor, Beckmann roughness 0.3) headless through EGL
// (surfaceless Mesa platform) into an RGBA32F framebuffer and writes the
// linear radiance as a PFM file.
//
// Usage: minimal_host EXPORT_DIR MODEL OUT.pfm
//            [WIDTH HEIGHT LOG_DENSITY [LOG_DENSITY_MAP.pfm|- [NORMAL_MAP.pfm]]]
//
// LOG_DENSITY_MAP.pfm (optional, "-" for none): ln N per texel (the first
// channel), uv (0, 0) at the image's top-left corner; fed through the
// export's input texture u_input_density as N = exp(ln N) with a mip chain
// (docs/INTEGRATION.md "Per-pixel material inputs"). NORMAL_MAP.pfm
// (optional): unit tangent-space normals (x, y, z) in glTF's convention,
// LEAN-mapped here into the input u_input_normal_slopes.
//
// What a host does with an export, in order:
//  1. read MODEL.glsl.manifest.json: the fragment shader's file, the model's
//     parameters (uniform name, default) and resources (file, format, size,
//     filtering, uniform);
//  2. compile its own vertex stage (outputs v_position, v_normal, v_uv,
//     v_dpdu in world space) with the exported fragment stage;
//  3. upload each resource as a texture and point its sampler uniform at a unit;
//  4. set the material, light and camera uniforms; draw.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <nlohmann/json.hpp>

namespace {

[[noreturn]] void die(const std::string& what) {
    throw std::runtime_error(what);
}

std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) die("cannot read " + path);
    return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

// A headless OpenGL 4.5 core context on Mesa's surfaceless EGL platform.
void make_context() {
    const char* ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (ext == nullptr || std::strstr(ext, "EGL_MESA_platform_surfaceless") == nullptr)
        die("EGL_MESA_platform_surfaceless is not available");
    EGLDisplay display =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor))
        die("eglInitialize failed");
    const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
                                     EGL_PBUFFER_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display, config_attribs, &config, 1, &count) || count < 1) {
        // Surfaceless displays may expose no config: a context without one.
        config = nullptr;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) die("eglBindAPI(EGL_OPENGL_API) failed");
    const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                      4,
                                      EGL_CONTEXT_MINOR_VERSION,
                                      5,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                      EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attribs);
    if (context == EGL_NO_CONTEXT) die("no OpenGL 4.5 core context");
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
        die("eglMakeCurrent failed");
}

GLuint compile(GLenum stage, const std::string& text, const std::string& name) {
    GLuint s = glCreateShader(stage);
    const char* src = text.c_str();
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[8192];
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        die(name + ": " + log);
    }
    return s;
}

// The vertex stage the exported fragment stage expects (world-space inputs).
const char* kVertex = R"(#version 450 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec3 a_dpdu;
uniform mat4 u_view_projection;
out vec3 v_position;
out vec3 v_normal;
out vec2 v_uv;
out vec3 v_dpdu;
void main() {
    v_position = a_position;
    v_normal = a_normal;
    v_uv = a_uv;
    v_dpdu = a_dpdu;
    gl_Position = u_view_projection * vec4(a_position, 1.0);
}
)";

// Column-major 4x4 matrices (OpenGL's layout).
struct Mat4 {
    float m[16] = {};
};
Mat4 multiply(const Mat4& a, const Mat4& b) {
    Mat4 r;
    for (int c = 0; c < 4; ++c)
        for (int row = 0; row < 4; ++row)
            for (int k = 0; k < 4; ++k) r.m[c * 4 + row] += a.m[k * 4 + row] * b.m[c * 4 + k];
    return r;
}
struct Vec3 {
    float x, y, z;
};
Vec3 sub(Vec3 a, Vec3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
float dot(Vec3 a, Vec3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
Vec3 normalize(Vec3 a) {
    const float l = std::sqrt(dot(a, a));
    return {a.x / l, a.y / l, a.z / l};
}
// gluLookAt / gluPerspective (vertical field of view).
Mat4 look_at(Vec3 eye, Vec3 target, Vec3 up) {
    const Vec3 f = normalize(sub(target, eye));
    const Vec3 s = normalize(cross(f, up));
    const Vec3 u = cross(s, f);
    Mat4 r;
    r.m[0] = s.x, r.m[4] = s.y, r.m[8] = s.z;
    r.m[1] = u.x, r.m[5] = u.y, r.m[9] = u.z;
    r.m[2] = -f.x, r.m[6] = -f.y, r.m[10] = -f.z;
    r.m[12] = -dot(s, eye), r.m[13] = -dot(u, eye), r.m[14] = dot(f, eye);
    r.m[15] = 1.0f;
    return r;
}
Mat4 perspective(float fovy, float aspect, float near_plane, float far_plane) {
    const float t = std::tan(fovy / 2.0f);
    Mat4 r;
    r.m[0] = 1.0f / (aspect * t);
    r.m[5] = 1.0f / t;
    r.m[10] = -(far_plane + near_plane) / (far_plane - near_plane);
    r.m[11] = -1.0f;
    r.m[14] = -(2.0f * far_plane * near_plane) / (far_plane - near_plane);
    return r;
}

// Sets a uniform from JSON values by the uniform's declared type.
void set_uniform(GLuint program, const std::map<std::string, GLenum>& types,
                 const std::string& name, const nlohmann::json& v) {
    const GLint loc = glGetUniformLocation(program, name.c_str());
    const auto it = types.find(name);
    if (loc < 0 || it == types.end()) return;  // optimised out: nothing to set
    // A number, a vector, or an array of either (a uniform array, e.g.
    // kneiphof2025's source directions), flattened in order.
    std::vector<float> f;
    std::vector<GLint> n;
    auto flatten = [&](const nlohmann::json& e, auto&& self) -> void {
        if (e.is_array()) {
            for (const nlohmann::json& x : e) self(x, self);
        } else if (e.is_boolean()) {
            f.push_back(e.get<bool>() ? 1.0f : 0.0f);
            n.push_back(e.get<bool>() ? 1 : 0);
        } else {
            f.push_back(e.get<float>());
            n.push_back(e.is_number_integer() ? e.get<GLint>()
                                              : static_cast<GLint>(e.get<float>()));
        }
    };
    flatten(v, flatten);
    if (f.empty()) return;  // an empty array (no sources): nothing to set
    auto count = [&](size_t components) {
        if (f.size() % components != 0)
            die("uniform " + name + ": " + std::to_string(f.size()) +
                " values are not a whole number of " + std::to_string(components) +
                "-component elements");
        return static_cast<GLsizei>(f.size() / components);
    };
    switch (it->second) {
        case GL_FLOAT:
            glProgramUniform1fv(program, loc, count(1), f.data());
            break;
        case GL_FLOAT_VEC2:
            glProgramUniform2fv(program, loc, count(2), f.data());
            break;
        case GL_FLOAT_VEC3:
            glProgramUniform3fv(program, loc, count(3), f.data());
            break;
        case GL_FLOAT_VEC4:
            glProgramUniform4fv(program, loc, count(4), f.data());
            break;
        case GL_INT:
        case GL_BOOL:
            glProgramUniform1iv(program, loc, count(1), n.data());
            break;
        case GL_UNSIGNED_INT: {
            std::vector<GLuint> u(n.begin(), n.end());
            glProgramUniform1uiv(program, loc, count(1), u.data());
            break;
        }
        case GL_INT_VEC2:
            glProgramUniform2iv(program, loc, count(2), n.data());
            break;
        case GL_INT_VEC3:
            glProgramUniform3iv(program, loc, count(3), n.data());
            break;
        case GL_INT_VEC4:
            glProgramUniform4iv(program, loc, count(4), n.data());
            break;
        default:
            die("uniform " + name + ": type not handled by this host");
    }
}

// Every channel of a PFM file (1 or 3; little-endian, rows bottom to top),
// rows from the top.
std::vector<float> read_pfm(const std::string& path, int* w, int* h, int* channels) {
    std::ifstream f(path, std::ios::binary);
    std::string magic;
    float scale = 0.0f;
    f >> magic >> *w >> *h >> scale;
    f.get();
    if (!f || (magic != "PF" && magic != "Pf") || scale >= 0.0f || *w < 1 || *h < 1 || *w > 16384 ||
        *h > 16384)
        die(path + ": not a little-endian PFM of at most 16384 x 16384");
    *channels = magic == "PF" ? 3 : 1;
    const size_t row = static_cast<size_t>(*w) * static_cast<size_t>(*channels);
    std::vector<float> data(row * static_cast<size_t>(*h));
    f.read(reinterpret_cast<char*>(data.data()),
           static_cast<std::streamsize>(data.size() * sizeof(float)));
    if (!f) die(path + ": truncated");
    std::vector<float> out(data.size());
    for (int y = 0; y < *h; ++y)
        std::copy_n(data.begin() + static_cast<std::ptrdiff_t>(row * size_t(*h - 1 - y)), row,
                    out.begin() + static_cast<std::ptrdiff_t>(row * size_t(y)));
    return out;
}

// The first channel of a PFM file, rows from the top.
std::vector<float> read_pfm_channel(const std::string& path, int* w, int* h) {
    int channels = 0;
    const std::vector<float> all = read_pfm(path, w, h, &channels);
    std::vector<float> out(all.size() / static_cast<size_t>(channels));
    for (size_t i = 0; i < out.size(); ++i) out[i] = all[i * static_cast<size_t>(channels)];
    return out;
}

// A float texture of 1 or 4 channels with a full mip chain of box means
// (glGenerateMipmap on a power-of-two image), trilinear, repeating.
GLuint mipmapped_texture(const std::vector<float>& texels, int w, int h, int channels) {
    int levels = 1;
    while ((std::max(w, h) >> levels) > 0) ++levels;
    GLuint tex = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &tex);
    glTextureStorage2D(tex, levels, channels == 1 ? GL_R32F : GL_RGBA32F, w, h);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(tex, 0, 0, 0, w, h, channels == 1 ? GL_RED : GL_RGBA, GL_FLOAT,
                        texels.data());
    glGenerateTextureMipmap(tex);
    glTextureParameteri(tex, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(tex, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(tex, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(tex, GL_TEXTURE_WRAP_T, GL_REPEAT);
    return tex;
}

// LEAN mapping of a tangent-space normal map (docs/INTEGRATION.md,
// "Per-pixel material inputs"): `normals` holds unit normals (x, y, z),
// rows from the top. Returns per texel (s_x, s_y, m_xx, m_yy): the slope
// s = (-x/z, -y/z) and the second moments of the surface a bilinear lookup
// reconstructs, averaged over the texel's cell (its four half-texel
// squares, each inside one bilinear patch where s^2 is of degree 2 per
// coordinate: 2 x 2 Gauss-Legendre nodes per square integrate it exactly).
// `cross`, when given, receives each texel's m_xy the same way (the input
// u_input_normal_cross of the models that read the slopes' correlation).
std::vector<float> lean_map(const std::vector<float>& normals, int w, int h,
                            std::vector<float>* cross = nullptr) {
    const size_t count = static_cast<size_t>(w) * static_cast<size_t>(h);
    std::vector<float> sx(count), sy(count);
    for (size_t i = 0; i < count; ++i) {
        const float z = std::max(normals[i * 3 + 2], 0.05f);  // at most 87.1 degrees steep
        sx[i] = -normals[i * 3] / z;
        sy[i] = -normals[i * 3 + 1] / z;
    }
    auto at = [&](const std::vector<float>& v, int x, int y) {
        return v[static_cast<size_t>(((y % h) + h) % h) * static_cast<size_t>(w) +
                 static_cast<size_t>(((x % w) + w) % w)];
    };
    const float g = 0.25f / std::sqrt(3.0f);
    const float nodes[4] = {-0.25f - g, -0.25f + g, 0.25f - g, 0.25f + g};
    std::vector<float> out(count * 4);
    if (cross) cross->assign(count, 0.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float mxx = 0.0f, myy = 0.0f, mxy = 0.0f;
            for (const float oy : nodes)
                for (const float ox : nodes) {
                    const float px = static_cast<float>(x) + ox, py = static_cast<float>(y) + oy;
                    const int ix = static_cast<int>(std::floor(px));
                    const int iy = static_cast<int>(std::floor(py));
                    const float fx = px - static_cast<float>(ix), fy = py - static_cast<float>(iy);
                    auto bilinear = [&](const std::vector<float>& v) {
                        const float top = at(v, ix, iy) + fx * (at(v, ix + 1, iy) - at(v, ix, iy));
                        const float bottom =
                            at(v, ix, iy + 1) + fx * (at(v, ix + 1, iy + 1) - at(v, ix, iy + 1));
                        return top + fy * (bottom - top);
                    };
                    const float a = bilinear(sx), b = bilinear(sy);
                    mxx += a * a, myy += b * b, mxy += a * b;
                }
            const size_t i =
                static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
            out[i * 4 + 0] = sx[i];
            out[i * 4 + 1] = sy[i];
            out[i * 4 + 2] = mxx / 16.0f;
            out[i * 4 + 3] = myy / 16.0f;
            if (cross) (*cross)[i] = mxy / 16.0f;
        }
    return out;
}

void write_pfm(const std::string& path, int w, int h, const std::vector<float>& rgb) {
    std::ofstream f(path, std::ios::binary);
    f << "PF\n" << w << " " << h << "\n-1.0\n";  // little-endian, rows bottom to top
    f.write(reinterpret_cast<const char*>(rgb.data()),
            static_cast<std::streamsize>(rgb.size() * sizeof(float)));
    if (!f) die("cannot write " + path);
}

int run(int argc, char** argv) {
    if (argc != 4 && (argc < 7 || argc > 9)) {
        std::fprintf(stderr,
                     "usage: %s EXPORT_DIR MODEL OUT.pfm [WIDTH HEIGHT LOG_DENSITY "
                     "[LOG_DENSITY_MAP.pfm|- [NORMAL_MAP.pfm]]]\n",
                     argv[0]);
        return 2;
    }
    const std::string dir = argv[1], model = argv[2], out = argv[3];
    const int width = argc >= 7 ? std::atoi(argv[4]) : 128;
    const int height = argc >= 7 ? std::atoi(argv[5]) : 128;
    const float log_density = argc >= 7 ? static_cast<float>(std::atof(argv[6])) : 12.0f;
    if (width < 1 || height < 1 || width > 8192 || height > 8192) die("bad image size");

    const nlohmann::json manifest =
        nlohmann::json::parse(slurp(dir + "/" + model + ".glsl.manifest.json"));
    std::string fragment_file;
    for (const auto& s : manifest.at("shaders"))
        if (s.at("variant") == "default") fragment_file = s.at("file");
    if (fragment_file.empty()) die("manifest lists no default fragment shader");

    make_context();
    GLuint program = glCreateProgram();
    glAttachShader(program, compile(GL_VERTEX_SHADER, kVertex, "vertex stage"));
    glAttachShader(program,
                   compile(GL_FRAGMENT_SHADER, slurp(dir + "/" + fragment_file), fragment_file));
    glLinkProgram(program);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) {
        char log[8192];
        glGetProgramInfoLog(program, sizeof log, nullptr, log);
        die(std::string("link: ") + log);
    }
    std::map<std::string, GLenum> types;
    GLint active = 0;
    glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &active);
    for (GLint i = 0; i < active; ++i) {
        char name[256];
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(program, static_cast<GLuint>(i), sizeof name, nullptr, &size, &type,
                           name);
        std::string n(name);
        if (n.size() > 3 && n.substr(n.size() - 3) == "[0]") n.resize(n.size() - 3);
        types[n] = type;
    }

    // Resources: textures at units from 4 on, as the manifest describes them.
    int unit = 4;
    bool environment = false;  // the export holds environment maps/tables
    for (const auto& r : manifest.at("resources")) {
        if (r.contains("used_by")) continue;  // a variant's resource
        const std::string format = r.at("format");
        const int w = r.at("width"), h = r.at("height");
        const std::string data = slurp(dir + "/" + r.at("file").get<std::string>());
        // Formats: float R/RG/RGB/RGBA, and RG32UI (wang2020's quadtree nodes,
        // raw uint32 pairs: an integer texture, read with texelFetch).
        GLenum internal = GL_RGBA32F, fmt = GL_RGBA, type = GL_FLOAT;
        if (format == "R32F") internal = GL_R32F, fmt = GL_RED;
        if (format == "RG32F") internal = GL_RG32F, fmt = GL_RG;
        if (format == "RGB32F") internal = GL_RGB32F, fmt = GL_RGB;
        if (format == "RG32UI") internal = GL_RG32UI, fmt = GL_RG_INTEGER, type = GL_UNSIGNED_INT;
        if (r.value("mipmaps", false))
            die(r.at("file").get<std::string>() + ": mipmaps not handled");
        // "layers": a 2D array texture (kneiphof2025's prefiltered maps, one
        // roughness per layer), layer after layer in the file.
        const int layers = r.value("layers", 0);
        GLuint tex = 0;
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        if (layers > 0) {
            glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &tex);
            glTextureStorage3D(tex, 1, internal, w, h, layers);
            glTextureSubImage3D(tex, 0, 0, 0, 0, w, h, layers, fmt, type, data.data());
        } else {
            glCreateTextures(GL_TEXTURE_2D, 1, &tex);
            glTextureStorage2D(tex, 1, internal, w, h);
            glTextureSubImage2D(tex, 0, 0, 0, w, h, fmt, type, data.data());
        }
        const GLint filter = r.at("filter") == "linear" ? GL_LINEAR : GL_NEAREST;
        glTextureParameteri(tex, GL_TEXTURE_MIN_FILTER, filter);
        glTextureParameteri(tex, GL_TEXTURE_MAG_FILTER, filter);
        const std::string wrap = r.at("wrap");
        const GLint wrap_s =
            wrap == "repeat" || wrap == "repeat_s_clamp_t" ? GL_REPEAT : GL_CLAMP_TO_EDGE;
        const GLint wrap_t = wrap == "repeat" ? GL_REPEAT : GL_CLAMP_TO_EDGE;
        glTextureParameteri(tex, GL_TEXTURE_WRAP_S, wrap_s);
        glTextureParameteri(tex, GL_TEXTURE_WRAP_T, wrap_t);
        // A resource made for an environment (kneiphof2025's maps, wang2020's
        // prefiltered table): the model's environment lighting is on.
        if (r.contains("environment")) environment = true;
        glBindTextureUnit(static_cast<GLuint>(unit), tex);
        glProgramUniform1i(
            program, glGetUniformLocation(program, r.at("uniform").get<std::string>().c_str()),
            unit);
        if (r.contains("uniforms"))
            for (const auto& [name, value] : r.at("uniforms").items())
                set_uniform(program, types, name, value);
        ++unit;
    }
    // The export's per-pixel input textures: a density map when given, its
    // texels N = exp(ln N) (a footprint's expected count is N's mean over
    // it) with a mip chain of box means (glGenerateMipmap on a power-of-two
    // map), read by the export's own footprint filter. The samplers of the
    // other inputs point at the same unit (their mask bits are 0).
    int input_mask = 0;
    if (argc >= 8 && std::string(argv[7]) != "-") {
        int mw = 0, mh = 0;
        std::vector<float> n = read_pfm_channel(argv[7], &mw, &mh);
        for (float& v : n) v = std::exp(v);
        glBindTextureUnit(static_cast<GLuint>(unit), mipmapped_texture(n, mw, mh, 1));
        input_mask |= 1;  // GLINT_INPUT_DENSITY
    }
    for (const char* name :
         {"u_input_density", "u_input_alpha", "u_input_color", "u_input_base_albedo",
          "u_input_normal_slopes", "u_input_normal_cross"})
        glProgramUniform1i(program, glGetUniformLocation(program, name), unit);
    // A normal map: its LEAN chain on the next unit, and its s_x s_y chain on
    // the one after where the model reads the slopes' correlation (the
    // manifest lists the input normal_map_cross).
    if (argc == 9) {
        int nw = 0, nh = 0, channels = 0;
        const std::vector<float> normals = read_pfm(argv[8], &nw, &nh, &channels);
        if (channels != 3) die(std::string(argv[8]) + ": a normal map holds RGB = (x, y, z)");
        bool reads_cross = false;
        for (const auto& input : manifest.at("inputs").at("textures"))
            reads_cross = reads_cross || input.at("key") == "normal_map_cross";
        std::vector<float> cross;
        glBindTextureUnit(
            static_cast<GLuint>(unit + 1),
            mipmapped_texture(lean_map(normals, nw, nh, reads_cross ? &cross : nullptr), nw, nh,
                              4));
        glProgramUniform1i(program, glGetUniformLocation(program, "u_input_normal_slopes"),
                           unit + 1);
        input_mask |= 1 << 4;  // GLINT_INPUT_NORMAL
        if (reads_cross) {
            glBindTextureUnit(static_cast<GLuint>(unit + 2), mipmapped_texture(cross, nw, nh, 1));
            glProgramUniform1i(program, glGetUniformLocation(program, "u_input_normal_cross"),
                               unit + 2);
            input_mask |= 1 << 5;  // GLINT_INPUT_NORMAL_CROSS
        }
    }
    set_uniform(program, types, "u_input_texture_mask", input_mask);
    const float identity[4] = {1, 0, 0, 1};
    for (int i = 0; i < 5; ++i)
        glProgramUniformMatrix2fv(
            program,
            glGetUniformLocation(program,
                                 ("u_input_texture_linear[" + std::to_string(i) + "]").c_str()),
            1, GL_FALSE, identity);

    // The model's parameters at the exported material's values (`value`; the
    // descriptor's `default` without --scene).
    for (const auto& p : manifest.at("parameters")) {
        if (!p.contains("uniform")) {
            std::fprintf(stderr, "minimal_host: %s.%s is host-side; left at the shader's default\n",
                         model.c_str(), p.at("key").get<std::string>().c_str());
            continue;
        }
        set_uniform(program, types, p.at("uniform"), p.value("value", p.at("default")));
    }
    // Uniforms the renderer derives from parameters, precomputed by the export.
    for (const auto& u : manifest.at("derived_uniforms"))
        set_uniform(program, types, u.at("uniform"), u.at("value"));

    // PLANE_25: camera 25 degrees above an 8 x 8 quad (uv scale 8), fov 45.
    const float pi = 3.14159265358979f;
    const float e = 25.0f * pi / 180.0f;
    const Vec3 eye{0.0f, 3.0f * std::sin(e), 3.0f * std::cos(e)};
    // Depth range from the quad's bounding sphere (radius 4 sqrt 2), as glintlab's renderer.
    const float radius = std::sqrt(32.0f);
    const float along = std::sqrt(dot(eye, eye));
    const float far_plane = along + radius * 1.01f;
    const float near_plane = std::fmax(along - radius * 1.01f, far_plane * 1e-5f);
    const Mat4 vp = multiply(
        perspective(45.0f * pi / 180.0f, static_cast<float>(width) / static_cast<float>(height),
                    near_plane, far_plane),
        look_at(eye, {0, 0, 0}, {0, 1, 0}));
    glProgramUniformMatrix4fv(program, glGetUniformLocation(program, "u_view_projection"), 1,
                              GL_FALSE, vp.m);
    set_uniform(program, types, "u_eye", {eye.x, eye.y, eye.z});
    // Material: the manifest's (the scene material it was exported from;
    // PLANE_25's is Beckmann alpha 0.3 with silver conductor Fresnel), ln N
    // from the command line if given.
    for (const auto& [name, value] : manifest.at("material").at("uniforms").items())
        set_uniform(program, types, name, value);
    if (argc >= 7) set_uniform(program, types, "u_glint_log_density", log_density);
    // One directional light towards (0.3, 0.8, 0.5), irradiance 2.
    const Vec3 l = normalize({0.3f, 0.8f, 0.5f});
    set_uniform(program, types, "u_directional_count", 1);
    set_uniform(program, types, "u_directional_direction", {l.x, l.y, l.z});
    set_uniform(program, types, "u_directional_irradiance", {2.0f, 2.0f, 2.0f});
    set_uniform(program, types, "u_point_count", 0);
    set_uniform(program, types, "u_environment_on", environment);
    // The quad's v runs along n x t (dp/dv = (0, 0, -1) below), so glTF's
    // bitangent, which points up the image (against dp/dv), is -(n x t): a
    // normal map's tangent w is -1 on it.
    set_uniform(program, types, "u_input_uv_mirrored", true);

    // The quad: y = 0, normal +y, uv (0,0) at (-4, 0, 4), dp/du = (1, 0, 0).
    const float v[] = {
        -4, 0, 4,  0, 1, 0, 0, 0, 1, 0, 0,  //
        4,  0, 4,  0, 1, 0, 8, 0, 1, 0, 0,  //
        4,  0, -4, 0, 1, 0, 8, 8, 1, 0, 0,  //
        -4, 0, -4, 0, 1, 0, 0, 8, 1, 0, 0,
    };
    const GLuint indices[] = {0, 1, 2, 0, 2, 3};
    GLuint vbo = 0, ibo = 0, vao = 0;
    glCreateBuffers(1, &vbo);
    glNamedBufferStorage(vbo, sizeof v, v, 0);
    glCreateBuffers(1, &ibo);
    glNamedBufferStorage(ibo, sizeof indices, indices, 0);
    glCreateVertexArrays(1, &vao);
    glVertexArrayVertexBuffer(vao, 0, vbo, 0, 11 * sizeof(float));
    glVertexArrayElementBuffer(vao, ibo);
    const int sizes[] = {3, 3, 2, 3}, offsets[] = {0, 3, 6, 8};
    for (GLuint a = 0; a < 4; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, sizes[a], GL_FLOAT, GL_FALSE,
                                  static_cast<GLuint>(offsets[a] * sizeof(float)));
        glVertexArrayAttribBinding(vao, a, 0);
    }

    // A linear RGBA32F target: the exported shader writes radiance, not sRGB.
    GLuint color = 0, depth = 0, fbo = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &color);
    glTextureStorage2D(color, 1, GL_RGBA32F, width, height);
    glCreateRenderbuffers(1, &depth);
    glNamedRenderbufferStorage(depth, GL_DEPTH_COMPONENT32F, width, height);
    glCreateFramebuffers(1, &fbo);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, color, 0);
    glNamedFramebufferRenderbuffer(fbo, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    if (glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        die("framebuffer incomplete");
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, width, height);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(program);
    glBindVertexArray(vao);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_INT, nullptr);

    std::vector<float> rgb(static_cast<size_t>(width) * height * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_RGB, GL_FLOAT, rgb.data());
    if (glGetError() != GL_NO_ERROR) die("OpenGL error");
    write_pfm(out, width, height, rgb);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "minimal_host: %s\n", e.what());
        return 1;
    }
}
