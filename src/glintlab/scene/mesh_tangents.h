// Per-vertex tangent frames of a mesh with uvs, for its normal maps
// (docs/SCENE_FORMAT.md, "Normal maps"): the frames a baker's MikkTSpace
// would give an indexed mesh whose seams are split vertices (glTF's rule:
// a vertex has one uv), so that a normal map's tangent space varies
// smoothly across triangles instead of jumping at every edge.
#pragma once

#include "glintlab/scene/mesh.h"

namespace glintlab {

// Fills mesh.tangents: for each vertex, ∂p/∂u of its triangles weighted by
// the triangles' angles at the vertex (MikkTSpace's weights), made
// orthogonal to the vertex normal (the face normals' angle-weighted mean
// without vertex normals), and w = ±1 so that n × t · w points up in the
// image, against ∂p/∂v (glTF's bitangent; −1 where the uv mapping is
// mirrored). A vertex whose triangles give no usable ∂p/∂u (degenerate uvs)
// gets a tangent orthogonal to its normal. Returns the number of such
// vertices. Needs uvs.
size_t generate_vertex_tangents(TriangleMesh& mesh);

}  // namespace glintlab
