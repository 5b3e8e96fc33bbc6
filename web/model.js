// Loads one model's files written by `glintlab export MODEL --lang glsles`
// (docs/INTEGRATION.md "Manifest"): the manifest, the flattened GLSL ES
// fragment stage and the raw float32 resources, and binds them for a frame.
// The page never carries model code: what it adds is the host side the
// export documents (which scene parameter goes to which uniform, the
// host-computed uniforms listed below).

import {materialTextures} from './material_maps.js';
import {oncePerContext, uploadMipmapped} from './mip_texture.js';
import {leanTexture} from './normal_map.js';

// Model parameters the exported shader does not read under their own name
// `u_<model>_<key>`: the host computes a uniform from them (as the native
// hooks do, glints/<model>/<model>_gpu.cpp), or they were applied when the
// files were exported (`baked`: changing them means exporting again).

const HOST_PARAMS = {
  chermain2020: {
    slope_correlation: {uniform: 'u_chermain2020_correlated', value: (v) => (v === 'chermain2021' ? 1 : 0)},
    masking: {uniform: 'u_glint_g2', value: (v) => (v === 'v_cavity' ? 1 : 0)},
  },
  deliot2023: {
    gaussian: {uniform: 'u_deliot2023_conditional', value: (v) => (v === 'conditional' ? 1 : 0)},
  },
  kneiphof2025: {
    levels: {baked: 'K of the prefiltered maps (glintlab export --env)'},
    black_level: {baked: 'black level of the prefiltered maps (glintlab export --env)'},
    variant: {uniform: 'u_kneiphof2025_wang2020_style', value: (v) => (v === 'wang2020_style' ? 1 : 0)},
    gaussian: {uniform: 'u_kneiphof2025_conditional', value: (v) => (v === 'conditional' ? 1 : 0)},
    // KNEIPHOF2025_SMOOTH_*: as_published / split_sum 0, lobe 1, lobe_sun 2.
    smooth: {uniform: 'u_kneiphof2025_smooth',
             value: (v) => ({lobe: 1, lobe_sun: 2}[v] ?? 0)},
    // The solid angle of the cone of half-angle gamma: 2 pi (1 - cos gamma).
    gamma_deg: {uniform: 'u_kneiphof2025_gamma_solid_angle',
                value: (v) => 2 * Math.PI * (1 - Math.cos(v * Math.PI / 180))},
  },
  // Every wang2020 parameter shapes its tables (DPF, quadtree, prefilter,
  // cone average), exported for the default material. `blur` and
  // `glint_blur` choose the page's §4.4 glint blur (renderer.js; the page
  // renders one sample per pixel, so "auto" blurs). Directional occlusion
  // is the renderer's occlusion ray: the page's one convex or flat shape
  // never occludes its own mirror directions, so its 9-tap blur of the
  // visibility is the identity here and the page has none.
  wang2020: Object.fromEntries(
      ['gamma_deg', 'depth', 'dpf_theta', 'dpf_phi', 'prefilter_samples', 'micro', 'prefilter']
          .map((k) => [k, {baked: 'built into the exported tables'}])
          .concat([['directional_occlusion',
                    {baked: 'the renderer\'s occlusion ray (the page\'s one shape never occludes its mirror directions)'}],
                   ['blur', {pagePass: true}], ['glint_blur', {pagePass: true}]])),
};

// Taps of the page's §4.4 glint blur for wang2020 (Wang et al. 2020;
// docs/MODELS.md wang2020, Post-process): 3 under "auto" (the page renders
// one sample per pixel) and "as_published", 1 (none) under "none" or with
// "blur" off. Other models: 1.
export function glintBlurTaps(model, params) {
  if (model.name !== 'wang2020') return 1;
  const value = (key) => params[key] ?? model.parameters.find((p) => p.key === key)?.default;
  if (value('blur') === false) return 1;
  return value('glint_blur') === 'none' ? 1 : 3;
}

// Material inputs a model's export fixes (its tables were built for them):
// the manifest's resource uniforms of these names.
export const MATERIAL_UNIFORMS = {
  u_glint_alpha: 'roughness', u_glint_log_density: 'log_density', u_glint_seed: 'seed',
};

// Fresnel reflectance at normal incidence of the material's Fresnel
// (kneiphof2025_f0 of glints/kneiphof2025/kneiphof2025.cpp: the host input
// u_kneiphof2025_f0 of the kneiphof2025 export).
function fresnelF0(material) {
  const f = material.fresnel;
  if (f.type === 'schlick') return f.f0;
  if (f.type === 'dielectric') {
    const r = (f.eta - 1) / (f.eta + 1);
    return [r * r, r * r, r * r];
  }
  if (f.type === 'conductor')
    return f.eta.map((eta, c) => {
      const k = f.k[c];
      return ((eta - 1) ** 2 + k * k) / ((eta + 1) ** 2 + k * k);
    });
  return [1, 1, 1];
}

const FRESNEL_MODE = {none: 0, schlick: 1, conductor: 2, dielectric: 3};

// The page's Fresnel description of the u_fresnel_* uniforms of a manifest.
function fresnelOfUniforms(u) {
  const type = Object.keys(FRESNEL_MODE).find((k) => FRESNEL_MODE[k] === u.u_fresnel_mode);
  if (!type) throw new Error(`manifest: u_fresnel_mode ${u.u_fresnel_mode} is not 0-3`);
  const f = {type};
  if (type === 'schlick') f.f0 = u.u_fresnel_f0.slice();
  if (type === 'dielectric') f.eta = u.u_fresnel_eta[0];
  if (type === 'conductor') Object.assign(f, {eta: u.u_fresnel_eta.slice(), k: u.u_fresnel_k.slice()});
  return f;
}

// Whether two Fresnel descriptions differ (type, or a value beyond 1e-6).
export function fresnelDiffers(a, b) {
  if (a.type !== b.type) return true;
  const values = (f) => [].concat(f.f0 ?? [], f.eta ?? [], f.k ?? []);
  const va = values(a), vb = values(b);
  return va.length !== vb.length ||
         va.some((v, i) => Math.abs(v - vb[i]) > 1e-6 * Math.max(1, Math.abs(vb[i])));
}

async function fetchOk(url, what) {
  let response;
  try {
    response = await fetch(url);
  } catch (e) {
    throw new Error(`cannot fetch ${what} ${url}: ${e.message}`);
  }
  if (!response.ok)
    throw new Error(`cannot fetch ${what} ${url}: HTTP ${response.status} ` +
                    '(run `make web` to export the models into web/export/)');
  return response;
}

// Parameter descriptors: the manifest's (key, type, default, uniform) with
// the numeric bounds of `glintlab info --json` (export/models.json).
function parameterTable(manifest, info) {
  const bounds = new Map((info?.parameters ?? []).map((p) => [p.key, p]));
  const host = HOST_PARAMS[manifest.model] ?? {};
  return manifest.parameters.map((p) => {
    const b = bounds.get(p.key) ?? {};
    const h = host[p.key] ?? {};
    // An enum switch without a host mapping cannot be set as a number.
    if (p.type === 'enum' && !h.value && !h.baked && !h.pagePass)
      h.baked = 'an enum switch set at export';
    return {
      key: p.key, type: p.type, doc: p.doc, unit: p.unit, range: p.range,
      default: p.default, min: p.min ?? b.min, max: p.max ?? b.max,
      values: p.values ?? b.values, choices: p.choices ?? b.choices,
      uniform: h.baked ? null : h.uniform ?? p.uniform ?? null, value: h.value ?? null,
      baked: h.baked ?? null, pagePass: !!h.pagePass,
    };
  });
}

export class ExportedModel {
  static async load(renderer, base, name, info) {
    const manifestUrl = `${base}/${name}.glsles.manifest.json`;
    const manifest = await (await fetchOk(manifestUrl, 'manifest')).json();
    if (manifest.model !== name || manifest.language !== 'glsles')
      throw new Error(`${manifestUrl}: a manifest of ${manifest.model} (${manifest.language}), ` +
                      `expected ${name} (glsles)`);
    const model = new ExportedModel();
    model.name = name;
    model.base = base;
    model.manifest = manifest;
    // The fragment stages: "default" and the model's option variants
    // (deliot2023's "noise_texture", 000 6.3), compiled on first use.
    model.shaders = manifest.shaders.filter((s) => s.stage === 'fragment');
    model.variants = model.shaders.map((s) => s.variant);
    if (!model.variants.includes('default'))
      throw new Error(`${manifestUrl}: no default fragment shader listed`);
    model.programs = new Map();
    model.parameters = parameterTable(manifest, info);
    model.textures = [];
    model.constants = {};  // uniforms given by the manifest's resources
    // The manifest's derived uniforms (kneiphof2025's bright sources, taken
    // out of the exported maps: map-frame directions, powers, radii, colour).
    model.derived = Object.fromEntries(
        (manifest.derived_uniforms ?? []).map((u) => [u.uniform, u.value]));
    model.environment = null;
    model.fixedMaterial = {};  // material keys the export fixes (wang2020)
    // The input bits the model reads per pixel (the manifest's inputs:
    // wang2020 takes density and roughness as uniforms only).
    model.perPixelInputs = new Set(
        (manifest.inputs?.textures ?? []).filter((i) => i.per_pixel).map((i) => i.bit));
    for (const r of manifest.resources) {
      const bytes = await (await fetchOk(`${base}/${r.file}`, 'resource')).arrayBuffer();
      const data = r.format.endsWith('UI') ? new Uint32Array(bytes) : new Float32Array(bytes);
      const channels = {RGBA32F: 4, RGB32F: 3, RG32F: 2, R32F: 1, RG32UI: 2}[r.format];
      if (!channels) throw new Error(`${r.file}: unsupported format "${r.format}"`);
      const layers = r.layers ?? 1;
      const expected = r.width * r.height * layers * channels;
      if (data.length !== expected)
        throw new Error(`${r.file}: ${data.length} floats, the manifest's ${r.format} ` +
                        `${r.width}x${r.height}x${layers} needs ${expected}`);
      const wrap = {repeat: 'repeat', clamp_to_edge: 'clamp', repeat_s_clamp_t: 'repeat_u'}[r.wrap];
      if (!wrap) throw new Error(`${r.file}: unknown wrap mode "${r.wrap}"`);
      const target = r.target === '2D_ARRAY' ? 'array' : '2d';
      const texture = renderer.floatTexture({
        data, width: r.width, height: r.height, depth: layers, format: r.format, target,
        filter: r.filter, wrap, mipmaps: !!r.mipmaps,
      });
      model.textures.push({uniform: r.uniform, texture});
      Object.assign(model.constants, r.uniforms ?? {});
      for (const [u, key] of Object.entries(MATERIAL_UNIFORMS))
        if (r.uniforms && u in r.uniforms) model.fixedMaterial[key] = r.uniforms[u];
      // wang2020's prefiltered table integrates the material's Fresnel.
      if (r.uniforms && 'u_fresnel_mode' in r.uniforms)
        model.fixedMaterial.fresnel = fresnelOfUniforms(r.uniforms);
      // The prefiltered radiance's layer 0 (sqrt(alpha) = 0: the map
      // itself at the prefilter's resolution) is the page's background.
      if (r.environment && r.uniform === 'kneiphof2025_radiance_layers')
        model.environment = {
          file: r.environment,
          texture: renderer.floatTexture({
            data: data.subarray(0, r.width * r.height * 4), width: r.width, height: r.height,
            format: 'RGBA32F', target: '2d', filter: 'linear', wrap: 'repeat_u',
          }),
        };
    }
    // Whether the export carries environment lighting: kneiphof2025's
    // prefiltered maps, wang2020's prefiltered tables (one zero texel and
    // resolution 1 x 1 x 1 x 1 when exported without --env).
    const res = model.constants.u_wang2020_prefilter_res;
    model.environmentLit = model.environment !== null ||
                           (Array.isArray(res) && res.reduce((a, b) => a * b, 1) > 1);
    return model;
  }

  // The forward program of fragment-stage variant `variant`.
  async program(renderer, variant) {
    if (!this.programs.has(variant)) {
      const shader = this.shaders.find((s) => s.variant === variant);
      if (!shader)
        throw new Error(`${this.name} has no shader variant "${variant}" ` +
                        `(exported: ${this.variants.join(', ')})`);
      const source = await (await fetchOk(`${this.base}/${shader.file}`, 'shader')).text();
      this.programs.set(variant, renderer.forwardProgram(source, shader.file));
    }
    return this.programs.get(variant);
  }

  // Sets every uniform of the forward program for `state` (app.js) and
  // binds the resources; called by Renderer.render before the draw, for
  // `part` of the lighting: 'all', 'lights' (no environment) or
  // 'environment' (only it: wang2020's glint layer).
  bind(renderer, prog, state, part = 'all', asset = null) {
    const gl = renderer.gl;
    const set = (name, value) => renderer.setUniform(prog, name, value);
    const m = state.material;
    set('u_glint_ndf', m.ndf === 'ggx' ? 1 : 0);
    set('u_glint_log_density', m.log_density);
    set('u_glint_seed', m.seed);
    // A glTF asset's part (gltf_asset.js): its material's colour, roughness,
    // base albedo and Fresnel (a map's mean where the model reads no map per
    // pixel), unless the export fixes them (wang2020's tables).
    const am = asset?.material ?? null;
    const maps = am?.maps ?? {};
    const perPixel = (bit, map) => map && this.perPixelInputs.has(bit);
    let color = m.color, alpha = m.roughness;
    if (am && !('color' in this.fixedMaterial))
      color = maps.color && !perPixel(2, maps.color) ? maps.color.mean.slice(0, 3) : am.color;
    if (am && !('roughness' in this.fixedMaterial)) {
      const a = maps.alpha && !perPixel(1, maps.alpha) ? Math.sqrt(maps.alpha.mean[0]) : am.alpha;
      alpha = [a, a];
    }
    set('u_glint_alpha', alpha);
    set('u_glint_color', color);
    // A dielectric asset material: its base colour as the base albedo under
    // its own dielectric Fresnel.
    let baseAlbedo = [0, 0, 0];
    if (am?.baseAlbedo)
      baseAlbedo = maps.baseAlbedo && !perPixel(3, maps.baseAlbedo) ? maps.baseAlbedo.mean.slice(0, 3)
                                                                    : am.baseAlbedo;
    set('u_glint_base_albedo', baseAlbedo);
    const fresnel = am?.fresnel && !('fresnel' in this.fixedMaterial) ? am.fresnel : m.fresnel;
    set('u_fresnel_mode', FRESNEL_MODE[fresnel.type]);
    set('u_fresnel_f0', fresnel.f0 ?? [0, 0, 0]);
    const eta = fresnel.eta ?? 1.5;
    set('u_fresnel_eta', Array.isArray(eta) ? eta : [eta, eta, eta]);
    set('u_fresnel_k', fresnel.k ?? [0, 0, 0]);
    // The height-correlated Smith G2 (the export's header); chermain2020's
    // "masking" parameter sets its V-cavity one (004 Eq. 14-16) below.
    set('u_glint_g2', 0);
    const l = state.light;
    set('u_directional_count', l.on && part !== 'environment' ? 1 : 0);
    set('u_directional_direction', normalize3(l.direction));
    set('u_directional_irradiance', [l.irradiance, l.irradiance, l.irradiance]);
    set('u_point_count', 0);
    const env = state.environment.on && this.environmentLit && part !== 'lights';
    set('u_environment_on', env ? 1 : 0);
    for (const [name, value] of Object.entries(this.constants)) set(name, value);
    if (this.name === 'kneiphof2025') {
      set('u_kneiphof2025_f0', fresnelF0(m));
      set('u_kneiphof2025_levels', this.constants.levels_K ?? 8);
      set('u_kneiphof2025_radiance_scale', state.environment.scale);
      set('kneiphof2025_env_rotation', state.environment.rotation);
      // The bright sources of the "lobe_sun" smooth term (the radiance
      // array's alpha holds their channel): the manifest's map-frame
      // directions turned by the environment rotation about +y (world phi =
      // map phi + rotation, as kneiphof2025_latlong_uv and the native
      // kneiphof2025_gpu.cpp); count 0 where the export has none.
      const d = this.derived;
      const dirs = d.u_kneiphof2025_source_direction ?? [];
      const r = state.environment.rotation;
      const c = Math.cos(r), sn = Math.sin(r);
      set('u_kneiphof2025_source_count', dirs.length);
      if (dirs.length > 0) {
        set('u_kneiphof2025_source_direction',
            dirs.flatMap((a) => normalize3([a[0] * c - a[2] * sn, a[1], a[2] * c + a[0] * sn])));
        set('u_kneiphof2025_source_power', d.u_kneiphof2025_source_power.flat());
        set('u_kneiphof2025_source_radius', d.u_kneiphof2025_source_radius);
        set('u_kneiphof2025_sources_color', d.u_kneiphof2025_sources_color);
      }
    }
    for (const p of this.parameters) {
      if (!p.uniform) continue;
      const v = state.params[p.key] ?? p.default;
      set(p.uniform, p.value ? p.value(v) : typeof v === 'boolean' ? (v ? 1 : 0) : v);
    }
    this.textures.forEach((t, i) => {
      const unit = 1 + i;  // unit 0: the background's environment
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(t.texture.target, t.texture.texture);
      set(t.uniform, unit);
    });
    // The export's optional input textures (docs/INTEGRATION.md "Per-pixel
    // material inputs"): the normal map when one is on, but every sampler is active
    // and must not point at unit 0, where the last frame's image may still
    // be bound (a feedback loop with the framebuffer): a 1x1 placeholder on
    // a unit of its own.
    const inputUnit = 1 + this.textures.length;
    gl.activeTexture(gl.TEXTURE0 + inputUnit);
    gl.bindTexture(gl.TEXTURE_2D, inputPlaceholder(gl));
    for (const name of ['u_input_density', 'u_input_alpha', 'u_input_color',
                        'u_input_base_albedo', 'u_input_normal_slopes', 'u_input_normal_cross'])
      set(name, inputUnit);
    let mask = 0;
    const linear = Array(5).fill([1, 0, 0, 1]), offset = Array(5).fill([0, 0]);
    if (am) {
      // The asset's maps on the units after the placeholder, with their uv
      // transforms (KHR_texture_transform); its handedness for the normal map.
      // The normal map's s_x s_y (bit 5) shares its uv transform (slot 4).
      const slots = [['u_input_alpha', maps.alpha, 1], ['u_input_color', maps.color, 2],
                     ['u_input_base_albedo', maps.baseAlbedo, 3], ['u_input_normal_slopes', maps.normal, 4],
                     ['u_input_normal_cross', maps.normal?.cross, 5]];
      slots.forEach(([name, map, bit], i) => {
        if (!perPixel(bit, map) && !(bit === 4 && map)) return;
        gl.activeTexture(gl.TEXTURE0 + inputUnit + 1 + i);
        gl.bindTexture(gl.TEXTURE_2D, oncePerContext(gl, map, () => uploadMipmapped(gl, map.texels, map.w, map.h, false, map.wrap)));
        set(name, inputUnit + 1 + i);
        if (bit < 5) {
          linear[bit] = map.linear;
          offset[bit] = map.offset;
        }
        mask |= 1 << bit;
      });
      set('u_input_uv_mirrored', asset.uvMirrored ? 1 : 0);
    } else if (state.textures !== 'none') {
      // Density, roughness and colour maps on the next units (bits 0-2),
      // for the models that read them per pixel (the manifest's inputs).
      const maps = materialTextures(gl, state.textures);
      const inputs = [['u_input_density', maps.density, 0], ['u_input_alpha', maps.alpha, 1],
                      ['u_input_color', maps.color, 2]];
      inputs.forEach(([name, texture, bit], i) => {
        if (!this.perPixelInputs.has(bit)) return;
        gl.activeTexture(gl.TEXTURE0 + inputUnit + 2 + i);
        gl.bindTexture(gl.TEXTURE_2D, texture);
        set(name, inputUnit + 2 + i);
        mask |= 1 << bit;
      });
    }
    if (!am && state.normalMap !== 'none') {
      // The normal map's LEAN texture on the next unit, its uv transform
      // the identity (the map tiles with the glint pattern's uv). Both
      // meshes' v runs along n x t (the plane's v along -z, the sphere's
      // towards its south pole), so glTF's bitangent, up the image, is
      // -(n x t): tangent w = -1.
      // (Made on first use, which binds on the active unit: this one.)
      gl.activeTexture(gl.TEXTURE0 + inputUnit + 1);
      const lean = leanTexture(gl, state.normalMap);
      gl.bindTexture(gl.TEXTURE_2D, lean.slopes);
      set('u_input_normal_slopes', inputUnit + 1);
      set('u_input_uv_mirrored', 1);
      mask |= 1 << 4;  // GLINT_INPUT_NORMAL
      if (this.perPixelInputs.has(5)) {  // the model reads the slopes' correlation
        // After the page's own maps (units + 2 to + 4).
        gl.activeTexture(gl.TEXTURE0 + inputUnit + 5);
        gl.bindTexture(gl.TEXTURE_2D, lean.cross);
        set('u_input_normal_cross', inputUnit + 5);
        mask |= 1 << 5;  // GLINT_INPUT_NORMAL_CROSS
      }
    }
    // The page's own maps tile with the glint pattern's uv (identity
    // transforms); an asset's carry theirs.
    set('u_input_texture_linear', linear.flat());
    set('u_input_texture_offset', offset.flat());
    set('u_input_texture_mask', mask);
    gl.activeTexture(gl.TEXTURE0);
  }
}

// One 1x1 RGBA8 texture per context, for samplers that read nothing.
const placeholders = new WeakMap();
function inputPlaceholder(gl) {
  let t = placeholders.get(gl);
  if (!t) {
    t = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, t);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 1, 1, 0, gl.RGBA, gl.UNSIGNED_BYTE,
                  new Uint8Array([0, 0, 0, 255]));
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    placeholders.set(gl, t);
  }
  return t;
}

function normalize3(v) {
  const l = Math.hypot(v[0], v[1], v[2]);
  return l > 0 ? v.map((x) => x / l) : [0, 1, 0];
}
