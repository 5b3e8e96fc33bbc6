// Plane and sphere meshes of the page, built exactly as the native renderer
// builds them (scene/shapes.cpp make_quad / make_sphere and
// realtime/gpu_geometry.cpp), so a view on the page and the same view in
// `glintlab render --gpu` rasterise the same triangles with the same uvs.
// Interleaved vertex: position (3), normal (3), uv (2), dp/du (3).

export const FLOATS_PER_VERTEX = 11;

// The quad in the xz plane, normal +y, u along +x and v along -z
// (docs/SCENE_FORMAT.md "quad"): `size` [w, d], `uvScale` [su, sv].
// Its per-triangle dp/du (realtime/gpu_geometry.cpp triangle_dpdu) is the
// same for both triangles: (w / su, 0, 0).
export function makeQuad(size, uvScale) {
  const hx = 0.5 * size[0], hz = 0.5 * size[1];
  const positions = [[-hx, 0, hz], [hx, 0, hz], [hx, 0, -hz], [-hx, 0, -hz]];
  const uvs = [[0, 0], [uvScale[0], 0], [uvScale[0], uvScale[1]], [0, uvScale[1]]];
  const dpdu = [size[0] / uvScale[0], 0, 0];
  const vertices = new Float32Array(4 * FLOATS_PER_VERTEX);
  for (let i = 0; i < 4; ++i)
    vertices.set([...positions[i], 0, 1, 0, ...uvs[i], ...dpdu], i * FLOATS_PER_VERTEX);
  const indices = new Uint32Array([0, 1, 2, 0, 2, 3]);
  return {vertices, indices, bounds: {centre: [0, 0, 0], radius: Math.hypot(hx, hz)}};
}

// The sphere of `radius` at the origin as the native renderer tessellates it
// (make_sphere(radius, segments, segments / 2): vertex (i, j) at
// u = i / segments, v = j / rings, theta = v pi from +y, phi = u 2 pi;
// dp/du = 2 pi dp/dphi; the degenerate triangles at the poles dropped).
// 192 segments: gpu_geometry.h kMaxSphereSegments, what a scene with one
// sphere gets. Bounds as scene_bounds (gpu_geometry.cpp): the sphere of the
// bounding box.
export function makeSphere(radius, segments = 192) {
  const rings = segments / 2;
  const stride = segments + 1;
  const vertices = new Float32Array(stride * (rings + 1) * FLOATS_PER_VERTEX);
  let k = 0;
  for (let j = 0; j <= rings; ++j) {
    // Float32 arithmetic as the C++ (static_cast<float>(j) / rows, then
    // float products), so the vertices are bit-for-bit close to the native ones.
    const v = Math.fround(j / rings);
    const theta = Math.fround(v * Math.fround(Math.PI));
    const st = Math.fround(Math.sin(theta)), ct = Math.fround(Math.cos(theta));
    for (let i = 0; i <= segments; ++i) {
      const u = Math.fround(i / segments);
      const phi = Math.fround(u * Math.fround(2 * Math.PI));
      const sp = Math.fround(Math.sin(phi)), cp = Math.fround(Math.cos(phi));
      const n = [Math.fround(st * cp), ct, Math.fround(st * sp)];
      const tp = Math.fround(2 * Math.PI) * radius;
      vertices.set([radius * n[0], radius * n[1], radius * n[2], n[0], n[1], n[2], u, v,
                    -tp * st * sp, 0, tp * st * cp], k);
      k += FLOATS_PER_VERTEX;
    }
  }
  const indices = [];
  for (let j = 0; j < rings; ++j) {
    for (let i = 0; i < segments; ++i) {
      const a = j * stride + i, b = a + 1, c = b + stride, d = a + stride;
      if (j !== 0) indices.push(a, b, c);
      if (j !== rings - 1) indices.push(a, c, d);
    }
  }
  return {vertices, indices: new Uint32Array(indices),
          bounds: {centre: [0, 0, 0], radius: Math.sqrt(3) * radius}};
}
