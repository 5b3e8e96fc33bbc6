// Textured glint parameters on the page, as a host feeds them to an
// exported shader (docs/INTEGRATION.md, "Per-pixel material inputs"): each
// input texture holds the quantity the renderer filters (N = e^{ln N}, α²,
// linear RGB) with a box-mean mip chain. The page's one set of maps is
// procedural, so that the browser test can hand the native renderer the
// same texels (web/tests/web_page_test.py tiles_maps).

import {oncePerContext, uploadMipmapped} from './mip_texture.js';

export const MATERIAL_MAPS = ['none', 'tiles'];
export const TILES_SIZE = 64;

// "tiles", 64², row 0 at v = 0, tiled with the glint pattern's uv:
//   ln N   14, 15, 16, 17 in four bands across u
//   α      0.2 on the light cells of an 8 x 8 checker, 0.4 on the others
//   colour linear RGB from (0.9, 0.6, 0.3) at v = 0 to (0.3, 0.6, 0.9) at v = 1
export function tilesMaps(size = TILES_SIZE) {
  const lnN = new Float32Array(size * size), alpha = new Float32Array(size * size);
  const color = new Float32Array(size * size * 3);
  for (let y = 0; y < size; ++y)
    for (let x = 0; x < size; ++x) {
      const i = y * size + x;
      lnN[i] = 14 + Math.floor(4 * x / size);
      alpha[i] = (Math.floor(x / 8) + Math.floor(y / 8)) % 2 === 0 ? 0.2 : 0.4;
      const t = (y + 0.5) / size;
      color.set([0.9 - 0.6 * t, 0.6, 0.3 + 0.6 * t], i * 3);
    }
  return {lnN, alpha, color};
}

function rgba(size, texel) {
  const out = new Float32Array(size * size * 4);
  for (let i = 0; i < size * size; ++i) out.set(texel(i), i * 4);
  return out;
}

// The input textures of a named set, made once per context: density (N),
// alpha (α²) and color (linear RGB).
export function materialTextures(gl, name) {
  if (name !== 'tiles') throw new Error(`textures ${name}: expected one of ${MATERIAL_MAPS}`);
  return oncePerContext(gl, `textures ${name}`, () => {
    const n = TILES_SIZE, m = tilesMaps(n);
    return {
      // N reaches e^17 ≈ 2.4e7, past half floats: 32-bit filtering or an error.
      density: uploadMipmapped(gl, rgba(n, (i) => [Math.exp(m.lnN[i]), 0, 0, 1]), n, n, true),
      alpha: uploadMipmapped(gl, rgba(n, (i) => [m.alpha[i] ** 2, 0, 0, 1]), n, n),
      color: uploadMipmapped(gl, rgba(n, (i) => [...m.color.subarray(i * 3, i * 3 + 3), 1]), n, n),
    };
  });
}
