// Mip-mapped float textures for the export's per-pixel inputs
// (docs/INTEGRATION.md, "Per-pixel material inputs"): the chain of box
// means a host builds (the renderer's MipTexture levels on a power-of-two
// image), uploaded level by level.

// Box-mean mip levels of a power-of-two RGBA float image.
function mipLevels(texels, w, h) {
  const levels = [{data: texels, w, h}];
  while (w > 1 || h > 1) {
    const nw = Math.max(w >> 1, 1), nh = Math.max(h >> 1, 1);
    const prev = levels[levels.length - 1].data;
    const next = new Float32Array(nw * nh * 4);
    for (let y = 0; y < nh; ++y)
      for (let x = 0; x < nw; ++x)
        for (let c = 0; c < 4; ++c) {
          let sum = 0;
          for (const [dx, dy] of [[0, 0], [1, 0], [0, 1], [1, 1]])
            sum += prev[(Math.min(2 * y + dy, h - 1) * w + Math.min(2 * x + dx, w - 1)) * 4 + c];
          next[(y * nw + x) * 4 + c] = sum / 4;
        }
    levels.push({data: next, w: nw, h: nh});
    w = nw;
    h = nh;
  }
  return levels;
}

// RGBA32F where OES_texture_float_linear makes it filterable, else RGBA16F
// (filterable in every WebGL2; `float32`: values past half floats' 65504,
// an error without the extension); trilinear; `wrap`: [wrap S, wrap T] as
// WebGL enums (glTF samplers' values), repeating by default.
export function uploadMipmapped(gl, texels, w, h, float32 = false, wrap = [gl.REPEAT, gl.REPEAT]) {
  const linear32 = gl.getExtension('OES_texture_float_linear') !== null;
  if (float32 && !linear32)
    throw new Error('this texture needs 32-bit float filtering (OES_texture_float_linear), ' +
                    'which this browser does not offer');
  const format = linear32 ? gl.RGBA32F : gl.RGBA16F;
  const t = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, t);
  mipLevels(texels, w, h).forEach((l, i) =>
    gl.texImage2D(gl.TEXTURE_2D, i, format, l.w, l.h, 0, gl.RGBA, gl.FLOAT, l.data));
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, wrap[0]);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, wrap[1]);
  return t;
}


// The value make() returns for (gl, name), made once per context.
const perContext = new WeakMap();
export function oncePerContext(gl, name, make) {
  let byName = perContext.get(gl);
  if (!byName) perContext.set(gl, byName = new Map());
  if (!byName.has(name)) byName.set(name, make());
  return byName.get(name);
}
