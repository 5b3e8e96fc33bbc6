// The page: state (from the URL), controls, the render loop and the test
// hooks (window.glintlab). docs/WEB.md describes the URL parameters.

import {makeQuad, makeSphere} from './geometry.js';
import {AssetError, readGlb} from './gltf_asset.js';
import {ExportedModel, fresnelDiffers, glintBlurTaps} from './model.js';
import {MATERIAL_MAPS} from './material_maps.js';
import {NORMAL_MAPS} from './normal_map.js';
import {Renderer} from './renderer.js';

// The models `glintlab export` can write (the page lists those whose
// manifest is present under the export directory).
const MODELS = ['smooth', 'zirr2016', 'chermain2020', 'deliot2023', 'kneiphof2025', 'wang2020'];

// The native scenes the page mirrors: scenes/plane_25.json (000 PLANE at
// 25 degrees: an 8 x 8 quad, uv scale 8) and scenes/sphere.json, with their
// cameras and directional lights.
const SHAPES = {
  plane: {mesh: () => makeQuad([8, 8], [8, 8]), eye: [0, 1.27, 2.72], target: [0, 0, 0],
          light: [0, 0.55, -1], irradiance: 1},
  sphere: {mesh: () => makeSphere(1), eye: [0, 0, 3.2], target: [0, 0, 0],
           light: [0.5, 0.6, 0.8], irradiance: 1.5},
};

class UrlError extends Error {}

function numbers(text, key, count) {
  const v = text.split(',').map(Number);
  if (!count.includes(v.length) || v.some((x) => !Number.isFinite(x)))
    throw new UrlError(`URL parameter ${key}=${text}: expected ${count.join(' or ')} ` +
                       'comma-separated finite numbers');
  return v;
}

function number(text, key, min, max) {
  const v = Number(text);
  if (!Number.isFinite(v) || v < min || v > max)
    throw new UrlError(`URL parameter ${key}=${text}: expected a number in [${min}, ${max}]`);
  return v;
}

function choice(text, key, allowed) {
  if (!allowed.includes(text))
    throw new UrlError(`URL parameter ${key}=${text}: expected one of ${allowed.join(', ')}`);
  return text;
}

// The state the URL describes (every key optional).
function stateFromUrl(search) {
  const q = new URLSearchParams(search);
  const shape = choice(q.get('shape') ?? 'plane', 'shape', Object.keys(SHAPES));
  const s = {
    model: choice(q.get('model') ?? 'deliot2023', 'model', MODELS),
    variant: q.get('variant') ?? 'default',
    shape,
    width: Math.round(number(q.get('w') ?? '512', 'w', 16, 4096)),
    height: Math.round(number(q.get('h') ?? '384', 'h', 16, 4096)),
    camera: {
      eye: q.has('eye') ? numbers(q.get('eye'), 'eye', [3]) : SHAPES[shape].eye.slice(),
      target: q.has('target') ? numbers(q.get('target'), 'target', [3]) : SHAPES[shape].target.slice(),
      fovDeg: number(q.get('fov') ?? '45', 'fov', 1, 170),
    },
    material: {
      ndf: choice(q.get('ndf') ?? 'beckmann', 'ndf', ['beckmann', 'ggx']),
      roughness: [0.3, 0.3],
      log_density: number(q.get('log_density') ?? '12', 'log_density', -20, 60),
      seed: Math.round(number(q.get('seed') ?? '1', 'seed', 0, 4294967295)),
      color: q.has('color') ? numbers(q.get('color'), 'color', [1, 3]) : [0.9, 0.85, 0.75],
      fresnel: {type: choice(q.get('fresnel') ?? 'schlick', 'fresnel',
                             ['none', 'schlick', 'conductor', 'dielectric'])},
    },
    light: {
      on: (q.get('light_on') ?? '1') !== '0',
      direction: q.has('light') ? numbers(q.get('light'), 'light', [3]) : SHAPES[shape].light.slice(),
      irradiance: q.has('irradiance') ? number(q.get('irradiance'), 'irradiance', 0, 1000)
                                      : SHAPES[shape].irradiance,
    },
    environment: {
      on: (q.get('env') ?? '1') !== '0',
      scale: number(q.get('env_scale') ?? '1', 'env_scale', 0, 1000),
      rotation: number(q.get('env_rotation') ?? '0', 'env_rotation', -360, 360) * Math.PI / 180,
    },
    normalMap: choice(q.get('normal_map') ?? 'none', 'normal_map', NORMAL_MAPS),
    textures: choice(q.get('textures') ?? 'none', 'textures', MATERIAL_MAPS),
    exposure: number(q.get('exposure') ?? '-1', 'exposure', -20, 20),
    params: {},
    continuous: q.get('static') !== '1',
    explicit: [...q.keys()],
    exportBase: q.get('export') ?? 'export',
    // A .glb to draw in place of the shape, fetched from this URL (relative
    // to the page); a file picked or dropped has no URL and is not kept.
    assetUrl: q.get('asset'),
  };
  if (q.has('roughness')) {
    const r = numbers(q.get('roughness'), 'roughness', [1, 2]);
    if (r.some((a) => a < 0.001 || a > 1))
      throw new UrlError(`URL parameter roughness=${q.get('roughness')}: expected alpha in [0.001, 1]`);
    s.material.roughness = r.length === 1 ? [r[0], r[0]] : r;
  }
  if (s.material.color.length === 1) s.material.color = [0, 0, 0].map(() => s.material.color[0]);
  const f = s.material.fresnel;
  if (f.type === 'schlick')
    f.f0 = q.has('f0') ? numbers(q.get('f0'), 'f0', [3]) : [0.95, 0.93, 0.88];
  if (f.type === 'dielectric') f.eta = number(q.get('eta') ?? '1.5', 'eta', 1, 4);
  if (f.type === 'conductor') {
    f.eta = numbers(q.get('eta') ?? '0.155,0.117,0.138', 'eta', [3]);  // silver
    f.k = numbers(q.get('k') ?? '4.83,3.12,2.15', 'k', [3]);
  }
  for (const [key, value] of q.entries())
    if (key.startsWith('p.')) s.params[key.slice(2)] = value;
  return s;
}

function urlFromState(s) {
  const q = new URLSearchParams();
  const list = (v) => v.map((x) => +x.toFixed(5)).join(',');
  q.set('model', s.model);
  q.set('shape', s.shape);
  if (s.variant !== 'default') q.set('variant', s.variant);
  q.set('w', s.width);
  q.set('h', s.height);
  q.set('eye', list(s.camera.eye));
  q.set('target', list(s.camera.target));
  q.set('fov', s.camera.fovDeg);
  q.set('ndf', s.material.ndf);
  q.set('roughness', list(s.material.roughness));
  q.set('log_density', s.material.log_density);
  q.set('seed', s.material.seed);
  q.set('color', list(s.material.color));
  q.set('fresnel', s.material.fresnel.type);
  if (s.material.fresnel.f0) q.set('f0', list(s.material.fresnel.f0));
  if (s.material.fresnel.eta !== undefined)
    q.set('eta', Array.isArray(s.material.fresnel.eta) ? list(s.material.fresnel.eta) : s.material.fresnel.eta);
  if (s.material.fresnel.k) q.set('k', list(s.material.fresnel.k));
  q.set('light_on', s.light.on ? 1 : 0);
  q.set('light', list(s.light.direction));
  q.set('irradiance', s.light.irradiance);
  q.set('env', s.environment.on ? 1 : 0);
  q.set('env_scale', s.environment.scale);
  q.set('env_rotation', +(s.environment.rotation * 180 / Math.PI).toFixed(3));
  q.set('exposure', s.exposure);
  if (s.normalMap !== 'none') q.set('normal_map', s.normalMap);
  if (s.textures !== 'none') q.set('textures', s.textures);
  if (s.assetUrl) q.set('asset', s.assetUrl);
  for (const [k, v] of Object.entries(s.params)) q.set(`p.${k}`, v);
  if (!s.continuous) q.set('static', 1);
  if (s.exportBase !== 'export') q.set('export', s.exportBase);
  return `?${q}`;
}

// ---- Controls ------------------------------------------------------------

function el(tag, attrs = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === 'class') e.className = v;
    else if (k in e) e[k] = v;
    else e.setAttribute(k, v);
  }
  e.append(...children);
  return e;
}

// A slider row; `log`: the slider moves log(value) (ranges over decades).
function slider(parent, label, {min, max, value, step = null, log = false, integer = false,
                                title = '', disabled = false}, onInput) {
  const toSlider = (v) => (log ? Math.log(v) : v);
  const fromSlider = (x) => {
    const v = log ? Math.exp(x) : x;
    return integer ? Math.round(v) : v;
  };
  const input = el('input', {
    type: 'range', min: toSlider(min), max: toSlider(max),
    step: step ?? (integer && !log ? 1 : (toSlider(max) - toSlider(min)) / 1000),
    value: toSlider(value), disabled,
  });
  const out = el('output', {}, format(value));
  input.addEventListener('input', () => {
    const v = fromSlider(Number(input.value));
    out.value = format(v);
    onInput(v);
  });
  parent.append(el('label', {title}, label, input, out));
  return input;
}

function format(v) {
  if (typeof v !== 'number') return String(v);
  if (Number.isInteger(v)) return String(v);
  return Math.abs(v) >= 100 || (Math.abs(v) < 0.01 && v !== 0) ? v.toPrecision(3) : v.toFixed(3);
}

function select(parent, label, options, value, onChange, title = '') {
  const s = el('select', {}, ...options.map((o) => el('option', {value: o}, o)));
  s.value = String(value);
  s.addEventListener('change', () => onChange(s.value));
  parent.append(el('label', {title}, label, s));
  return s;
}

function checkbox(parent, label, value, onChange, title = '') {
  const c = el('input', {type: 'checkbox', checked: value});
  c.addEventListener('change', () => onChange(c.checked));
  parent.append(el('label', {class: 'checkbox', title}, label, c));
  return c;
}

// ---- Application -----------------------------------------------------------

class App {
  constructor() {
    this.canvas = document.getElementById('canvas');
    this.errorBox = document.getElementById('error');
    this.readout = document.getElementById('frame-time');
    this.assetStatus = document.getElementById('asset-status');
    this.asset = null;          // a loaded .glb (gltf_asset.js), drawn in place of the shape
    this.assetError = null;
    this.assetLoading = false;
    this.models = new Map();  // name -> ExportedModel (loaded)
    this.info = null;         // glintlab info --json, written beside the exports
    this.dirty = true;
    this.frames = 0;
    this.cpuMs = null;
    this.lastFrame = null;
    this.glErrors = [];
    this.ready = false;
  }

  fail(error) {
    const message = error instanceof Error ? error.message : String(error);
    this.error = message;
    this.errorBox.hidden = false;
    this.errorBox.textContent = message;
    console.error(`glintlab: ${message}`);
  }

  async start() {
    this.state = stateFromUrl(window.location.search);
    this.renderer = new Renderer(this.canvas);
    const base = this.state.exportBase;
    // The models' descriptors (ranges of the sliders); optional.
    try {
      const r = await fetch(`${base}/models.json`);
      if (r.ok) this.info = await r.json();
    } catch (e) { /* the manifest's parameters remain */ }
    const available = await this.availableModels(base);
    if (!available.includes(this.state.model))
      throw new Error(`model ${this.state.model} is not exported under ${base}/ ` +
                      `(exported: ${available.join(', ') || 'none'}; run \`make web\`)`);
    this.available = available;
    this.setShape(this.state.shape);
    await this.setModel(this.state.model);
    this.buildControls();
    this.installOrbit();
    if (this.state.assetUrl) await this.loadAssetUrl(this.state.assetUrl);
    this.ready = true;
    this.schedule();
  }

  // The models scripts/export_web.sh exported (its index.json).
  async availableModels(base) {
    const url = `${base}/index.json`;
    let r;
    try {
      r = await fetch(url);
    } catch (e) {
      throw new Error(`cannot fetch ${url}: ${e.message}`);
    }
    if (!r.ok)
      throw new Error(`${url}: HTTP ${r.status}: the models are not exported ` +
                      '(run `make web`, which writes web/export/)');
    const index = await r.json();
    return MODELS.filter((m) => index.models.includes(m));
  }

  // Another view from URL parameters without reloading the page (models
  // already loaded keep their compiled program and resources).
  async navigate(search) {
    const state = stateFromUrl(search);
    if (state.exportBase !== this.state.exportBase)
      throw new UrlError('navigate: the export directory cannot change without a reload');
    this.state = state;
    history.replaceState(null, '', search);
    this.setShape(state.shape);
    await this.setModel(state.model);
    this.buildControls();
    if (state.assetUrl) await this.loadAssetUrl(state.assetUrl);
    this.dirty = true;
    this.lastFrame = null;
    this.cpuMs = null;
    this.schedule();
  }

  setShape(shape) {
    this.state.shape = shape;
    this.asset = null;
    this.assetStatus.textContent = '';
    this.renderer.setMesh(SHAPES[shape].mesh());
    this.dirty = true;
  }

  // A user's .glb (file picker or drop): drawn with its materials' maps in
  // place of the shape, framed by the camera. A file the page cannot read
  // is an error in the page's error box; the current view stays.
  async loadAsset(file) {
    this.state.assetUrl = null;  // a local file has no URL to keep
    await this.showAsset(file.name, () => file.arrayBuffer());
  }

  // The .glb of the URL's `asset` parameter. A fetch that fails is an error
  // naming the parameter, the URL and the HTTP status.
  async loadAssetUrl(url) {
    const name = decodeURIComponent(url.split(/[?#]/)[0].split('/').pop() || url);
    await this.showAsset(name, async () => {
      let r;
      try {
        r = await fetch(url);
      } catch (e) {
        throw new AssetError(`URL parameter asset=${url}: cannot fetch it (${e.message})`);
      }
      if (!r.ok) throw new AssetError(`URL parameter asset=${url}: HTTP ${r.status}`);
      return r.arrayBuffer();
    });
  }

  async showAsset(name, bytes) {
    this.assetError = null;
    this.assetLoading = true;
    try {
      const asset = await readGlb(await bytes(), name);
      this.renderer.setMesh(asset);
      this.asset = asset;
      const {centre, radius} = asset.bounds;
      const s = this.state;
      s.camera.target = centre.slice();
      s.camera.eye = [centre[0], centre[1] + 0.9 * radius, centre[2] + 2.4 * radius];
      // The plane's light: from behind the asset, so that its upward faces
      // reflect it towards the camera as the plane's glints do.
      s.light.direction = SHAPES.plane.light.slice();
      s.light.irradiance = SHAPES.plane.irradiance;
      this.assetStatus.textContent = `${name}: ${asset.triangles} triangles, ` +
          `${asset.parts.length} material${asset.parts.length > 1 ? 's' : ''}, whose colour ` +
          'and roughness replace the panel\'s' +
          (asset.warnings.length ? ` (${asset.warnings.join('; ')})` : '');
      this.errorBox.hidden = true;
      this.changed();
    } catch (e) {
      if (!(e instanceof AssetError)) console.error(e);
      this.assetError = e instanceof Error ? e.message : String(e);
      this.errorBox.hidden = false;
      this.errorBox.textContent = this.assetError;
    } finally {
      this.assetLoading = false;
    }
  }

  async setModel(name) {
    if (!this.models.has(name)) {
      const info = this.info?.models?.find((m) => m.name === name) ?? null;
      this.models.set(name, await ExportedModel.load(this.renderer, this.state.exportBase, name, info));
    }
    this.model = this.models.get(name);
    this.renderer.forward = await this.model.program(this.renderer, this.state.variant);
    this.state.model = name;
    // Material inputs the export fixes (wang2020's tables): the state shows
    // them; a URL asking for another value is an error.
    const m = this.state.material;
    for (const [key, fixed] of Object.entries(this.model.fixedMaterial)) {
      if (key === 'fresnel') {
        const asked = ['fresnel', 'f0', 'eta', 'k'].filter((k) => this.state.explicit.includes(k));
        if (fresnelDiffers(m.fresnel, fixed) && asked.length)
          throw new UrlError(`URL parameter ${asked.join(', ')}: ${name}'s exported tables were ` +
                             `built for Fresnel ${JSON.stringify(fixed)} (export again for another)`);
        m.fresnel = JSON.parse(JSON.stringify(fixed));
        continue;
      }
      const current = key === 'roughness' ? m.roughness : [m[key]];
      const want = Array.isArray(fixed) ? fixed : [fixed];
      const differs = current.some((v, i) => Math.abs(v - want[i]) > 1e-6 * Math.max(1, Math.abs(want[i])));
      if (differs && this.state.explicit.includes(key))
        throw new UrlError(`URL parameter ${key}=${current.join(',')}: ${name}'s exported tables ` +
                           `were built for ${key} ${want.join(',')} (export again for another)`);
      if (key === 'roughness') m.roughness = want.slice();
      else m[key] = want[0];
    }
    // URL values of the model's parameters, checked against the descriptor.
    for (const p of this.model.parameters) {
      const raw = this.state.params[p.key];
      if (raw === undefined) continue;
      this.state.params[p.key] = parseParam(p, raw);
      const v = this.state.params[p.key];
      if (p.baked && (typeof v === 'number' ? Math.abs(v - p.default) > 1e-6 * Math.abs(p.default)
                                             : v !== p.default))
        throw new UrlError(`URL parameter p.${p.key}=${raw}: fixed at ${p.default} by the ` +
                           `exported files (${p.baked})`);
    }
    for (const key of Object.keys(this.state.params))
      if (!this.model.parameters.some((p) => p.key === key))
        throw new UrlError(`URL parameter p.${key}: ${name} has no parameter "${key}" ` +
                           `(its parameters: ${this.model.parameters.map((p) => p.key).join(', ')})`);
    this.dirty = true;
  }

  // One pending animation frame at most.
  schedule() {
    if (this.scheduled) return;
    this.scheduled = true;
    requestAnimationFrame((t) => {
      this.scheduled = false;
      this.frame(t);
    });
  }

  frame(time) {
    try {
      if (this.lastFrame !== null && this.state.continuous) {
        const dt = time - this.lastFrame;
        this.cpuMs = this.cpuMs === null ? dt : 0.9 * this.cpuMs + 0.1 * dt;
      }
      this.lastFrame = time;
      if (this.dirty || this.state.continuous) this.draw();
    } catch (e) {
      this.fail(e);
      return;
    }
    if (this.state.continuous || this.dirty) this.schedule();
  }

  draw() {
    const s = this.state;
    const t0 = performance.now();
    this.renderer.resize(s.width, s.height);
    const env = s.environment.on && this.model.environment
      ? {texture: this.model.environment.texture, scale: s.environment.scale,
         rotation: s.environment.rotation}
      : null;
    this.renderer.render({
      camera: s.camera, exposure: s.exposure, environment: env,
      bindResources: (r, prog, part, k) => this.model.bind(r, prog, s, part, this.asset?.parts[k]),
      // The glint layer only where the environment lights the model.
      glintBlurTaps: s.environment.on && this.model.environmentLit
        ? glintBlurTaps(this.model, s.params) : 1,
    });
    const gl = this.renderer.gl;
    if (!s.continuous) {
      gl.finish();
      this.cpuMs = performance.now() - t0;
    }
    for (let e = gl.getError(); e !== gl.NO_ERROR; e = gl.getError()) {
      this.glErrors.push(e);
      console.error(`glintlab: WebGL error 0x${e.toString(16)} in frame ${this.frames}`);
    }
    this.frames += 1;
    this.dirty = false;
    const gpu = this.renderer.gpuMs;
    this.readout.textContent =
      `${s.model} ${s.width}×${s.height}  ` +
      (this.cpuMs !== null ? `frame ${this.cpuMs.toFixed(1)} ms` : 'frame —') +
      (gpu !== null ? `  GPU ${gpu.toFixed(2)} ms` : '');
  }

  changed() {
    this.dirty = true;
    clearTimeout(this.urlTimer);
    this.urlTimer = setTimeout(() => {
      const url = urlFromState(this.state);
      history.replaceState(null, '', url);
      document.getElementById('permalink').href = url;
    }, 200);
    if (!this.state.continuous) this.schedule();
  }

  buildControls() {
    const s = this.state;
    const modelSelect = document.getElementById('model');
    modelSelect.replaceChildren(...MODELS.map((m) => el('option', {
      value: m, disabled: !this.available.includes(m),
    }, this.available.includes(m) ? m : `${m} (not exported)`)));
    modelSelect.value = s.model;
    modelSelect.onchange = async () => {
      try {
        s.params = {};
        s.variant = 'default';
        s.explicit = [];
        await this.setModel(modelSelect.value);
        this.buildControls();
        this.changed();
      } catch (e) { this.fail(e); }
    };
    const shapeSelect = document.getElementById('shape');
    shapeSelect.value = s.shape;
    shapeSelect.onchange = () => {
      s.assetUrl = null;  // the shape replaces the asset
      this.setShape(shapeSelect.value);
      s.camera.eye = SHAPES[s.shape].eye.slice();
      s.camera.target = SHAPES[s.shape].target.slice();
      s.light.direction = SHAPES[s.shape].light.slice();
      s.light.irradiance = SHAPES[s.shape].irradiance;
      this.buildControls();
      this.changed();
    };
    const normalSelect = document.getElementById('normal-map');
    normalSelect.value = s.normalMap;
    normalSelect.onchange = () => { s.normalMap = normalSelect.value; this.changed(); };
    // A .glb by the file picker or dropped on the image.
    const assetInput = document.getElementById('asset');
    assetInput.onchange = () => {
      if (assetInput.files.length) this.loadAsset(assetInput.files[0]);
    };
    const dropZone = document.getElementById('view');
    dropZone.ondragover = (e) => e.preventDefault();
    dropZone.ondrop = (e) => {
      e.preventDefault();
      const file = e.dataTransfer?.files?.[0];
      if (file) this.loadAsset(file);
    };
    const texturesSelect = document.getElementById('textures');
    texturesSelect.value = s.textures;
    texturesSelect.onchange = () => { s.textures = texturesSelect.value; this.changed(); };
    const envBox = document.getElementById('environment');
    envBox.checked = s.environment.on;
    envBox.onchange = () => { s.environment.on = envBox.checked; this.changed(); };

    const light = document.getElementById('light-controls');
    light.replaceChildren(el('legend', {}, 'Directional light'));
    checkbox(light, 'on', s.light.on, (v) => { s.light.on = v; this.changed(); });
    const d = s.light.direction;
    const len = Math.hypot(...d);
    const angles = {
      elevation: Math.asin(d[1] / len) * 180 / Math.PI,
      azimuth: Math.atan2(d[0], d[2]) * 180 / Math.PI,
    };
    const setDirection = () => {
      const e = angles.elevation * Math.PI / 180, a = angles.azimuth * Math.PI / 180;
      s.light.direction = [Math.cos(e) * Math.sin(a), Math.sin(e), Math.cos(e) * Math.cos(a)];
      this.changed();
    };
    slider(light, 'elevation (deg)', {min: -90, max: 90, value: angles.elevation},
           (v) => { angles.elevation = v; setDirection(); });
    slider(light, 'azimuth (deg)', {min: -180, max: 180, value: angles.azimuth},
           (v) => { angles.azimuth = v; setDirection(); });
    slider(light, 'irradiance', {min: 0, max: 10, value: s.light.irradiance},
           (v) => { s.light.irradiance = v; this.changed(); });

    const mat = document.getElementById('material-controls');
    mat.replaceChildren(el('legend', {}, 'Glint material'));
    const m = s.material;
    const fixed = (key) => key in this.model.fixedMaterial;
    const fixedNote = `fixed by ${s.model}'s exported tables`;
    select(mat, 'ndf', ['beckmann', 'ggx'], m.ndf, (v) => { m.ndf = v; this.changed(); });
    slider(mat, 'roughness α', {min: 0.001, max: 1, value: m.roughness[0], log: true,
                                disabled: fixed('roughness'), title: fixed('roughness') ? fixedNote : ''},
           (v) => { m.roughness = [v, v]; this.changed(); });
    slider(mat, 'log_density', {min: -20, max: 60, value: m.log_density, disabled: fixed('log_density'),
                                title: fixed('log_density') ? fixedNote : 'ln(microfacets per unit uv area)'},
           (v) => { m.log_density = v; this.changed(); });
    slider(mat, 'seed', {min: 0, max: 1000, value: m.seed, integer: true, disabled: fixed('seed'),
                         title: fixed('seed') ? fixedNote : ''},
           (v) => { m.seed = v; this.changed(); });
    ['r', 'g', 'b'].forEach((c, i) => slider(mat, `color ${c}`, {min: 0, max: 1, value: m.color[i]},
                                            (v) => { m.color[i] = v; this.changed(); }));
    const fresnelFixed = fixed('fresnel');
    const fresnelTitle = fresnelFixed ? fixedNote : '';
    select(mat, 'fresnel', ['none', 'schlick', 'conductor', 'dielectric'], m.fresnel.type, (v) => {
      m.fresnel = {type: v};
      if (v === 'schlick') m.fresnel.f0 = [0.95, 0.93, 0.88];
      if (v === 'dielectric') m.fresnel.eta = 1.5;
      if (v === 'conductor') Object.assign(m.fresnel, {eta: [0.155, 0.117, 0.138], k: [4.83, 3.12, 2.15]});
      this.buildControls();
      this.changed();
    }, fresnelTitle).disabled = fresnelFixed;
    const f = {disabled: fresnelFixed, title: fresnelTitle};
    if (m.fresnel.type === 'schlick')
      ['r', 'g', 'b'].forEach((c, i) => slider(mat, `f0 ${c}`, {min: 0, max: 1, value: m.fresnel.f0[i], ...f},
                                              (v) => { m.fresnel.f0[i] = v; this.changed(); }));
    if (m.fresnel.type === 'dielectric')
      slider(mat, 'eta', {min: 1, max: 3, value: m.fresnel.eta, ...f},
             (v) => { m.fresnel.eta = v; this.changed(); });
    if (m.fresnel.type === 'conductor')
      ['r', 'g', 'b'].forEach((c, i) => {
        slider(mat, `eta ${c}`, {min: 0.01, max: 5, value: m.fresnel.eta[i], log: true, ...f},
               (v) => { m.fresnel.eta[i] = v; this.changed(); });
        slider(mat, `k ${c}`, {min: 0, max: 10, value: m.fresnel.k[i], ...f},
               (v) => { m.fresnel.k[i] = v; this.changed(); });
      });

    const view = document.getElementById('view-controls');
    view.replaceChildren(el('legend', {}, 'View'));
    slider(view, 'exposure (stops)', {min: -8, max: 8, value: s.exposure},
           (v) => { s.exposure = v; this.changed(); });
    slider(view, 'fov (deg)', {min: 10, max: 90, value: s.camera.fovDeg},
           (v) => { s.camera.fovDeg = v; this.changed(); });
    slider(view, 'environment scale', {min: 0.01, max: 100, value: s.environment.scale, log: true},
           (v) => { s.environment.scale = v; this.changed(); });
    slider(view, 'environment rotation', {min: -180, max: 180, value: s.environment.rotation * 180 / Math.PI},
           (v) => { s.environment.rotation = v * Math.PI / 180; this.changed(); });
    checkbox(view, 'render continuously', s.continuous, (v) => {
      s.continuous = v;
      this.cpuMs = null;
      this.lastFrame = null;
      this.changed();
      if (v) this.schedule();
    }, 'continuous frames give the frame-time readout');
    this.buildModelControls();
  }

  buildModelControls() {
    const s = this.state;
    const box = document.getElementById('model-controls');
    box.replaceChildren(el('legend', {}, `${s.model} parameters`));
    const man = this.model.manifest;
    document.getElementById('model-info').textContent =
      man.citations.map((c) => `${c.authors} (${c.year}), ${c.venue}`).join('; ') +
      ` — glintlab ${man.glintlab_version}` +
      (this.model.environment ? `; environment ${this.model.environment.file.split('/').pop()}` : '');
    document.getElementById('environment').disabled = !this.model.environmentLit;
    if (this.model.variants.length > 1)
      select(box, 'shader variant', this.model.variants, s.variant, async (v) => {
        try {
          s.variant = v;
          this.renderer.forward = await this.model.program(this.renderer, v);
          this.changed();
        } catch (e) { this.fail(e); }
      }, 'the exported fragment stages of this model (its manifest "shaders")');
    if (this.model.parameters.length === 0) box.append(el('p', {class: 'hint'}, 'no parameters'));
    for (const p of this.model.parameters) {
      const value = s.params[p.key] ?? p.default;
      const title = `${p.doc} (${p.range}${p.unit ? ' ' + p.unit : ''})` +
                    (p.baked ? ` — fixed: ${p.baked}` : '');
      const label = p.key + (p.unit ? ` (${p.unit})` : '');
      const disabled = !!p.baked || (!p.uniform && !p.pagePass);
      const set = (v) => { s.params[p.key] = v; this.changed(); };
      if (p.type === 'bool') {
        checkbox(box, label, !!value, set, title).disabled = disabled;
      } else if (p.type === 'enum' || p.values) {
        select(box, label, (p.choices ?? p.values).map(String), value,
               (v) => set(p.type === 'enum' ? v : Number(v)), title).disabled = disabled;
      } else {
        const log = p.min > 0 && p.max / p.min > 100;
        slider(box, label, {min: p.min, max: p.max, value, log, integer: p.type === 'integer',
                            title, disabled}, set);
      }
    }
  }

  // Drag: orbit the eye around the target; wheel: move along the view axis.
  installOrbit() {
    let drag = null;
    this.canvas.addEventListener('pointerdown', (e) => {
      drag = {x: e.clientX, y: e.clientY};
      this.canvas.setPointerCapture(e.pointerId);
    });
    this.canvas.addEventListener('pointerup', () => { drag = null; });
    this.canvas.addEventListener('pointermove', (e) => {
      if (!drag) return;
      const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
      drag = {x: e.clientX, y: e.clientY};
      const c = this.state.camera;
      const v = c.eye.map((x, i) => x - c.target[i]);
      const r = Math.hypot(...v);
      let theta = Math.acos(Math.max(-1, Math.min(1, v[1] / r)));
      let phi = Math.atan2(v[0], v[2]);
      phi -= dx * 0.01;
      theta = Math.max(0.01, Math.min(Math.PI - 0.01, theta - dy * 0.01));
      c.eye = [c.target[0] + r * Math.sin(theta) * Math.sin(phi), c.target[1] + r * Math.cos(theta),
               c.target[2] + r * Math.sin(theta) * Math.cos(phi)];
      this.changed();
    });
    this.canvas.addEventListener('wheel', (e) => {
      e.preventDefault();
      const c = this.state.camera;
      const k = Math.exp(Math.sign(e.deltaY) * 0.1);
      c.eye = c.eye.map((x, i) => c.target[i] + (x - c.target[i]) * k);
      this.changed();
    }, {passive: false});
  }
}

function parseParam(p, raw) {
  if (typeof raw !== 'string') return raw;
  const where = `URL parameter p.${p.key}=${raw}`;
  if (p.type === 'bool') {
    if (raw !== 'true' && raw !== 'false' && raw !== '0' && raw !== '1')
      throw new UrlError(`${where}: expected true or false`);
    return raw === 'true' || raw === '1';
  }
  if (p.type === 'enum') return choice(raw, `p.${p.key}`, p.choices);
  const v = Number(raw);
  if (!Number.isFinite(v) || (p.min !== undefined && (v < p.min || v > p.max)) ||
      (p.type === 'integer' && !Number.isInteger(v)) || (p.values && !p.values.includes(v)))
    throw new UrlError(`${where}: expected ${p.type} ${p.range}`);
  return v;
}

// Test hooks (web/tests): readiness, errors, frame count, the HDR frame.
const app = new App();
window.glintlab = {
  get ready() { return app.ready && app.frames > 0 && !app.dirty && !app.assetLoading; },
  // The loaded glTF asset (null without one) and the last asset error.
  get asset() {
    const a = app.asset;
    return a ? {name: a.name, triangles: a.triangles, uvMirrored: a.uvMirrored,
                warnings: a.warnings.slice(),
                materials: a.parts.map((p) => ({name: p.material.name,
                                                maps: Object.keys(p.material.maps)}))}
             : null;
  },
  get assetError() { return app.assetError ?? null; },
  get error() { return app.error ?? null; },
  get glErrors() { return app.glErrors.slice(); },
  get frames() { return app.frames; },
  // Shows the view of URL parameters `search` ("?model=...") in this page.
  navigate(search) {
    app.ready = false;
    app.navigate(search).then(() => { app.ready = true; }, (e) => app.fail(e));
  },
  get state() { return JSON.parse(JSON.stringify(app.state)); },
  get size() { return [app.renderer.width, app.renderer.height]; },
  // The linear frame (RGBA float32, rows top to bottom, alpha = coverage)
  // as base64 of its little-endian bytes.
  readHdr() { return base64(new Uint8Array(app.renderer.readHdr().buffer)); },
  // The canvas as displayed (RGBA8, rows top to bottom), through a 2D
  // canvas: what a screenshot of the page shows.
  readDisplay() {
    const [w, h] = this.size;
    const c = document.createElement('canvas');
    c.width = w;
    c.height = h;
    const ctx = c.getContext('2d');
    ctx.drawImage(app.canvas, 0, 0);
    return base64(new Uint8Array(ctx.getImageData(0, 0, w, h).data.buffer));
  },
};

function base64(bytes) {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000)
    s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
  return btoa(s);
}
app.start().catch((e) => app.fail(e));
