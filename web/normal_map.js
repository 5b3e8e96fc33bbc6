// A normal map on the page, as a host feeds one to an exported shader
// (docs/INTEGRATION.md, "Per-pixel material inputs"): the map's LEAN
// texture, slopes and second moments with a box-mean mip chain, on the
// export's input u_input_normal_slopes (mask bit 4).
// The page's one map is procedural, so that the browser test can hand the
// native renderer the same texels (web/tests/web_page_test.py bumps_normals).

import {oncePerContext, uploadMipmapped} from './mip_texture.js';

export const NORMAL_MAPS = ['none', 'bumps'];
export const BUMPS_SIZE = 64;

// "bumps": ridges along u and v, n = normalize(-0.5 cos 4πu, -0.5 sin 6πv, 1)
// at texel centres (u, v) = ((x + 0.5) / 64, (y + 0.5) / 64), row 0 at v = 0:
// tilts up to 35°. Unit normals (x, y, z), glTF's tangent-space convention.
export function bumpsNormals(size = BUMPS_SIZE) {
  const n = new Float32Array(size * size * 3);
  for (let y = 0; y < size; ++y)
    for (let x = 0; x < size; ++x) {
      const u = (x + 0.5) / size, v = (y + 0.5) / size;
      const a = -0.5 * Math.cos(4 * Math.PI * u), b = -0.5 * Math.sin(6 * Math.PI * v);
      const len = Math.hypot(a, b, 1);
      n.set([a / len, b / len, 1 / len], (y * size + x) * 3);
    }
  return n;
}

// The LEAN texture's finest level (RGBA): the slope s = (-x/z, -y/z) and
// the second moments (s_x², s_y²) of the bilinear surface over each
// texel's cell: its four half-texel squares, 2 x 2 Gauss–Legendre nodes in
// each (exact for the squares of bilinear slopes), repeating edges.
// `cross`, when given (RGBA, w h texels), receives s_x s_y the same way in
// R: the export's u_input_normal_cross for the models that read the
// slopes' correlation.
export function leanTexels(normals, w, h, cross = null) {
  const count = w * h;
  const sx = new Float32Array(count), sy = new Float32Array(count);
  for (let i = 0; i < count; ++i) {
    const z = Math.max(normals[i * 3 + 2], 0.05);
    sx[i] = -normals[i * 3] / z;
    sy[i] = -normals[i * 3 + 1] / z;
  }
  const at = (s, x, y) => s[(((y % h) + h) % h) * w + (((x % w) + w) % w)];
  const g = 0.25 / Math.sqrt(3);
  const nodes = [-0.25 - g, -0.25 + g, 0.25 - g, 0.25 + g];
  const texels = new Float32Array(count * 4);
  for (let y = 0; y < h; ++y)
    for (let x = 0; x < w; ++x) {
      let mxx = 0, myy = 0, mxy = 0;
      for (const oy of nodes)
        for (const ox of nodes) {
          const px = x + ox, py = y + oy;
          const ix = Math.floor(px), iy = Math.floor(py);
          const fx = px - ix, fy = py - iy;
          const lerp2 = (s) => {
            const top = at(s, ix, iy) + fx * (at(s, ix + 1, iy) - at(s, ix, iy));
            const bottom = at(s, ix, iy + 1) + fx * (at(s, ix + 1, iy + 1) - at(s, ix, iy + 1));
            return top + fy * (bottom - top);
          };
          const a = lerp2(sx), b = lerp2(sy);
          mxx += a * a;
          myy += b * b;
          mxy += a * b;
        }
      const i = y * w + x;
      texels.set([sx[i], sy[i], mxx / 16, myy / 16], i * 4);
      if (cross) cross.set([mxy / 16, 0, 0, 1], i * 4);
    }
  return texels;
}

// The LEAN textures of a named map, made once per context: {slopes, cross}.
export function leanTexture(gl, name) {
  if (name !== 'bumps') throw new Error(`normal map ${name}: expected one of ${NORMAL_MAPS}`);
  return oncePerContext(gl, `normal_map ${name}`, () => {
    const cross = new Float32Array(BUMPS_SIZE * BUMPS_SIZE * 4);
    const slopes = leanTexels(bumpsNormals(), BUMPS_SIZE, BUMPS_SIZE, cross);
    return {slopes: uploadMipmapped(gl, slopes, BUMPS_SIZE, BUMPS_SIZE),
            cross: uploadMipmapped(gl, cross, BUMPS_SIZE, BUMPS_SIZE)};
  });
}
