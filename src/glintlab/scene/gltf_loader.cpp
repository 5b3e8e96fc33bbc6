#include "glintlab/scene/gltf_loader.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

// tinygltf is built without its stb_image dependency (another module owns
// STB_IMAGE_IMPLEMENTATION): images are decoded by glintlab's own hardened
// readers, and only those a used material reads.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <draco/compression/decode.h>
#include <draco/core/decoder_buffer.h>
#include <nlohmann/json.hpp>

#include "glintlab/core/error.h"
#include "glintlab/core/json_depth.h"
#include "glintlab/core/regular_file.h"
#include "glintlab/core/texture_image.h"
#include "glintlab/scene/draco_header.h"
#include "glintlab/scene/gltf_materials.h"
#include "glintlab/scene/transform.h"

namespace glintlab {

namespace {

constexpr const char* kDracoExtension = "KHR_draco_mesh_compression";

// Images are decoded by glintlab's own readers (core/texture_image.h), and
// only those a used material reads: tinygltf keeps the encoded bytes.
// Images in data URIs keep their bytes here; those in buffer views are read
// from their view, range-checked, when a material needs them.
bool keep_encoded_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                        const unsigned char* bytes, int size, void*) {
    if (image->bufferView < 0 && size > 0) image->image.assign(bytes, bytes + size);
    image->as_is = true;
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
    // `uv_sets[m]`: the TEXCOORD set material m's textures read. `merge`:
    // one part for every primitive (TEXCOORD_0), else one per material.
    GltfReader(const tinygltf::Model& model, std::string name, std::vector<int> uv_sets, bool merge)
        : model_(model), name_(std::move(name)), uv_sets_(std::move(uv_sets)), merge_(merge) {}

    std::vector<GltfScene::Part> read_scene() {
        // glTF 2.0 (§3.5.3): the node graph is a forest, every node has at
        // most one parent. A node with two parents would be instanced once
        // per path, and chains of such nodes multiply the paths
        // exponentially, so it is an error like a cycle.
        const int count = static_cast<int>(model_.nodes.size());
        std::vector<int> parent(model_.nodes.size(), -1);
        for (int i = 0; i < count; ++i)
            for (int child : model_.nodes[i].children) {
                if (child < 0 || child >= count)
                    fail("{}: node {} has child index {} out of range [0, {})", name_, i, child,
                         count);
                if (parent[child] >= 0)
                    fail(
                        "{}: node {} is a child of both node {} and node {} (glTF nodes have at "
                        "most one parent)",
                        name_, child, parent[child], i);
                parent[child] = i;
            }
        std::vector<int> roots;
        if (!model_.scenes.empty()) {
            const int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
            if (scene >= static_cast<int>(model_.scenes.size()))
                fail("{}: default scene {} out of range [0, {})", name_, scene,
                     model_.scenes.size());
            roots = model_.scenes[scene].nodes;
        } else {
            // No scene: every node that is nobody's child is a root.
            for (int i = 0; i < count; ++i)
                if (parent[i] < 0) roots.push_back(i);
            if (roots.empty() && count > 0) {
                // Every node has one parent, so following parents from node 0
                // must end on a cycle; n steps land on a node of it.
                int node = 0;
                for (int step = 0; step < count; ++step) node = parent[node];
                fail(
                    "{}: node hierarchy contains a cycle (through node {}): every node is "
                    "another node's child",
                    name_, node);
            }
        }
        on_path_.assign(model_.nodes.size(), 0);
        for (int root : roots) visit(root);
        size_t triangles = 0;
        for (const GltfScene::Part& part : parts_) triangles += part.mesh.triangles.size();
        if (triangles == 0) fail("{}: glTF scene has no triangles", name_);
        std::vector<GltfScene::Part> parts;
        for (GltfScene::Part& part : parts_) {
            if (part.mesh.triangles.empty()) continue;
            part.mesh.validate(name_);
            parts.push_back(std::move(part));
        }
        return parts;
    }

  private:
    // Depth-first walk of the hierarchy under `root` with an explicit stack:
    // chains tens of thousands of nodes deep are legal glTF and would
    // overflow the call stack if walked recursively. A valid node graph is a
    // forest; a child that is already on the current path closes a cycle.
    void visit(int root) {
        struct Frame {
            int node;
            glm::dmat4 world;
            size_t next_child;
        };
        const int count = static_cast<int>(model_.nodes.size());
        std::vector<char>& on_path = on_path_;  // all 0 between walks
        std::vector<Frame> stack;
        auto enter = [&](int node, const glm::dmat4& parent, int parent_node) {
            if (node < 0 || node >= count) {
                if (parent_node < 0)
                    fail("{}: root node index {} out of range [0, {})", name_, node, count);
                fail("{}: node {} has child index {} out of range [0, {})", name_, parent_node,
                     node, count);
            }
            if (on_path[node])
                fail(
                    "{}: node hierarchy contains a cycle: node {} is its own ancestor "
                    "(reached again as a child of node {})",
                    name_, node, parent_node);
            on_path[node] = 1;
            const tinygltf::Node& n = model_.nodes[node];
            stack.push_back({node, parent * local_matrix(n), 0});
            if (n.mesh >= 0) add_mesh(n.mesh, stack.back().world);
        };
        enter(root, glm::dmat4(1.0), -1);
        while (!stack.empty()) {
            Frame& top = stack.back();
            const std::vector<int>& children = model_.nodes[top.node].children;
            if (top.next_child == children.size()) {
                on_path[top.node] = 0;
                stack.pop_back();
                continue;
            }
            const int child = children[top.next_child++];
            // Copy: enter() may reallocate the stack.
            const glm::dmat4 world = top.world;
            const int parent = top.node;
            enter(child, world, parent);
        }
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
            const int material = merge_ ? -1 : mesh.primitives[p].material;
            if (material >= static_cast<int>(model_.materials.size()))
                fail("{}: mesh '{}' primitive {} names material {}, out of range [0, {})", name_,
                     mesh.name, p, material, model_.materials.size());
            const int uv_set = material >= 0 ? uv_sets_[static_cast<size_t>(material)] : 0;
            TriangleMesh part = read_primitive(mesh, p, fmt::format("TEXCOORD_{}", uv_set));
            transform_mesh(part, transform);
            append_mesh(part_of(material), part);
        }
    }

    TriangleMesh& part_of(int material) {
        for (GltfScene::Part& part : parts_)
            if (part.material == material) return part.mesh;
        parts_.push_back({TriangleMesh{}, material});
        return parts_.back().mesh;
    }

    TriangleMesh read_primitive(const tinygltf::Mesh& mesh, size_t p,
                                const std::string& uv_attribute) const {
        const tinygltf::Primitive& prim = mesh.primitives[p];
        const std::string what = fmt::format("mesh '{}' primitive {}", mesh.name, p);
        if (prim.mode != -1 && prim.mode != TINYGLTF_MODE_TRIANGLES)
            fail("{}: {} has primitive mode {} ({}); only triangles (4) are supported", name_, what,
                 prim.mode, mode_name(prim.mode));
        const auto pos_it = prim.attributes.find("POSITION");
        if (pos_it == prim.attributes.end()) fail("{}: {} has no POSITION", name_, what);
        if (auto ext = prim.extensions.find(kDracoExtension); ext != prim.extensions.end())
            return read_draco_primitive(prim, ext->second, what, uv_attribute);

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
        if (auto it = prim.attributes.find("TANGENT"); it != prim.attributes.end()) {
            // glTF's tangents (xyz along ∂p/∂u, w the bitangent sign): the
            // normal map's tangent space as the asset was baked.
            const AccessorView tan = view(it->second, TINYGLTF_TYPE_VEC4, what + " TANGENT");
            require_float(tan, what + " TANGENT");
            if (tan.count != pos.count)
                fail("{}: {} has {} tangents for {} positions", name_, what, tan.count, pos.count);
            part.tangents.resize(tan.count);
            for (size_t i = 0; i < tan.count; ++i) {
                glm::vec4 t = read_vec<4>(tan, i);
                // glTF requires w = ±1; other values keep their sign.
                if (std::isfinite(t.w)) t.w = t.w < 0.0f ? -1.0f : 1.0f;
                part.tangents[i] = t;
            }
        }
        if (auto it = prim.attributes.find(uv_attribute); it != prim.attributes.end()) {
            const AccessorView uv = view(it->second, TINYGLTF_TYPE_VEC2, what + " " + uv_attribute);
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

    // KHR_draco_mesh_compression: the extension names a bufferView holding
    // one Draco-encoded mesh and maps glTF attribute names to Draco unique
    // attribute ids. Attributes the extension does not name are read from
    // their accessors as usual; they must have one element per Draco point.
    // Draco dequantises positions/uvs and unpacks octahedral normals itself.
    TriangleMesh read_draco_primitive(const tinygltf::Primitive& prim, const tinygltf::Value& ext,
                                      const std::string& what,
                                      const std::string& uv_attribute) const {
        const std::string where = fmt::format("{}: {} {}", name_, what, kDracoExtension);
        if (!ext.IsObject()) fail("{} is not an object", where);
        const tinygltf::Value& bv_value = ext.Get("bufferView");
        if (!bv_value.IsInt()) fail("{}: \"bufferView\" must be an integer", where);
        const int bv_index = bv_value.Get<int>();
        if (bv_index < 0 || bv_index >= static_cast<int>(model_.bufferViews.size()))
            fail("{}: bufferView {} out of range [0, {})", where, bv_index,
                 model_.bufferViews.size());
        const tinygltf::BufferView& bv = model_.bufferViews[bv_index];
        if (bv.buffer < 0 || bv.buffer >= static_cast<int>(model_.buffers.size()))
            fail("{}: bufferView {} has no valid buffer", where, bv_index);
        const tinygltf::Buffer& buffer = model_.buffers[bv.buffer];
        if (bv.byteOffset > buffer.data.size() ||
            bv.byteLength > buffer.data.size() - bv.byteOffset)
            fail("{}: bufferView {} reads past the end of its buffer", where, bv_index);
        const tinygltf::Value& attributes = ext.Get("attributes");
        if (!attributes.IsObject()) fail("{}: \"attributes\" must be an object", where);

        const char* encoded = reinterpret_cast<const char*>(buffer.data.data() + bv.byteOffset);
        if (const auto sizes = read_draco_mesh_sizes(encoded, bv.byteLength))
            require_draco_memory(*sizes, fmt::format("{} bufferView {}", where, bv_index));
        draco::DecoderBuffer input;
        input.Init(encoded, bv.byteLength);
        draco::Decoder decoder;
        auto decoded = decoder.DecodeMeshFromBuffer(&input);
        if (!decoded.ok())
            fail("{}: Draco cannot decode bufferView {}: {}", where, bv_index,
                 decoded.status().error_msg_string());
        const std::unique_ptr<draco::Mesh> draco_mesh = std::move(decoded).value();
        if (!draco_mesh) fail("{}: Draco decoded no mesh from bufferView {}", where, bv_index);
        const size_t points = draco_mesh->num_points();

        // One attribute: from Draco when the extension names it, else from
        // its accessor; empty when the primitive has no such attribute.
        auto read = [&]<int Dim>(const char* semantic, int type) {
            std::vector<glm::vec<Dim, float>> out;
            const auto it = prim.attributes.find(semantic);
            if (!attributes.Has(semantic)) {
                if (it == prim.attributes.end()) return out;
                const AccessorView v = view(it->second, type, what + " " + semantic);
                if (!std::string_view(semantic).starts_with("TEXCOORD_"))
                    require_float(v, what + " " + semantic);
                if (v.count != points)
                    fail("{}: {} accessor has {} elements for {} Draco points", where, semantic,
                         v.count, points);
                out.resize(points);
                for (size_t i = 0; i < points; ++i) out[i] = read_vec<Dim>(v, i);
                return out;
            }
            if (it == prim.attributes.end())
                fail("{}: attribute {} is not among the primitive's attributes", where, semantic);
            const tinygltf::Value& id = attributes.Get(semantic);
            if (!id.IsInt() || id.Get<int>() < 0)
                fail("{}: attribute {} must map to a non-negative Draco attribute id", where,
                     semantic);
            const draco::PointAttribute* a =
                draco_mesh->GetAttributeByUniqueId(static_cast<uint32_t>(id.Get<int>()));
            if (!a)
                fail("{}: the Draco mesh has no attribute with id {} (for {})", where,
                     id.Get<int>(), semantic);
            if (a->num_components() != Dim)
                fail("{}: Draco attribute {} ({}) has {} components, expected {}", where,
                     id.Get<int>(), semantic, a->num_components(), Dim);
            // The accessor stays the authority on the element count.
            const tinygltf::Accessor& acc = model_.accessors.at(static_cast<size_t>(it->second));
            if (acc.count != points)
                fail("{}: {} accessor count {} differs from the {} decoded Draco points", where,
                     semantic, acc.count, points);
            out.resize(points);
            for (size_t i = 0; i < points; ++i) {
                const draco::AttributeValueIndex value =
                    a->mapped_index(draco::PointIndex(static_cast<uint32_t>(i)));
                if (value.value() >= a->size() ||
                    !a->ConvertValue<float>(value, Dim, glm::value_ptr(out[i])))
                    fail("{}: Draco attribute {} ({}) cannot be read at point {}", where,
                         id.Get<int>(), semantic, i);
            }
            return out;
        };
        // Accessor indices of attributes were range-checked by tinygltf's
        // parser only when they have a bufferView; check them here.
        for (const auto& [semantic, index] : prim.attributes)
            if (index < 0 || index >= static_cast<int>(model_.accessors.size()))
                fail("{}: {} accessor {} out of range [0, {})", where, semantic, index,
                     model_.accessors.size());

        TriangleMesh part;
        part.positions = read.template operator()<3>("POSITION", TINYGLTF_TYPE_VEC3);
        part.normals = read.template operator()<3>("NORMAL", TINYGLTF_TYPE_VEC3);
        part.uvs = read.template operator()<2>(uv_attribute.c_str(), TINYGLTF_TYPE_VEC2);
        part.tangents = read.template operator()<4>("TANGENT", TINYGLTF_TYPE_VEC4);
        for (glm::vec4& t : part.tangents)
            if (std::isfinite(t.w)) t.w = t.w < 0.0f ? -1.0f : 1.0f;  // quantised ±1
        part.triangles.reserve(draco_mesh->num_faces());
        for (draco::FaceIndex f(0); f < draco_mesh->num_faces(); ++f) {
            const draco::Mesh::Face& face = draco_mesh->face(f);
            part.triangles.emplace_back(face[0].value(), face[1].value(), face[2].value());
        }
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
    std::vector<int> uv_sets_;
    bool merge_ = false;
    std::vector<GltfScene::Part> parts_;
    std::vector<char> on_path_;  // per node: on the path of the current walk
};

}  // namespace

namespace {

// Extensions a file may list as required. Material and texture extensions
// only change how surfaces look in other renderers; glintlab reads geometry
// alone, so they do not change what it loads.
bool extension_supported(const std::string& name) {
    return name == kDracoExtension || name.starts_with("KHR_materials_") ||
           name.starts_with("KHR_texture_") || name.starts_with("EXT_texture_");
}

uint32_t get32(const std::string& bytes, size_t offset) {
    uint32_t v = 0;
    for (int b = 0; b < 4; ++b)
        v |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[offset + b])) << (8 * b);
    return v;
}

void put32(std::string& bytes, uint32_t v) {
    for (int b = 0; b < 4; ++b) bytes.push_back(static_cast<char>((v >> (8 * b)) & 0xff));
}

// tinygltf's parser rejects a primitive whose "indices" accessor has no
// bufferView, which is how KHR_draco_mesh_compression stores its indices
// (inside the Draco stream). Unless tinygltf decodes Draco itself
// (TINYGLTF_ENABLE_DRACO, which indexes bufferViews and Draco attributes
// without range checks), such files cannot be parsed. So the "indices" of
// Draco primitives are dropped from the JSON before tinygltf sees it; the
// reader takes the indices from the decoded Draco faces. Returns the
// rewritten file, or nothing when the file has no Draco primitive with
// indices (or is malformed: then tinygltf reports the problem).
// The JSON text of a glTF file; of a GLB, its JSON chunk (12-byte header,
// then the chunk's length, "JSON", text). Empty when the GLB is malformed
// (tinygltf then reports the problem).
std::string_view gltf_json_text(const std::string& file, bool binary) {
    if (!binary) return file;
    if (file.size() < 20 || get32(file, 16) != 0x4E4F534Au) return {};
    const size_t json_length = get32(file, 12);
    if (json_length > file.size() - 20) return {};
    return std::string_view(file.data() + 20, json_length);
}

std::optional<std::string> strip_draco_indices(const std::string& file, bool binary) {
    const std::string_view text = gltf_json_text(file, binary);
    if (binary && text.empty()) return std::nullopt;
    const size_t json_begin = binary ? 20 : 0, json_length = text.size();
    if (text.find(kDracoExtension) == std::string_view::npos) return std::nullopt;
    nlohmann::json doc = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (doc.is_discarded() || !doc.is_object() || !doc.contains("meshes") ||
        !doc["meshes"].is_array())
        return std::nullopt;
    bool changed = false;
    for (nlohmann::json& mesh : doc["meshes"]) {
        if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array())
            continue;
        for (nlohmann::json& prim : mesh["primitives"]) {
            if (!prim.is_object() || !prim.contains("indices") || !prim.contains("extensions") ||
                !prim["extensions"].is_object() || !prim["extensions"].contains(kDracoExtension))
                continue;
            prim.erase("indices");
            changed = true;
        }
    }
    if (!changed) return std::nullopt;
    std::string json_text = doc.dump();
    if (!binary) return json_text;
    while (json_text.size() % 4 != 0) json_text += ' ';
    // The chunks after the JSON chunk (BIN) are kept byte for byte.
    const size_t rest = json_begin + ((json_length + 3) / 4) * 4;
    const std::string tail = rest < file.size() ? file.substr(rest) : std::string();
    std::string out = file.substr(0, 8);
    put32(out, static_cast<uint32_t>(12 + 8 + json_text.size() + tail.size()));
    put32(out, static_cast<uint32_t>(json_text.size()));
    put32(out, 0x4E4F534Au);  // "JSON"
    out += json_text;
    out += tail;
    return out;
}

}  // namespace

namespace {

std::string read_file(const std::filesystem::path& path) {
    const std::string name = path.string();
    if (const std::string problem = regular_file_problem(path); !problem.empty())
        fail("{}: the glTF file {}", name, problem);
    std::ifstream in(path, std::ios::binary);
    if (!in) fail("{}: cannot open glTF file", name);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool is_binary(const std::string& file) {
    // Binary glTF starts with the magic "glTF" (glTF 2.0 §4.4.3.1).
    return file.size() >= 4 && std::memcmp(file.data(), "glTF", 4) == 0;
}

tinygltf::Model parse_model(const std::string& file, const std::string& name,
                            const std::filesystem::path& base_dir) {
    const bool binary = is_binary(file);
    // tinygltf walks its JSON recursively (extras, extensions): a deep
    // nesting would overflow the stack, so it is refused before parsing.
    if (const size_t depth = json_nesting_depth(gltf_json_text(file, binary));
        depth > kMaxJsonNesting)
        fail("{}: glTF JSON nests arrays and objects {} levels deep (at most {} are read)", name,
             depth, kMaxJsonNesting);

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keep_encoded_image, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    const std::optional<std::string> rewritten = strip_draco_indices(file, binary);
    const std::string& bytes = rewritten ? *rewritten : file;
    if (bytes.size() > std::numeric_limits<unsigned int>::max())
        fail("{}: glTF file too large", name);
    const auto size = static_cast<unsigned int>(bytes.size());
    const std::string dir = base_dir.string();
    const bool ok =
        binary ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                             reinterpret_cast<const unsigned char*>(bytes.data()),
                                             size, dir)
               : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), size, dir);
    if (!ok) fail("{}: cannot parse glTF: {}", name, err.empty() ? warn : err);
    for (const std::string& ext : model.extensionsRequired)
        if (!extension_supported(ext))
            fail(
                "{}: required glTF extension \"{}\" is not supported (supported: {}; material "
                "and texture extensions are accepted, and those not read are named in a "
                "warning)",
                name, ext, kDracoExtension);
    return model;
}

// How texture blocks name image i: its file (an external uri, resolved
// against the glTF file's folder) or an in-memory name for images stored in
// the file (a buffer view or a data uri).
std::vector<std::string> image_names(const tinygltf::Model& model, const std::string& name,
                                     const std::filesystem::path& base_dir) {
    std::vector<std::string> names;
    for (size_t i = 0; i < model.images.size(); ++i) {
        const tinygltf::Image& image = model.images[i];
        if (image.bufferView < 0 && !image.uri.empty() && !tinygltf::IsDataURI(image.uri))
            names.push_back((base_dir / tinygltf::dlib::urldecode(image.uri)).string());
        else
            names.push_back(fmt::format("<{} image {}>", name, i));
    }
    return names;
}

// The encoded bytes of an image stored in the file.
std::string embedded_image_bytes(const tinygltf::Model& model, int index,
                                 const std::string& image_name) {
    const tinygltf::Image& image = model.images[static_cast<size_t>(index)];
    if (image.bufferView < 0) {
        if (image.image.empty()) fail("{}: the image holds no data", image_name);
        return std::string(image.image.begin(), image.image.end());
    }
    if (image.bufferView >= static_cast<int>(model.bufferViews.size()))
        fail("{}: bufferView {} out of range [0, {})", image_name, image.bufferView,
             model.bufferViews.size());
    const tinygltf::BufferView& bv = model.bufferViews[static_cast<size_t>(image.bufferView)];
    if (bv.buffer < 0 || bv.buffer >= static_cast<int>(model.buffers.size()))
        fail("{}: bufferView {} has no valid buffer", image_name, image.bufferView);
    const std::vector<unsigned char>& data = model.buffers[static_cast<size_t>(bv.buffer)].data;
    if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset)
        fail("{}: bufferView {} reads past the end of its buffer", image_name, image.bufferView);
    const auto* begin = reinterpret_cast<const char*>(data.data() + bv.byteOffset);
    return std::string(begin, bv.byteLength);
}

GltfScene read_gltf(const std::string& file, const std::string& name,
                    const std::filesystem::path& base_dir, bool merge) {
    const tinygltf::Model model = parse_model(file, name, base_dir);
    GltfScene scene;
    scene.file_materials = model.materials.size();
    if (merge) {
        scene.parts = GltfReader(model, name, {}, true).read_scene();
        return scene;
    }
    const std::vector<std::string> images = image_names(model, name, base_dir);
    const nlohmann::json document = nlohmann::json::parse(gltf_json_text(file, is_binary(file)),
                                                          nullptr, /*allow_exceptions=*/false);
    std::vector<int> uv_sets;
    for (size_t m = 0; m < model.materials.size(); ++m) {
        scene.materials.push_back(translate_gltf_material(document, int(m), images, name));
        uv_sets.push_back(scene.materials.back().uv_set);
    }
    scene.default_material = translate_gltf_material(document, -1, images, name);
    scene.parts = GltfReader(model, name, std::move(uv_sets), false).read_scene();
    for (const GltfScene::Part& part : scene.parts) {
        if (part.material < 0) continue;
        for (int image : scene.materials[static_cast<size_t>(part.material)].images) {
            const std::string& image_name = images[static_cast<size_t>(image)];
            if (!image_name.starts_with("<") || scene.images.contains(image_name)) continue;
            scene.images.emplace(image_name,
                                 std::make_shared<const TextureImage>(decode_texture_image(
                                     embedded_image_bytes(model, image, image_name), image_name)));
        }
    }
    return scene;
}

}  // namespace

GltfScene load_gltf_scene(const std::filesystem::path& path) {
    return read_gltf(read_file(path), path.string(), path.parent_path(), false);
}

GltfScene load_gltf_scene_bytes(const std::string& bytes, const std::string& name,
                                const std::filesystem::path& base_dir) {
    return read_gltf(bytes, name, base_dir, false);
}

TriangleMesh load_gltf(const std::filesystem::path& path, size_t* file_materials) {
    return load_gltf_bytes(read_file(path), path.string(), path.parent_path(), file_materials);
}

TriangleMesh load_gltf_bytes(const std::string& file, const std::string& name,
                             const std::filesystem::path& base_dir, size_t* file_materials) {
    GltfScene scene = read_gltf(file, name, base_dir, true);
    if (file_materials) *file_materials = scene.file_materials;
    return std::move(scene.parts.front().mesh);
}

}  // namespace glintlab
