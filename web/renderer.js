// The page's WebGL2 host: geometry upload, the HDR forward pass with the
// exported fragment stage, the environment background, the display pass
// (exposure, sRGB) and read-back. Everything model-specific comes from the
// files of `glintlab export MODEL --lang glsles` (model.js loads them); this
// file only implements the host contract those files document: the vertex
// stage's outputs, u_eye, the light and material uniforms, the resources.

import {FLOATS_PER_VERTEX} from './geometry.js';
import * as m4 from './mat4.js';

// The vertex stage the exported fragment stage expects (its inputs
// v_position, v_normal, v_uv, v_dpdu, all in world space), as the native
// forward pass (realtime/shaders/forward.vert.glsl): the meshes are in world
// space already.
const FORWARD_VERTEX = `#version 300 es
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
`;

const FULLSCREEN_VERTEX = `#version 300 es
out vec2 v_ndc;
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    v_ndc = p * 2.0 - 1.0;
    gl_Position = vec4(v_ndc, 1.0, 1.0);
}
`;

// The environment seen along each camera ray (the native background pass,
// realtime/shaders/background.frag.glsl): lat-long map, theta from +y,
// phi = atan(x, -z) - rotation, u = 0.5 + phi / 2 pi, bilinear, no mipmaps.
const BACKGROUND_FRAGMENT = `#version 300 es
precision highp float;
in vec2 v_ndc;
out vec4 o_radiance;
uniform mat4 u_inverse_view_projection;
uniform float u_environment_scale;
uniform float u_environment_rotation;
uniform highp sampler2D u_environment;
void main() {
    vec4 a = u_inverse_view_projection * vec4(v_ndc, -1.0, 1.0);
    vec4 c = u_inverse_view_projection * vec4(v_ndc, 1.0, 1.0);
    vec3 d = normalize(c.xyz / c.w - a.xyz / a.w);
    float theta = acos(clamp(d.y, -1.0, 1.0));
    float phi = atan(d.x, -d.z) - u_environment_rotation;
    float u = 0.5 + phi * 0.15915494309189535;
    u -= floor(u);
    vec3 env = textureLod(u_environment, vec2(u, theta * 0.3183098861837907), 0.0).rgb;
    // alpha 0: not a surface (the page's read-back uses alpha as the
    // coverage of the shapes; the exported stage writes 1).
    o_radiance = vec4(u_environment_scale * env, 0.0);
}
`;

// Display: 2^exposure, sRGB encode (IEC 61966-2-1), clamp — the convention
// of the native PNG preview and viewer (realtime/shaders/tonemap.frag.glsl).
const DISPLAY_FRAGMENT = `#version 300 es
precision highp float;
out vec4 o_color;
uniform highp sampler2D u_hdr;
uniform float u_exposure_scale;
float srgb_encode(float x) {
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}
void main() {
    vec3 c = texelFetch(u_hdr, ivec2(gl_FragCoord.xy), 0).rgb * u_exposure_scale;
    o_color = vec4(clamp(srgb_encode(c.r), 0.0, 1.0), clamp(srgb_encode(c.g), 0.0, 1.0),
                   clamp(srgb_encode(c.b), 0.0, 1.0), 1.0);
}
`;

// One axis of wang2020's §4.4 glint blur (Wang et al. 2020, "Gaussian
// Blurring"; the native post pass, glints/wang2020/wang2020_blur.comp.glsl):
// a normalised Gaussian of 2 r + 1 taps, sigma = taps / 6, borders clamped
// to the edge. With u_add the source u_base (the frame without the glint
// layer) is added: the last pass composites.
const GLINT_BLUR_FRAGMENT = `#version 300 es
precision highp float;
out vec4 o_radiance;
uniform highp sampler2D u_src;
uniform highp sampler2D u_base;
uniform float u_taps[16];
uniform int u_radius;
uniform ivec2 u_axis;
uniform bool u_add;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(u_src, 0);
    vec3 sum = vec3(0.0);
    for (int k = -15; k <= 15; ++k) {
        if (k < -u_radius || k > u_radius) continue;
        ivec2 q = clamp(p + k * u_axis, ivec2(0), size - 1);
        sum += u_taps[k + u_radius] * texelFetch(u_src, q, 0).rgb;
    }
    vec4 base = u_add ? texelFetch(u_base, p, 0) : vec4(0.0);
    o_radiance = vec4(base.rgb + sum, base.a);
}
`;

// The normalised taps of a Gaussian of `size` taps (odd), sigma = size / 6
// (wang2020_postprocess.h).
export function gaussianTaps(size) {
  const r = (size - 1) / 2, sigma = size / 6;
  const taps = [];
  for (let i = -r; i <= r; ++i) taps.push(Math.exp(-0.5 * i * i / (sigma * sigma)));
  const sum = taps.reduce((a, b) => a + b, 0);
  return taps.map((t) => t / sum);
}

// Numbered source lines around the ones a compile log names (ANGLE writes
// "ERROR: 0:LINE: ...").
function annotateLog(source, log) {
  const lines = source.split('\n');
  const out = [log.trim()];
  for (const match of log.matchAll(/ERROR: \d+:(\d+)/g)) {
    const n = Number(match[1]);
    for (let i = Math.max(1, n - 2); i <= Math.min(lines.length, n + 2); ++i)
      out.push(`${String(i).padStart(5)}| ${lines[i - 1]}`);
  }
  return out.join('\n');
}

export class Renderer {
  constructor(canvas) {
    this.canvas = canvas;
    const gl = canvas.getContext('webgl2', {
      antialias: false, alpha: false, depth: false, preserveDrawingBuffer: true,
    });
    if (!gl) throw new Error('this browser has no WebGL2 context');
    this.gl = gl;
    // Rendering to RGBA32F needs EXT_color_buffer_float; filtering float
    // textures (the environment) needs OES_texture_float_linear.
    if (!gl.getExtension('EXT_color_buffer_float'))
      throw new Error('WebGL2 without EXT_color_buffer_float: no float render target');
    this.floatLinear = !!gl.getExtension('OES_texture_float_linear');
    this.timerExt = gl.getExtension('EXT_disjoint_timer_query_webgl2');
    this.queries = [];
    this.gpuMs = null;
    this.background = this.program(FULLSCREEN_VERTEX, BACKGROUND_FRAGMENT, 'background');
    this.display = this.program(FULLSCREEN_VERTEX, DISPLAY_FRAGMENT, 'display');
    this.glintBlur = this.program(FULLSCREEN_VERTEX, GLINT_BLUR_FRAGMENT, 'glint blur');
    this.emptyVao = gl.createVertexArray();
    this.forward = null;
    this.mesh = null;
    this.environment = null;
    this.width = 0;
    this.height = 0;
  }

  compile(type, source, label) {
    const gl = this.gl;
    const s = gl.createShader(type);
    gl.shaderSource(s, source);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) {
      const log = gl.getShaderInfoLog(s) || '(no log)';
      gl.deleteShader(s);
      throw new Error(`${label}: compile error\n${annotateLog(source, log)}`);
    }
    return s;
  }

  // A linked program with its active uniforms (name -> {location, type, size}).
  program(vertexSource, fragmentSource, label) {
    const gl = this.gl;
    const vs = this.compile(gl.VERTEX_SHADER, vertexSource, `${label} (vertex)`);
    const fs = this.compile(gl.FRAGMENT_SHADER, fragmentSource, `${label} (fragment)`);
    const p = gl.createProgram();
    gl.attachShader(p, vs);
    gl.attachShader(p, fs);
    gl.linkProgram(p);
    gl.deleteShader(vs);
    gl.deleteShader(fs);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS))
      throw new Error(`${label}: link error\n${gl.getProgramInfoLog(p)}`);
    const uniforms = new Map();
    const n = gl.getProgramParameter(p, gl.ACTIVE_UNIFORMS);
    for (let i = 0; i < n; ++i) {
      const info = gl.getActiveUniform(p, i);
      const name = info.name.replace(/\[0\]$/, '');
      uniforms.set(name, {location: gl.getUniformLocation(p, info.name), type: info.type,
                          size: info.size});
    }
    return {handle: p, uniforms, label};
  }

  // Sets uniform `name` of program `prog` from a number, boolean or array
  // (arrays of vectors flattened); the GL type decides the call. Uniforms
  // the compiler removed are skipped; returns whether it was set.
  setUniform(prog, name, value) {
    const gl = this.gl;
    const u = prog.uniforms.get(name);
    if (!u) return false;
    const v = Array.isArray(value) || ArrayBuffer.isView(value) ? Array.from(value, Number)
                                                               : [Number(value)];
    gl.useProgram(prog.handle);
    switch (u.type) {
      case gl.FLOAT: gl.uniform1fv(u.location, v); break;
      case gl.FLOAT_VEC2: gl.uniform2fv(u.location, v); break;
      case gl.FLOAT_VEC3: gl.uniform3fv(u.location, v); break;
      case gl.FLOAT_VEC4: gl.uniform4fv(u.location, v); break;
      case gl.INT: case gl.BOOL: case gl.SAMPLER_2D: case gl.SAMPLER_3D:
      case gl.SAMPLER_2D_ARRAY: case gl.SAMPLER_CUBE: case gl.INT_SAMPLER_2D:
      case gl.UNSIGNED_INT_SAMPLER_2D: case gl.INT_SAMPLER_2D_ARRAY:
      case gl.UNSIGNED_INT_SAMPLER_2D_ARRAY: case gl.SAMPLER_2D_SHADOW:
        gl.uniform1iv(u.location, v.map((x) => Math.trunc(x))); break;
      case gl.INT_VEC2: case gl.BOOL_VEC2: gl.uniform2iv(u.location, v); break;
      case gl.INT_VEC3: case gl.BOOL_VEC3: gl.uniform3iv(u.location, v); break;
      case gl.INT_VEC4: case gl.BOOL_VEC4: gl.uniform4iv(u.location, v); break;
      case gl.UNSIGNED_INT: gl.uniform1uiv(u.location, v.map((x) => x >>> 0)); break;
      case gl.UNSIGNED_INT_VEC2: gl.uniform2uiv(u.location, v); break;
      case gl.UNSIGNED_INT_VEC3: gl.uniform3uiv(u.location, v); break;
      case gl.UNSIGNED_INT_VEC4: gl.uniform4uiv(u.location, v); break;
      case gl.FLOAT_MAT2: gl.uniformMatrix2fv(u.location, false, v); break;
      case gl.FLOAT_MAT4: gl.uniformMatrix4fv(u.location, false, v); break;
      default: throw new Error(`${prog.label}: uniform ${name} has an unsupported type 0x${u.type.toString(16)}`);
    }
    return true;
  }

  // A forward program: the page's vertex stage + the exported fragment
  // stage (the caller keeps it and sets this.forward to draw with it).
  forwardProgram(fragmentSource, label) {
    return this.program(FORWARD_VERTEX, fragmentSource, label);
  }

  setMesh(mesh) {
    const gl = this.gl;
    if (this.mesh) {
      gl.deleteVertexArray(this.mesh.vao);
      gl.deleteBuffer(this.mesh.vbo);
      gl.deleteBuffer(this.mesh.ibo);
    }
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    const vbo = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, vbo);
    gl.bufferData(gl.ARRAY_BUFFER, mesh.vertices, gl.STATIC_DRAW);
    const stride = FLOATS_PER_VERTEX * 4;
    [[0, 3, 0], [1, 3, 3], [2, 2, 6], [3, 3, 8]].forEach(([loc, n, offset]) => {
      gl.enableVertexAttribArray(loc);
      gl.vertexAttribPointer(loc, n, gl.FLOAT, false, stride, offset * 4);
    });
    const ibo = gl.createBuffer();
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, ibo);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, mesh.indices, gl.STATIC_DRAW);
    gl.bindVertexArray(null);
    // Draw parts (a glTF asset: one per material), each drawn with its own
    // resources: the whole index list for the page's shapes.
    const parts = mesh.parts ?? [{first: 0, count: mesh.indices.length}];
    this.mesh = {vao, vbo, ibo, parts, bounds: mesh.bounds};
  }

  // A texture from raw data: `format` RGBA32F | RGB32F | RG32F | R32F
  // (Float32Array) or RG32UI (Uint32Array, unfiltered), 2D, or 2D array / 3D
  // with `depth`.
  floatTexture({data, width, height, depth = 0, format = 'RGBA32F', target = '2d',
                filter = 'linear', wrap = 'clamp', mipmaps = false}) {
    const gl = this.gl;
    const formats = {
      RGBA32F: [gl.RGBA32F, gl.RGBA, gl.FLOAT], RGB32F: [gl.RGB32F, gl.RGB, gl.FLOAT],
      RG32F: [gl.RG32F, gl.RG, gl.FLOAT], R32F: [gl.R32F, gl.RED, gl.FLOAT],
      RG32UI: [gl.RG32UI, gl.RG_INTEGER, gl.UNSIGNED_INT],
    };
    if (!formats[format]) throw new Error(`texture format ${format} is not one of ${Object.keys(formats)}`);
    const [internal, fmt, type] = formats[format];
    const integer = type === gl.UNSIGNED_INT;
    const t = gl.createTexture();
    const glTarget = target === '2d' ? gl.TEXTURE_2D : target === '3d' ? gl.TEXTURE_3D
                                                                       : gl.TEXTURE_2D_ARRAY;
    gl.bindTexture(glTarget, t);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    if (glTarget === gl.TEXTURE_2D)
      gl.texImage2D(glTarget, 0, internal, width, height, 0, fmt, type, data);
    else
      gl.texImage3D(glTarget, 0, internal, width, height, depth, 0, fmt, type, data);
    // Integer textures are never filtered; float ones need OES_texture_float_linear.
    const linear = filter === 'linear' && this.floatLinear && !integer;
    const mips = mipmaps && this.floatLinear && !integer;
    if (mips) gl.generateMipmap(glTarget);
    gl.texParameteri(glTarget, gl.TEXTURE_MIN_FILTER,
                     mips ? gl.LINEAR_MIPMAP_LINEAR : linear ? gl.LINEAR : gl.NEAREST);
    gl.texParameteri(glTarget, gl.TEXTURE_MAG_FILTER, linear ? gl.LINEAR : gl.NEAREST);
    const wrapS = wrap === 'repeat' || wrap === 'repeat_u' ? gl.REPEAT : gl.CLAMP_TO_EDGE;
    const wrapT = wrap === 'repeat' ? gl.REPEAT : gl.CLAMP_TO_EDGE;
    gl.texParameteri(glTarget, gl.TEXTURE_WRAP_S, wrapS);
    gl.texParameteri(glTarget, gl.TEXTURE_WRAP_T, wrapT);
    gl.texParameteri(glTarget, gl.TEXTURE_WRAP_R, wrapT);
    return {texture: t, target: glTarget};
  }

  resize(width, height) {
    if (width === this.width && height === this.height && this.fbo) return;
    const gl = this.gl;
    this.canvas.width = width;
    this.canvas.height = height;
    if (this.fbo) {
      for (const t of this.targets) {
        gl.deleteFramebuffer(t.fbo);
        gl.deleteTexture(t.texture);
      }
      gl.deleteRenderbuffer(this.depth);
    }
    this.depth = gl.createRenderbuffer();
    gl.bindRenderbuffer(gl.RENDERBUFFER, this.depth);
    gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, width, height);
    // RGBA32F targets: the frame; wang2020's glint layer (the shapes'
    // environment glints, drawn with the same depth buffer), its blur along
    // x, and the composite of the frame and the blurred layer.
    const target = (withDepth) => {
      const texture = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA32F, width, height);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
      const fbo = gl.createFramebuffer();
      gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
      if (withDepth)
        gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, this.depth);
      const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      if (status !== gl.FRAMEBUFFER_COMPLETE)
        throw new Error(`RGBA32F framebuffer incomplete (0x${status.toString(16)})`);
      return {texture, fbo};
    };
    const frame = target(true), layer = target(true), blurX = target(false), composite = target(false);
    this.targets = [frame, layer, blurX, composite];
    Object.assign(this, {frame, layer, blurX, composite});
    this.fbo = frame.fbo;
    this.hdr = frame.texture;
    this.output = frame;  // the target the last frame ended in
    this.width = width;
    this.height = height;
  }

  // The camera matrices of the native renderer (gpu_renderer.cpp render):
  // glm::lookAt, glm::perspective with near/far around the scene's bounding
  // sphere.
  viewProjection(camera) {
    const {centre, radius} = this.mesh.bounds;
    const forward = m4.normalize(m4.sub(camera.target, camera.eye));
    const along = m4.dot(m4.sub(centre, camera.eye), forward);
    const far = Math.max(along + radius * 1.01, 1e-3);
    const near = Math.max(along - radius * 1.01, far * 1e-5);
    const proj = m4.perspective(camera.fovDeg * Math.PI / 180, this.width / this.height, near, far);
    return m4.multiply(proj, m4.lookAt(camera.eye, camera.target, [0, 1, 0]));
  }

  // One frame: background (environment or black), the forward pass into the
  // RGBA32F target, the display pass onto the canvas. `bindResources(r,
  // prog, part)` binds the model's textures and sets its uniforms on the
  // forward program for `part`: 'all' the lights and the environment,
  // 'lights' without the environment, 'environment' only it.
  // `glintBlurTaps` > 1 (wang2020 lit by an environment, one sample per
  // pixel: docs/WEB.md) runs §4.4's glint blur as the native renderer
  // does: the environment's glints go to a layer of their own, which is
  // blurred by a `glintBlurTaps`-tap Gaussian and added to the frame.
  // (`environment` is the background; a model may be lit by an
  // environment whose map the export left out, as wang2020's tables.)
  render({camera, exposure, environment, bindResources, glintBlurTaps = 1}) {
    const gl = this.gl;
    this.pollTimer();
    let query = null;
    if (this.timerExt && this.queries.length < 4) {
      query = gl.createQuery();
      gl.beginQuery(this.timerExt.TIME_ELAPSED_EXT, query);
    }
    const vp = this.viewProjection(camera);
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.fbo);
    gl.viewport(0, 0, this.width, this.height);
    gl.disable(gl.BLEND);
    gl.disable(gl.CULL_FACE);
    gl.disable(gl.DEPTH_TEST);
    gl.clearColor(0, 0, 0, 0);
    gl.clear(gl.COLOR_BUFFER_BIT);
    if (environment) {
      const bg = this.background;
      this.setUniform(bg, 'u_inverse_view_projection', m4.invert(vp));
      this.setUniform(bg, 'u_environment_scale', environment.scale);
      this.setUniform(bg, 'u_environment_rotation', environment.rotation);
      this.setUniform(bg, 'u_environment', 0);
      gl.activeTexture(gl.TEXTURE0);
      gl.bindTexture(gl.TEXTURE_2D, environment.texture.texture);
      gl.useProgram(bg.handle);
      gl.bindVertexArray(this.emptyVao);
      gl.drawArrays(gl.TRIANGLES, 0, 3);
    }
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LESS);
    gl.clearDepth(1);
    gl.clear(gl.DEPTH_BUFFER_BIT);
    const f = this.forward;
    const layered = glintBlurTaps > 1;
    const drawShapes = (part) => {
      this.setUniform(f, 'u_view_projection', vp);
      this.setUniform(f, 'u_eye', camera.eye);
      this.mesh.parts.forEach((p, k) => {
        bindResources(this, f, part, k);
        gl.useProgram(f.handle);
        gl.bindVertexArray(this.mesh.vao);
        gl.drawElements(gl.TRIANGLES, p.count, gl.UNSIGNED_INT, 4 * p.first);
        gl.bindVertexArray(null);
      });
    };
    drawShapes(layered ? 'lights' : 'all');
    this.output = this.frame;
    if (layered) {
      // The glint layer: the environment's glints alone, on black.
      gl.bindFramebuffer(gl.FRAMEBUFFER, this.layer.fbo);
      gl.clearColor(0, 0, 0, 0);
      gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
      drawShapes('environment');
      gl.disable(gl.DEPTH_TEST);
      const taps = gaussianTaps(glintBlurTaps);
      const b = this.glintBlur;
      this.setUniform(b, 'u_taps', taps.concat(new Array(16 - taps.length).fill(0)));
      this.setUniform(b, 'u_radius', (taps.length - 1) / 2);
      this.setUniform(b, 'u_src', 0);
      this.setUniform(b, 'u_base', 1);
      const pass = (src, dst, axis, add) => {
        this.setUniform(b, 'u_axis', axis);
        this.setUniform(b, 'u_add', add ? 1 : 0);
        gl.bindFramebuffer(gl.FRAMEBUFFER, dst.fbo);
        gl.activeTexture(gl.TEXTURE0);
        gl.bindTexture(gl.TEXTURE_2D, src.texture);
        gl.activeTexture(gl.TEXTURE1);
        gl.bindTexture(gl.TEXTURE_2D, this.frame.texture);
        gl.useProgram(b.handle);
        gl.bindVertexArray(this.emptyVao);
        gl.drawArrays(gl.TRIANGLES, 0, 3);
        gl.bindVertexArray(null);
      };
      pass(this.layer, this.blurX, [1, 0], false);
      pass(this.blurX, this.composite, [0, 1], true);
      gl.activeTexture(gl.TEXTURE0);
      this.output = this.composite;
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.disable(gl.DEPTH_TEST);
    gl.viewport(0, 0, this.width, this.height);
    this.setUniform(this.display, 'u_exposure_scale', Math.pow(2, exposure));
    this.setUniform(this.display, 'u_hdr', 0);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.output.texture);
    gl.useProgram(this.display.handle);
    gl.bindVertexArray(this.emptyVao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindVertexArray(null);
    if (query) {
      gl.endQuery(this.timerExt.TIME_ELAPSED_EXT);
      this.queries.push(query);
    }
  }

  // GPU time of the oldest finished frame (EXT_disjoint_timer_query_webgl2).
  pollTimer() {
    const gl = this.gl;
    while (this.queries.length) {
      const q = this.queries[0];
      if (!gl.getQueryParameter(q, gl.QUERY_RESULT_AVAILABLE)) break;
      const disjoint = gl.getParameter(this.timerExt.GPU_DISJOINT_EXT);
      if (!disjoint) this.gpuMs = gl.getQueryParameter(q, gl.QUERY_RESULT) / 1e6;
      gl.deleteQuery(q);
      this.queries.shift();
    }
  }

  // The linear HDR frame, rows top to bottom (as the native Image), RGBA
  // with alpha 1 where a shape was drawn, 0 on the background.
  readHdr() {
    const gl = this.gl;
    const w = this.width, h = this.height;
    const rgba = new Float32Array(w * h * 4);
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.output.fbo);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.FLOAT, rgba);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    const out = new Float32Array(w * h * 4);
    for (let y = 0; y < h; ++y)  // GL rows go up
      out.set(rgba.subarray((h - 1 - y) * w * 4, (h - y) * w * 4), y * w * 4);
    return out;
  }
}
