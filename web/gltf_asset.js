// A user's glTF binary (.glb) on the page: its meshes flattened into world
// space as the page's vertex layout (geometry.js), one draw part per
// material, and each material's maps as the export's per-pixel inputs
// (docs/INTEGRATION.md, "Per-pixel material inputs"), read as the native
// loader reads a file's materials when a glint material overrides them
// (docs/SCENE_FORMAT.md, "glTF materials"): the base colour (sRGB decoded,
// times its factor) as the glint colour, the perceptual roughness (G
// channel, times its factor, α = roughness²) as α², the normal texture
// (times its scale) as a LEAN texture, KHR_texture_transform as each
// input's uv transform. Errors name the file and the glTF path.

import {FLOATS_PER_VERTEX} from './geometry.js';
import {leanTexels} from './normal_map.js';

export class AssetError extends Error {}

const GLB_MAGIC = 0x46546c67;  // "glTF"
const CHUNK_JSON = 0x4e4f534a;
const CHUNK_BIN = 0x004e4942;
// Limits that keep a hostile file from exhausting the tab.
const MAX_BYTES = 512 * 1024 * 1024;
const MAX_TRIANGLES = 8 * 1024 * 1024;
const MAX_IMAGE_SIDE = 1024;  // images are resampled to a power of two at most this
const COMPONENTS = {SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4, MAT4: 16};
const TYPED = {
  5120: Int8Array, 5121: Uint8Array, 5122: Int16Array, 5123: Uint16Array, 5125: Uint32Array,
  5126: Float32Array,
};
// Extensions the page reads; any other is named in a warning.
const READ_EXTENSIONS = ['KHR_texture_transform', 'KHR_materials_ior'];
const WRAP_REPEAT = 10497;
const WRAP_MODES = [WRAP_REPEAT, 33071, 33648];  // REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT

// The texel bytes' colour decoding (IEC 61966-2-1).
function srgbDecode(c) {
  return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
}

class Reader {
  constructor(buffer, name) {
    this.name = name;
    this.warnings = [];
    if (!(buffer instanceof ArrayBuffer)) throw this.error('', 'expected the bytes of a file');
    if (buffer.byteLength > MAX_BYTES)
      throw this.error('', `${buffer.byteLength} bytes: the page reads files of at most ${MAX_BYTES}`);
    if (buffer.byteLength < 20) throw this.error('', `${buffer.byteLength} bytes: truncated (a GLB has a 12-byte header and chunks)`);
    const view = new DataView(buffer);
    const magic = view.getUint32(0, true);
    if (magic !== GLB_MAGIC)
      throw this.error('', `not a binary glTF (magic 0x${magic.toString(16)}, expected 0x${GLB_MAGIC.toString(16)} "glTF"); ` +
                       'the page reads .glb files (a .gltf with separate files: pack it, e.g. with gltf-pipeline)');
    const version = view.getUint32(4, true);
    if (version !== 2) throw this.error('', `glTF version ${version}: the page reads version 2`);
    const length = view.getUint32(8, true);
    if (length > buffer.byteLength)
      throw this.error('', `truncated: the header says ${length} bytes, the file has ${buffer.byteLength}`);
    let offset = 12;
    this.json = null;
    this.bin = null;
    while (offset + 8 <= length) {
      const chunkLength = view.getUint32(offset, true), type = view.getUint32(offset + 4, true);
      const start = offset + 8;
      if (start + chunkLength > length)
        throw this.error('', `truncated: chunk at byte ${offset} claims ${chunkLength} bytes past the file's ${length}`);
      if (type === CHUNK_JSON && this.json === null) {
        const text = new TextDecoder().decode(new Uint8Array(buffer, start, chunkLength));
        try {
          this.json = JSON.parse(text);
        } catch (e) {
          throw this.error('', `the JSON chunk does not parse: ${e.message}`);
        }
      } else if (type === CHUNK_BIN && this.bin === null) {
        this.bin = new Uint8Array(buffer, start, chunkLength);
      }
      offset = start + chunkLength + ((4 - (chunkLength % 4)) % 4);
    }
    if (!this.json || typeof this.json !== 'object') throw this.error('', 'no JSON chunk');
    const required = this.list(this.json.extensionsRequired, 'extensionsRequired');
    const unreadRequired = required.filter((e) => !READ_EXTENSIONS.includes(e));
    if (unreadRequired.length)
      throw this.error('extensionsRequired', `${unreadRequired.join(', ')}: not read by the page ` +
                       '(write the file without them, e.g. without mesh compression)');
    // Named by readGlb, after the materials have named theirs.
    this.unreadUsed = this.list(this.json.extensionsUsed, 'extensionsUsed').filter((e) => !READ_EXTENSIONS.includes(e));
  }

  error(path, message) {
    return new AssetError(`${this.name}: ${path ? `${path}: ` : ''}${message}`);
  }

  item(array, index, path) {
    const list = this.json[array];
    if (!Number.isInteger(index) || !Array.isArray(list) || index < 0 || index >= list.length)
      throw this.error(path, `${array} index ${index} out of range [0, ${Array.isArray(list) ? list.length : 0})`);
    const it = list[index];
    if (it === null || typeof it !== 'object' || Array.isArray(it))
      throw this.error(`${array}[${index}]`, 'not an object');
    return it;
  }

  // An optional array member (absent: empty).
  list(value, path) {
    if (value === undefined) return [];
    if (!Array.isArray(value)) throw this.error(path, 'not an array');
    return value;
  }

  // An optional array of n finite numbers (absent: the fallback).
  numbers(value, n, path, fallback) {
    if (value === undefined) return fallback;
    if (!Array.isArray(value) || value.length !== n || !value.every((x) => typeof x === 'number' && Number.isFinite(x)))
      throw this.error(path, `expected ${n} finite numbers`);
    return value;
  }

  bufferViewBytes(index, path) {
    const view = this.item('bufferViews', index, path);
    const buffer = this.item('buffers', view.buffer ?? -1, `bufferViews[${index}]`);
    if (buffer.uri !== undefined || !this.bin)
      throw this.error(`bufferViews[${index}]`, 'data outside the GLB\'s binary chunk (an external or data-URI buffer) is not read');
    const offset = view.byteOffset ?? 0, length = view.byteLength;
    if (!Number.isInteger(offset) || !Number.isInteger(length) || offset < 0 || length < 0 ||
        offset + length > this.bin.length)
      throw this.error(`bufferViews[${index}]`, `bytes [${offset}, ${offset + length}) outside the binary chunk's ${this.bin.length}`);
    return {bytes: this.bin.subarray(offset, offset + length), stride: view.byteStride ?? 0};
  }

  // An accessor as a Float32Array of count x components (normalized
  // integers mapped to [0, 1] / [-1, 1]), or integer indices.
  accessor(index, path, {components, indices = false}) {
    const a = this.item('accessors', index, path);
    const where = `accessors[${index}]`;
    const n = COMPONENTS[a.type];
    if (components && !components.includes(n))
      throw this.error(where, `type ${a.type} where ${path} needs ${components.map((c) => Object.keys(COMPONENTS).find((k) => COMPONENTS[k] === c)).join(' or ')}`);
    const Type = TYPED[a.componentType];
    if (!Type) throw this.error(where, `componentType ${a.componentType} is not a glTF component type`);
    if (a.sparse) throw this.error(where, 'sparse accessors are not read by the page');
    const count = a.count;
    if (!Number.isInteger(count) || count < 0 || count > 3 * MAX_TRIANGLES)
      throw this.error(where, `count ${count}: expected an integer in [0, ${3 * MAX_TRIANGLES}]`);
    if (a.bufferView === undefined)  // all zeros (glTF 3.6.2.3)
      return indices ? new Uint32Array(count) : new Float32Array(count * n);
    const {bytes, stride} = this.bufferViewBytes(a.bufferView, where);
    const size = Type.BYTES_PER_ELEMENT;
    const step = stride || size * n;
    const offset = a.byteOffset ?? 0;
    if (!Number.isInteger(offset) || offset < 0 || !Number.isInteger(step) || step <= 0 ||
        (count > 0 && offset + (count - 1) * step + size * n > bytes.length))
      throw this.error(where, `${count} elements from byte ${offset} (stride ${step}) past the end of bufferView ${a.bufferView} (${bytes.length} bytes)`);
    const out = indices ? new Uint32Array(count) : new Float32Array(count * n);
    const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    const get = {
      5120: (o) => view.getInt8(o), 5121: (o) => view.getUint8(o),
      5122: (o) => view.getInt16(o, true), 5123: (o) => view.getUint16(o, true),
      5125: (o) => view.getUint32(o, true), 5126: (o) => view.getFloat32(o, true),
    }[a.componentType];
    const scale = a.normalized ? {5120: 1 / 127, 5121: 1 / 255, 5122: 1 / 32767, 5123: 1 / 65535}[a.componentType] ?? 1 : 1;
    for (let i = 0; i < count; ++i)
      for (let c = 0; c < n; ++c) {
        const v = get(offset + i * step + c * size);
        out[i * n + c] = a.normalized && !indices ? Math.max(v * scale, -1) : v;
      }
    if (!indices)
      for (let i = 0; i < out.length; ++i)
        if (!Number.isFinite(out[i])) throw this.error(where, `element ${Math.floor(i / n)} is not finite`);
    return out;
  }
}

// Column-major 4x4 products and the node's local matrix (matrix or TRS).
function multiply(a, b) {
  const r = new Array(16).fill(0);
  for (let c = 0; c < 4; ++c)
    for (let row = 0; row < 4; ++row)
      for (let k = 0; k < 4; ++k) r[c * 4 + row] += a[k * 4 + row] * b[c * 4 + k];
  return r;
}
function localMatrix(r, node, path) {
  if (node.matrix !== undefined) return r.numbers(node.matrix, 16, `${path}.matrix`).slice();
  const [tx, ty, tz] = r.numbers(node.translation, 3, `${path}.translation`, [0, 0, 0]);
  const [x, y, z, w] = r.numbers(node.rotation, 4, `${path}.rotation`, [0, 0, 0, 1]);
  const [sx, sy, sz] = r.numbers(node.scale, 3, `${path}.scale`, [1, 1, 1]);
  const q = [1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w),
             2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
             2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y)];
  return [q[0] * sx, q[1] * sx, q[2] * sx, 0, q[3] * sy, q[4] * sy, q[5] * sy, 0,
          q[6] * sz, q[7] * sz, q[8] * sz, 0, tx, ty, tz, 1];
}
function transformPoint(m, p) {
  return [0, 1, 2].map((i) => m[i] * p[0] + m[4 + i] * p[1] + m[8 + i] * p[2] + m[12 + i]);
}
function transformVector(m, v) {
  return [0, 1, 2].map((i) => m[i] * v[0] + m[4 + i] * v[1] + m[8 + i] * v[2]);
}
// Normals transform with the inverse transpose of the upper 3x3.
function normalMatrix(m) {
  const a = [m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]];
  const c = [a[4] * a[8] - a[5] * a[7], a[5] * a[6] - a[3] * a[8], a[3] * a[7] - a[4] * a[6],
             a[2] * a[7] - a[1] * a[8], a[0] * a[8] - a[2] * a[6], a[1] * a[6] - a[0] * a[7],
             a[1] * a[5] - a[2] * a[4], a[2] * a[3] - a[0] * a[5], a[0] * a[4] - a[1] * a[3]];
  return [c[0], c[1], c[2], 0, c[3], c[4], c[5], 0, c[6], c[7], c[8], 0, 0, 0, 0, 1];
}
function sub(a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; }
function cross(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }
function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
function normalize(v, fallback) {
  const l = Math.hypot(v[0], v[1], v[2]);
  return l > 1e-20 && Number.isFinite(l) ? v.map((x) => x / l) : fallback;
}

// The triangles of every mesh node of the default scene, grouped by
// material: {vertices, indices, parts: [{first, count, material}], bounds,
// handedness: [positive, negative] vertex counts of the tangent frame}.
function flatten(r) {
  const g = r.json;
  const sceneIndex = g.scene ?? 0;
  const roots = Array.isArray(g.scenes) && g.scenes.length
      ? r.list(r.item('scenes', sceneIndex, 'scene').nodes, `scenes[${sceneIndex}].nodes`)
      : r.list(g.nodes, 'nodes').map((_, i) => i);
  const byMaterial = new Map();  // material index -> [{positions, normals, uvs, tangents, indices}]
  let triangles = 0;
  const visit = (index, parent, depth) => {
    if (depth > 64) throw r.error(`nodes[${index}]`, 'the node hierarchy is deeper than 64 (a cycle?)');
    const node = r.item('nodes', index, 'nodes');
    const m = multiply(parent, localMatrix(r, node, `nodes[${index}]`));
    if (node.mesh !== undefined) {
      const mesh = r.item('meshes', node.mesh, `nodes[${index}].mesh`);
      r.list(mesh.primitives, `meshes[${node.mesh}].primitives`).forEach((p, k) => {
        const path = `meshes[${node.mesh}].primitives[${k}]`;
        if (p === null || typeof p !== 'object') throw r.error(path, 'not an object');
        const mode = p.mode ?? 4;
        if (mode !== 4) {
          r.warnings.push(`${path}: mode ${mode} (not triangles) is not drawn`);
          return;
        }
        const at = p.attributes ?? {};
        if (at.POSITION === undefined) throw r.error(path, 'no POSITION attribute');
        if (at.TEXCOORD_0 === undefined)
          throw r.error(path, 'no TEXCOORD_0: the glint pattern and the maps need uvs (the native loader\'s "uv" projection option makes them)');
        const positions = r.accessor(at.POSITION, `${path}.attributes.POSITION`, {components: [3]});
        const count = positions.length / 3;
        const uvs = r.accessor(at.TEXCOORD_0, `${path}.attributes.TEXCOORD_0`, {components: [2]});
        const normals = at.NORMAL !== undefined ? r.accessor(at.NORMAL, `${path}.attributes.NORMAL`, {components: [3]}) : null;
        const tangents = at.TANGENT !== undefined ? r.accessor(at.TANGENT, `${path}.attributes.TANGENT`, {components: [4]}) : null;
        for (const [what, a, n] of [['TEXCOORD_0', uvs, 2], ['NORMAL', normals, 3], ['TANGENT', tangents, 4]])
          if (a && a.length !== count * n)
            throw r.error(`${path}.attributes.${what}`, `${a.length / n} elements for ${count} positions`);
        let indices;
        if (p.indices !== undefined) {
          indices = r.accessor(p.indices, `${path}.indices`, {components: [1], indices: true});
          for (let i = 0; i < indices.length; ++i)
            if (indices[i] >= count) throw r.error(`${path}.indices`, `index ${indices[i]} out of range [0, ${count})`);
        } else {
          indices = Uint32Array.from({length: count}, (_, i) => i);
        }
        if (indices.length % 3) throw r.error(`${path}.indices`, `${indices.length} indices: not whole triangles`);
        triangles += indices.length / 3;
        if (triangles > MAX_TRIANGLES) throw r.error(path, `more than ${MAX_TRIANGLES} triangles: the page draws at most that many`);
        const nm = normalMatrix(m);
        const P = [], N = [], T = [];
        for (let i = 0; i < count; ++i) {
          P.push(transformPoint(m, [positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]]));
          N.push(normals ? normalize(transformVector(nm, [normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]]), null) : null);
          T.push(tangents ? [...transformVector(m, [tangents[4 * i], tangents[4 * i + 1], tangents[4 * i + 2]]), tangents[4 * i + 3]] : null);
        }
        const key = p.material ?? -1;
        if (!byMaterial.has(key)) byMaterial.set(key, []);
        byMaterial.get(key).push({P, N, T, uvs, indices, path, hasNormals: !!normals});
      });
    }
    for (const child of r.list(node.children, `nodes[${index}].children`)) visit(child, m, depth + 1);
  };
  const identity = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
  roots.forEach((n) => visit(n, identity, 0));
  if (!triangles) throw r.error('', 'no triangles in the default scene');

  const vertices = [], indexList = [], parts = [];
  let base = 0;
  let positive = 0, negative = 0;
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  let missingNormals = false;
  for (const [material, prims] of byMaterial) {
    const first = indexList.length;
    for (const {P, N, T, uvs, indices, hasNormals} of prims) {
      const n = P.length;
      // Per vertex: dp/du and dp/dv summed over its triangles (the native
      // renderer's per-triangle dp/du), face normals where the file has none.
      const dpdu = Array.from({length: n}, () => [0, 0, 0]), dpdv = Array.from({length: n}, () => [0, 0, 0]);
      const faceN = Array.from({length: n}, () => [0, 0, 0]);
      for (let t = 0; t < indices.length; t += 3) {
        const [a, b, c] = [indices[t], indices[t + 1], indices[t + 2]];
        const e1 = sub(P[b], P[a]), e2 = sub(P[c], P[a]);
        const du1 = uvs[2 * b] - uvs[2 * a], dv1 = uvs[2 * b + 1] - uvs[2 * a + 1];
        const du2 = uvs[2 * c] - uvs[2 * a], dv2 = uvs[2 * c + 1] - uvs[2 * a + 1];
        const det = du1 * dv2 - du2 * dv1;
        const fn = cross(e1, e2);
        for (const v of [a, b, c]) for (let k = 0; k < 3; ++k) faceN[v][k] += fn[k];
        if (Math.abs(det) < 1e-20) continue;
        const pu = [0, 1, 2].map((k) => (e1[k] * dv2 - e2[k] * dv1) / det);
        const pv = [0, 1, 2].map((k) => (e2[k] * du1 - e1[k] * du2) / det);
        for (const v of [a, b, c]) for (let k = 0; k < 3; ++k) { dpdu[v][k] += pu[k]; dpdv[v][k] += pv[k]; }
      }
      if (!hasNormals) missingNormals = true;
      for (let i = 0; i < n; ++i) {
        const normal = N[i] ?? normalize(faceN[i], [0, 1, 0]);
        let t = T[i] ? T[i].slice(0, 3) : dpdu[i];
        // The tangent in the surface (Gram–Schmidt), any one where uvs degenerate.
        t = sub(t, normal.map((x) => x * dot(normal, t)));
        t = normalize(t, normalize(cross(Math.abs(normal[1]) < 0.9 ? [0, 1, 0] : [1, 0, 0], normal), [1, 0, 0]));
        // glTF's bitangent cross(n, t) w points up the image, against dp/dv.
        const side = dot(cross(normal, t), dpdv[i]);
        const w = T[i] ? T[i][3] : (side > 0 ? -1 : 1);
        // Vertices whose uvs degenerate (a pole) have no handedness of their own.
        if (T[i] || Math.abs(side) > 1e-6 * Math.hypot(...dpdv[i])) {
          if (w < 0) ++negative; else ++positive;
        }
        vertices.push(...P[i], ...normal, uvs[2 * i], uvs[2 * i + 1], ...t);
        for (let k = 0; k < 3; ++k) { lo[k] = Math.min(lo[k], P[i][k]); hi[k] = Math.max(hi[k], P[i][k]); }
      }
      for (let i = 0; i < indices.length; ++i) indexList.push(base + indices[i]);
      base += n;
    }
    parts.push({first, count: indexList.length - first, material});
  }
  if (missingNormals) r.warnings.push('primitives without NORMAL: normals averaged from their faces');
  const centre = [0, 1, 2].map((k) => 0.5 * (lo[k] + hi[k]));
  const radius = Math.max(0.5 * Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]), 1e-6);
  if (vertices.length / FLOATS_PER_VERTEX !== base) throw r.error('', 'internal: vertex layout');
  return {vertices: new Float32Array(vertices), indices: new Uint32Array(indexList), parts,
          bounds: {centre, radius}, triangles, handedness: [positive, negative]};
}

// An image of the file as RGBA8 texels resampled to a power of two (at most
// MAX_IMAGE_SIDE), rows from the top.
async function decodeImage(r, index, path) {
  const image = r.item('images', index, path);
  let bytes;
  if (image.bufferView !== undefined) {
    bytes = r.bufferViewBytes(image.bufferView, `images[${index}]`).bytes;
  } else if (typeof image.uri === 'string' && image.uri.startsWith('data:')) {
    const comma = image.uri.indexOf(',');
    bytes = Uint8Array.from(atob(image.uri.slice(comma + 1)), (c) => c.charCodeAt(0));
  } else {
    throw r.error(`images[${index}]`, `external image "${image.uri}": a file picked on the page comes without its neighbours; pack the images into the GLB`);
  }
  let bitmap;
  try {
    bitmap = await createImageBitmap(new Blob([bytes], {type: image.mimeType ?? 'image/png'}),
                                     {premultiplyAlpha: 'none', colorSpaceConversion: 'none'});
  } catch (e) {
    throw r.error(`images[${index}]`, `does not decode as ${image.mimeType ?? 'an image'}: ${e.message}`);
  }
  const side = (n) => Math.min(MAX_IMAGE_SIDE, 2 ** Math.round(Math.log2(Math.max(n, 1))));
  const w = side(bitmap.width), h = side(bitmap.height);
  const canvas = new OffscreenCanvas(w, h);
  const ctx = canvas.getContext('2d', {colorSpace: 'srgb'});
  ctx.imageSmoothingQuality = 'high';
  ctx.drawImage(bitmap, 0, 0, w, h);
  return {data: ctx.getImageData(0, 0, w, h).data, w, h};
}

// A map of the page's inputs: RGBA float texels, their mean (what a model
// that reads the input as a uniform takes), size and uv transform.
function inputMap(texels, w, h, t) {
  const mean = [0, 0, 0, 0];
  for (let i = 0; i < w * h; ++i) for (let c = 0; c < 4; ++c) mean[c] += texels[4 * i + c];
  return {texels, w, h, mean: mean.map((x) => x / (w * h)), linear: t.linear, offset: t.offset,
          wrap: t.wrap};
}

// A textureInfo's image and uv transform (st = linear uv + offset, the
// export's u_input_texture_linear / _offset).
async function textureOf(r, info, path) {
  const texture = r.item('textures', info.index ?? -1, `${path}.index`);
  if (texture.source === undefined)
    throw r.error(`textures[${info.index}]`, 'no PNG/JPEG source (KHR_texture_basisu, EXT_texture_webp are not read)');
  let texCoord = info.texCoord ?? 0;
  let linear = [1, 0, 0, 1], offset = [0, 0];
  const t = info.extensions?.KHR_texture_transform;
  if (t) {
    const [sx, sy] = t.scale ?? [1, 1], [ox, oy] = t.offset ?? [0, 0], a = t.rotation ?? 0;
    const c = Math.cos(a), s = Math.sin(a);
    // The native TextureUvTransform: offset + R(a) (scale ⊙ uv), R's rows
    // (c, s), (-s, c); a GLSL mat2 is column-major.
    linear = [c * sx, -s * sx, s * sy, c * sy];
    offset = [ox, oy];
    texCoord = t.texCoord ?? texCoord;
  }
  if (texCoord !== 0) r.warnings.push(`${path}: TEXCOORD_${texCoord} read as TEXCOORD_0 (the page carries one uv set)`);
  // The sampler's wrapS and wrapT, apart (glTF's values are WebGL's enums);
  // an unknown value repeats, as the native loader reads it, and is named.
  // Every map is filtered over the pixel footprint (trilinear, mip-mapped):
  // a sampler's nearest or unmipmapped filter is named, not followed. A
  // sampler the file lacks is named and read as glTF's default.
  const wrap = [WRAP_REPEAT, WRAP_REPEAT];
  const warnOnce = (w) => { if (!r.warnings.includes(w)) r.warnings.push(w); };
  const samplers = r.json.samplers;
  const sampler = texture.sampler === undefined ? undefined : samplers?.[texture.sampler];
  if (texture.sampler !== undefined && (sampler === null || typeof sampler !== 'object' || Array.isArray(sampler))) {
    warnOnce(`textures[${info.index}].sampler ${JSON.stringify(texture.sampler)} is not one of the file's samplers; read as repeat, filtered`);
  } else if (sampler) {
    ['wrapS', 'wrapT'].forEach((axis, i) => {
      const mode = sampler[axis] ?? WRAP_REPEAT;
      if (WRAP_MODES.includes(mode)) wrap[i] = mode;
      else warnOnce(`samplers[${texture.sampler}].${axis} ${JSON.stringify(mode)} is not a glTF wrap mode; read as repeat`);
    });
    const mag = sampler.magFilter ?? 9729, min = sampler.minFilter ?? 9987;
    if (mag === 9728 || min === 9728 || min === 9729)
      warnOnce(`samplers[${texture.sampler}] asks for ${mag === 9728 || min === 9728 ? 'nearest' : 'unmipmapped'} ` +
               `filtering (magFilter ${mag}, minFilter ${min}); the page filters every map over the pixel footprint`);
  }
  return {image: await decodeImage(r, texture.source, `textures[${info.index}].source`), linear, offset, wrap};
}

// Each material as the glint inputs the page feeds the export, as the
// native loader turns a file material into a glint (docs/SCENE_FORMAT.md,
// "glTF materials"): the base colour is the glint colour on the metallic
// side (metallicFactor >= 0.5), else the base albedo under dielectric
// Fresnel with the file's IOR; a glint has no metal/dielectric mix.
async function readMaterial(r, index) {
  if (index < 0) return {name: 'default', color: [1, 1, 1], alpha: 1, maps: {}};
  const path = `materials[${index}]`;
  const m = r.item('materials', index, path);
  const pbr = m.pbrMetallicRoughness ?? {};
  const factor = r.numbers(pbr.baseColorFactor, 4, `${path}.pbrMetallicRoughness.baseColorFactor`, [1, 1, 1, 1]);
  const roughness = r.numbers([pbr.roughnessFactor ?? 1], 1, `${path}.pbrMetallicRoughness.roughnessFactor`)[0];
  const out = {name: m.name || `material ${index}`, color: factor.slice(0, 3), alpha: roughness * roughness, maps: {}};
  const unread = Object.keys(m.extensions ?? {}).filter((e) => !READ_EXTENSIONS.includes(e));
  if (unread.length) r.warnings.push(`${path} "${out.name}": extensions not read: ${unread.join(', ')}`);
  const metallic = r.numbers([pbr.metallicFactor ?? 1], 1, `${path}.pbrMetallicRoughness.metallicFactor`)[0];
  if (pbr.metallicRoughnessTexture || (metallic > 0 && metallic < 1))
    r.warnings.push(`${path} "${out.name}": a glint has no metal/dielectric mix: ` +
                    `${metallic >= 0.5 ? 'metallic' : 'dielectric'} (metallicFactor ${metallic})`);
  if (pbr.baseColorTexture) {
    const t = await textureOf(r, pbr.baseColorTexture, `${path}.pbrMetallicRoughness.baseColorTexture`);
    const {data, w, h} = t.image;
    const texels = new Float32Array(w * h * 4);
    for (let i = 0; i < w * h; ++i)
      for (let c = 0; c < 3; ++c) texels[4 * i + c] = factor[c] * srgbDecode(data[4 * i + c] / 255);
    out.maps.color = inputMap(texels, w, h, t);
  }
  if (pbr.metallicRoughnessTexture) {
    const t = await textureOf(r, pbr.metallicRoughnessTexture, `${path}.pbrMetallicRoughness.metallicRoughnessTexture`);
    const {data, w, h} = t.image;
    const texels = new Float32Array(w * h * 4);
    // α = (roughness factor G)², stored as α² (the quantity the footprint filters).
    for (let i = 0; i < w * h; ++i) texels[4 * i] = (roughness * data[4 * i + 1] / 255) ** 4;
    out.maps.alpha = inputMap(texels, w, h, t);
  }
  if (m.normalTexture) {
    const t = await textureOf(r, m.normalTexture, `${path}.normalTexture`);
    const {data, w, h} = t.image;
    const scale = m.normalTexture.scale ?? 1;
    const normals = new Float32Array(w * h * 3);
    for (let i = 0; i < w * h; ++i) {
      const n = normalize([scale * (2 * data[4 * i] / 255 - 1), scale * (2 * data[4 * i + 1] / 255 - 1),
                           2 * data[4 * i + 2] / 255 - 1], [0, 0, 1]);
      normals.set(n, 3 * i);
    }
    const cross = new Float32Array(w * h * 4);
    out.maps.normal = inputMap(leanTexels(normals, w, h, cross), w, h, t);
    out.maps.normal.cross = inputMap(cross, w, h, t);  // s_x s_y, for the slopes' correlation
  }
  if (metallic < 0.5) {
    out.baseAlbedo = out.color;
    out.color = [1, 1, 1];
    if (out.maps.color) {
      out.maps.baseAlbedo = out.maps.color;
      delete out.maps.color;
    }
    out.fresnel = {type: 'dielectric', eta: m.extensions?.KHR_materials_ior?.ior ?? 1.5};
  }
  return out;
}

// The asset of a .glb file's bytes: geometry, one part per material and the
// materials' maps; `warnings` lists what the page does not read.
export async function readGlb(buffer, name) {
  try {
    return await read(buffer, name);
  } catch (e) {
    if (e instanceof AssetError) throw e;
    // A member of an unexpected type where no check names it.
    throw new AssetError(`${name}: not a well-formed glTF (${e.message})`);
  }
}

async function read(buffer, name) {
  const r = new Reader(buffer, name);
  const geometry = flatten(r);
  const materials = [];
  for (const part of geometry.parts) materials.push(await readMaterial(r, part.material));
  const named = r.warnings.join(' ');
  const unread = r.unreadUsed.filter((e) => !named.includes(e));
  if (unread.length) r.warnings.push(`extensions not read: ${unread.join(', ')}`);
  const [positive, negative] = geometry.handedness;
  // The export takes one handedness per draw (u_input_uv_mirrored): the
  // majority's.
  const mirrored = negative > positive;
  // (A few vertices at a seam or a pole of another sign are not mirrored
  // uv islands: below 0.5 % they are not named.)
  if (Math.min(positive, negative) > 0.005 * (positive + negative))
    r.warnings.push(`uv handedness differs: ${Math.min(positive, negative)} of ${positive + negative} vertices ` +
                    `are drawn with the other side's (${mirrored ? 'mirrored' : 'unmirrored'}) normal-map frame`);
  return {name, vertices: geometry.vertices, indices: geometry.indices, bounds: geometry.bounds,
          parts: geometry.parts.map((p, i) => ({first: p.first, count: p.count, material: materials[i]})),
          triangles: geometry.triangles, uvMirrored: mirrored, warnings: r.warnings};
}
