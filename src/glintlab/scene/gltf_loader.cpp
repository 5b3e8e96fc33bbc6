#include "glintlab/scene/gltf_loader.h"

#include <cstring>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

// Textures are not needed for geometry, so tinygltf is built without its
// stb_image dependency (another module owns STB_IMAGE_IMPLEMENTATION) and
// images are skipped by a no-op loader below.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include "glintlab/core/error.h"
#include "glintlab/scene/transform.h"

namespace glintlab {

namespace {

bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                const unsigned char*, int, void*) {
    return true;
}

// A strided view of one accessor's elements inside its buffer, bounds-checked
// once so element reads need no further checks.
struct AccessorView {
    const unsigned char* data = nullptr;
    size_t stride = 0;
    size_t count = 0;
    int component_type = 0;
    bool normalized = false;
};

class GltfReader {
  public:
    GltfReader(const tinygltf::Model& model, std::string name)
        : model_(model), name_(std::move(name)) {}

    TriangleMesh read_scene() {
        std::vector<int> roots;
        if (!model_.scenes.empty()) {
            const int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
            if (scene >= static_cast<int>(model_.scenes.size()))
                fail("{}: default scene {} out of range [0, {})", name_, scene,
                     model_.scenes.size());
            roots = model_.scenes[scene].nodes;
        } else {
            // No scene: every node that is nobody's child is a root.
            std::vector<bool> is_child(model_.nodes.size(), false);
            for (const tinygltf::Node& node : model_.nodes)
                for (int child : node.children)
                    if (child >= 0 && child < static_cast<int>(is_child.size()))
                        is_child[child] = true;
            for (size_t i = 0; i < model_.nodes.size(); ++i)
                if (!is_child[i]) roots.push_back(static_cast<int>(i));
        }
        for (int root : roots) visit(root, glm::dmat4(1.0), 0);
        if (mesh_.triangles.empty()) fail("{}: glTF scene has no triangles", name_);
        mesh_.validate(name_);
        return std::move(mesh_);
    }

  private:
    void visit(int node_index, const glm::dmat4& parent, int depth) {
        // A valid glTF node graph is a forest; the depth bound catches cycles.
        if (depth > static_cast<int>(model_.nodes.size()))
            fail("{}: node hierarchy contains a cycle", name_);
        if (node_index < 0 || node_index >= static_cast<int>(model_.nodes.size()))
            fail("{}: node index {} out of range [0, {})", name_, node_index, model_.nodes.size());
        const tinygltf::Node& node = model_.nodes[node_index];
        const glm::dmat4 world = parent * local_matrix(node);
        if (node.mesh >= 0) add_mesh(node.mesh, world);
        for (int child : node.children) visit(child, world, depth + 1);
    }

    glm::dmat4 local_matrix(const tinygltf::Node& node) const {
        if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major
        // glTF: local = T * R * S.
        glm::dmat4 m(1.0);
        if (node.translation.size() == 3)
            m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
        if (node.rotation.size() == 4) {
            // glTF stores quaternions as (x, y, z, w); glm's constructor takes w first.
            const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1],
                               node.rotation[2]);
            m = m * glm::mat4_cast(glm::normalize(q));
        }
        if (node.scale.size() == 3)
            m = m * glm::dmat4(glm::dvec4(node.scale[0], 0, 0, 0),
                               glm::dvec4(0, node.scale[1], 0, 0),
                               glm::dvec4(0, 0, node.scale[2], 0), glm::dvec4(0, 0, 0, 1));
        return m;
    }

    void add_mesh(int mesh_index, const glm::dmat4& world) {
        if (mesh_index >= static_cast<int>(model_.meshes.size()))
            fail("{}: mesh index {} out of range [0, {})", name_, mesh_index, model_.meshes.size());
        const float det = static_cast<float>(glm::determinant(glm::dmat3(world)));
        if (!(det != 0.0f) || !std::isfinite(det))
            fail("{}: node transform of mesh {} is singular", name_, mesh_index);
        const Transform transform{glm::mat4(world), glm::mat4(glm::inverse(world))};
        const tinygltf::Mesh& mesh = model_.meshes[mesh_index];
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            TriangleMesh part = read_primitive(mesh, p);
            transform_mesh(part, transform);
            append_mesh(mesh_, part);
        }
    }

    TriangleMesh read_primitive(const tinygltf::Mesh& mesh, size_t p) const {
        const tinygltf::Primitive& prim = mesh.primitives[p];
        const std::string what = fmt::format("mesh '{}' primitive {}", mesh.name, p);
        if (prim.mode != -1 && prim.mode != TINYGLTF_MODE_TRIANGLES)
            fail("{}: {} has primitive mode {} ({}); only triangles (4) are supported", name_, what,
                 prim.mode, mode_name(prim.mode));
        const auto pos_it = prim.attributes.find("POSITION");
        if (pos_it == prim.attributes.end()) fail("{}: {} has no POSITION", name_, what);

        TriangleMesh part;
        const AccessorView pos = view(pos_it->second, TINYGLTF_TYPE_VEC3, what + " POSITION");
        require_float(pos, what + " POSITION");
        part.positions.resize(pos.count);
        for (size_t i = 0; i < pos.count; ++i) part.positions[i] = read_vec<3>(pos, i);

        if (auto it = prim.attributes.find("NORMAL"); it != prim.attributes.end()) {
            const AccessorView nrm = view(it->second, TINYGLTF_TYPE_VEC3, what + " NORMAL");
            require_float(nrm, what + " NORMAL");
            if (nrm.count != pos.count)
                fail("{}: {} has {} normals for {} positions", name_, what, nrm.count, pos.count);
            part.normals.resize(nrm.count);
            for (size_t i = 0; i < nrm.count; ++i) part.normals[i] = read_vec<3>(nrm, i);
        }
        if (auto it = prim.attributes.find("TEXCOORD_0"); it != prim.attributes.end()) {
            const AccessorView uv = view(it->second, TINYGLTF_TYPE_VEC2, what + " TEXCOORD_0");
            if (uv.count != pos.count)
                fail("{}: {} has {} uvs for {} positions", name_, what, uv.count, pos.count);
            part.uvs.resize(uv.count);
            for (size_t i = 0; i < uv.count; ++i) part.uvs[i] = read_vec<2>(uv, i);
        }

        std::vector<uint32_t> indices;
        if (prim.indices >= 0) {
            const AccessorView idx = view(prim.indices, TINYGLTF_TYPE_SCALAR, what + " indices");
            indices.resize(idx.count);
            for (size_t i = 0; i < idx.count; ++i) indices[i] = read_index(idx, i, what);
        } else {
            indices.resize(pos.count);
            for (size_t i = 0; i < pos.count; ++i) indices[i] = static_cast<uint32_t>(i);
        }
        if (indices.size() % 3 != 0)
            fail("{}: {} has {} indices, not a multiple of 3", name_, what, indices.size());
        for (size_t i = 0; i < indices.size(); i += 3)
            part.triangles.emplace_back(indices[i], indices[i + 1], indices[i + 2]);
        // Check indices and values before the part is transformed and merged,
        // so the message names the primitive.
        part.validate(fmt::format("{}: {}", name_, what));
        return part;
    }

    static const char* mode_name(int mode) {
        switch (mode) {
            case TINYGLTF_MODE_POINTS:
                return "points";
            case TINYGLTF_MODE_LINE:
                return "lines";
            case TINYGLTF_MODE_LINE_LOOP:
                return "line loop";
            case TINYGLTF_MODE_LINE_STRIP:
                return "line strip";
            case TINYGLTF_MODE_TRIANGLE_STRIP:
                return "triangle strip";
            case TINYGLTF_MODE_TRIANGLE_FAN:
                return "triangle fan";
            default:
                return "unknown";
        }
    }

    AccessorView view(int accessor_index, int type, const std::string& what) const {
        if (accessor_index < 0 || accessor_index >= static_cast<int>(model_.accessors.size()))
            fail("{}: {} accessor {} out of range [0, {})", name_, what, accessor_index,
                 model_.accessors.size());
        const tinygltf::Accessor& acc = model_.accessors[accessor_index];
        if (acc.sparse.isSparse) fail("{}: {} uses a sparse accessor (unsupported)", name_, what);
        if (acc.type != type)
            fail("{}: {} accessor has type {}, expected {}", name_, what, acc.type, type);
        if (acc.bufferView < 0 || acc.bufferView >= static_cast<int>(model_.bufferViews.size()))
            fail("{}: {} accessor has no valid bufferView", name_, what);
        const tinygltf::BufferView& bv = model_.bufferViews[acc.bufferView];
        if (bv.buffer < 0 || bv.buffer >= static_cast<int>(model_.buffers.size()))
            fail("{}: {} bufferView has no valid buffer", name_, what);
        const tinygltf::Buffer& buffer = model_.buffers[bv.buffer];
        const int stride = acc.ByteStride(bv);
        if (stride <= 0) fail("{}: {} has an invalid byte stride", name_, what);
        const size_t element =
            static_cast<size_t>(
                tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(acc.componentType))) *
            static_cast<size_t>(tinygltf::GetNumComponentsInType(static_cast<uint32_t>(acc.type)));
        // The last element must end inside both the view and the buffer.
        const size_t end =
            acc.count == 0 ? acc.byteOffset : acc.byteOffset + (acc.count - 1) * stride + element;
        if (end > bv.byteLength || bv.byteOffset + bv.byteLength > buffer.data.size())
            fail("{}: {} accessor reads past the end of its buffer", name_, what);
        AccessorView v;
        v.data = buffer.data.data() + bv.byteOffset + acc.byteOffset;
        v.stride = static_cast<size_t>(stride);
        v.count = acc.count;
        v.component_type = acc.componentType;
        v.normalized = acc.normalized;
        return v;
    }

    void require_float(const AccessorView& v, const std::string& what) const {
        if (v.component_type != TINYGLTF_COMPONENT_TYPE_FLOAT)
            fail("{}: {} must have float components, got component type {}", name_, what,
                 v.component_type);
    }

    template <int Dim>
    glm::vec<Dim, float> read_vec(const AccessorView& v, size_t i) const {
        const unsigned char* p = v.data + i * v.stride;
        glm::vec<Dim, float> out;
        for (int k = 0; k < Dim; ++k) out[k] = read_component(v, p, k);
        return out;
    }

    float read_component(const AccessorView& v, const unsigned char* p, int k) const {
        switch (v.component_type) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: {
                float f;
                std::memcpy(&f, p + 4 * k, 4);
                return f;
            }
            // Normalized integer texture coordinates (glTF 2.0 §3.11).
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                if (v.normalized) return static_cast<float>(p[k]) / 255.0f;
                break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
                if (v.normalized) {
                    uint16_t s;
                    std::memcpy(&s, p + 2 * k, 2);
                    return static_cast<float>(s) / 65535.0f;
                }
                break;
            default:
                break;
        }
        fail("{}: unsupported component type {} (normalized = {})", name_, v.component_type,
             v.normalized);
    }

    uint32_t read_index(const AccessorView& v, size_t i, const std::string& what) const {
        const unsigned char* p = v.data + i * v.stride;
        switch (v.component_type) {
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                return p[0];
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                uint16_t s;
                std::memcpy(&s, p, 2);
                return s;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
                uint32_t u;
                std::memcpy(&u, p, 4);
                return u;
            }
            default:
                fail("{}: {} index component type {} is not u8/u16/u32", name_, what,
                     v.component_type);
        }
    }

    const tinygltf::Model& model_;
    std::string name_;
    TriangleMesh mesh_;
};

}  // namespace

TriangleMesh load_gltf(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) fail("{}: glTF file not found", name);

    // Binary glTF starts with the magic "glTF" (glTF 2.0 §4.4.3.1).
    char magic[4] = {};
    {
        std::ifstream in(path, std::ios::binary);
        in.read(magic, 4);
    }
    const bool binary = std::memcmp(magic, "glTF", 4) == 0;

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skip_image, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    const bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, name)
                           : loader.LoadASCIIFromFile(&model, &err, &warn, name);
    if (!ok) fail("{}: cannot parse glTF: {}", name, err.empty() ? warn : err);
    return GltfReader(model, name).read_scene();
}

}  // namespace glintlab
