// SPDX-License-Identifier: MIT
// glTF 2.0 writer on tinygltf (the Debian package ships it compiled, so no
// TINYGLTF_IMPLEMENTATION here): one mesh and node per source surface, and
// the primitives every glTF writer builds (gltf_primitives.h).
#include <seamless/base/error.h>
#include <seamless/mesh/io/gltf_io.h>
#include <seamless/mesh/io/gltf_primitives.h>
#include <seamless/mesh/io/mesh_text.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace seamless {
namespace {

constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

// Appends `bytes` to the buffer as a new bufferView (4-byte aligned) and returns its index.
int add_view(tinygltf::Model& model, const void* bytes, size_t size, int target) {
    auto& data = model.buffers[0].data;
    while (data.size() % 4 != 0) data.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = size;
    view.target = target;
    const auto* p = static_cast<const unsigned char*>(bytes);
    data.insert(data.end(), p, p + size);
    model.bufferViews.push_back(view);
    return static_cast<int>(model.bufferViews.size()) - 1;
}

int add_accessor(tinygltf::Model& model, int view, int component, size_t count, int type) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.byteOffset = 0;
    a.componentType = component;
    a.count = count;
    a.type = type;
    model.accessors.push_back(a);
    return static_cast<int>(model.accessors.size()) - 1;
}

// A float attribute of `count` elements of `type` in a view of its own.
int add_float_attribute(tinygltf::Model& model, const std::vector<float>& values, size_t count,
                        int type) {
    return add_accessor(model,
                        add_view(model, values.data(), values.size() * sizeof(float), kArrayBuffer),
                        TINYGLTF_COMPONENT_TYPE_FLOAT, count, type);
}

// The unit normal of corner c of triangle t, renormalised in float so the
// validator's unit-length test holds.
std::array<float, 3> corner_normal(const TriangleMesh& mesh, int t, int c) {
    Vec3 d = normalize(mesh.corner_normals[t][c]);
    if (!(norm(d) > 0.5)) { // zero or non-finite: fall back to the face normal
        const auto& f = mesh.triangles[t];
        d = normalize(cross(mesh.positions[f[1]] - mesh.positions[f[0]],
                            mesh.positions[f[2]] - mesh.positions[f[0]]));
        if (!(norm(d) > 0.5)) d = {0, 0, 1};
    }
    float fx = static_cast<float>(d.x), fy = static_cast<float>(d.y), fz = static_cast<float>(d.z);
    const float l = std::sqrt(fx * fx + fy * fy + fz * fz);
    return {fx / l, fy / l, fz / l};
}

// A vertex of one primitive: the source vertex and, when present, the corner's
// float normal and uv (so corners that agree share a vertex, others are split).
using VertexKey = std::tuple<int, float, float, float, float, float>;

// The vertex arrays and indices of one primitive.
struct PrimitiveArrays {
    std::vector<float> pos, nrm, uv;
    std::vector<uint32_t> indices;
    size_t vertices() const { return pos.size() / 3; }
};

PrimitiveArrays primitive_arrays(const TriangleMesh& mesh, const std::vector<int>& tris,
                                 CornerData has, double scale) {
    PrimitiveArrays a;
    std::map<VertexKey, uint32_t> index_of;
    a.indices.reserve(3 * tris.size());
    for (int t : tris) {
        for (int c = 0; c < 3; ++c) {
            const int v = mesh.triangles[t][c];
            std::array<float, 3> n{0, 0, 0};
            float w[2] = {0, 0};
            if (has.normals) n = corner_normal(mesh, t, c);
            if (has.uvs) {
                w[0] = static_cast<float>(mesh.corner_uvs[t][c][0]);
                w[1] = static_cast<float>(mesh.corner_uvs[t][c][1]);
            }
            const VertexKey key{v, n[0], n[1], n[2], w[0], w[1]};
            auto [it, inserted] = index_of.try_emplace(key, static_cast<uint32_t>(a.vertices()));
            if (inserted) {
                const Vec3 p = scale * mesh.positions[v];
                a.pos.insert(a.pos.end(), {static_cast<float>(p.x), static_cast<float>(p.y),
                                           static_cast<float>(p.z)});
                if (has.normals) a.nrm.insert(a.nrm.end(), n.begin(), n.end());
                if (has.uvs) a.uv.insert(a.uv.end(), w, w + 2);
            }
            a.indices.push_back(it->second);
        }
    }
    return a;
}

// The primitive's accessors and views, appended to the model's buffer.
tinygltf::Primitive add_primitive(tinygltf::Model& model, const PrimitiveArrays& a,
                                  CornerData has) {
    const size_t nv = a.vertices();
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    const int pa = add_float_attribute(model, a.pos, nv, TINYGLTF_TYPE_VEC3);
    // POSITION needs min and max (glTF 2.0, 3.7.2.1), exactly the float values stored.
    std::vector<double> lo(3, HUGE_VAL), hi(3, -HUGE_VAL);
    for (size_t i = 0; i < nv; ++i)
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], static_cast<double>(a.pos[3 * i + k]));
            hi[k] = std::max(hi[k], static_cast<double>(a.pos[3 * i + k]));
        }
    model.accessors[pa].minValues = lo;
    model.accessors[pa].maxValues = hi;
    prim.attributes["POSITION"] = pa;
    if (has.normals)
        prim.attributes["NORMAL"] = add_float_attribute(model, a.nrm, nv, TINYGLTF_TYPE_VEC3);
    if (has.uvs)
        prim.attributes["TEXCOORD_0"] = add_float_attribute(model, a.uv, nv, TINYGLTF_TYPE_VEC2);
    prim.indices = add_accessor(
        model,
        add_view(model, a.indices.data(), a.indices.size() * sizeof(uint32_t), kElementArrayBuffer),
        TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, a.indices.size(), TINYGLTF_TYPE_SCALAR);
    return prim;
}

// A mesh of one primitive and a node showing it, named after the surface.
void add_surface_node(tinygltf::Model& model, tinygltf::Scene& scene, const TriangleMesh& mesh,
                      int surface, tinygltf::Primitive prim) {
    tinygltf::Mesh gmesh;
    gmesh.name = surface >= 0 && surface < static_cast<int>(mesh.surface_names.size())
                     ? mesh.surface_names[surface]
                     : "surface" + std::to_string(surface);
    gmesh.primitives.push_back(std::move(prim));
    model.meshes.push_back(gmesh);
    tinygltf::Node node;
    node.name = gmesh.name;
    node.mesh = static_cast<int>(model.meshes.size()) - 1;
    model.nodes.push_back(node);
    scene.nodes.push_back(static_cast<int>(model.nodes.size()) - 1);
}

} // namespace

tinygltf::Model new_gltf_model() {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "seamless";
    model.buffers.resize(1);
    return model;
}

tinygltf::Primitive add_triangles(tinygltf::Model& model, const TriangleMesh& mesh,
                                  const std::vector<int>& tris, CornerData has, double scale) {
    return add_primitive(model, primitive_arrays(mesh, tris, has, scale), has);
}

namespace {

// [[id, first, count], ...]: the runs of consecutive triangles of `tris`
// with one id (id_of[t]).
tinygltf::Value id_runs(const std::vector<int>& tris, const std::vector<int>& id_of) {
    tinygltf::Value::Array runs;
    for (size_t k = 0; k < tris.size();) {
        size_t end = k + 1;
        while (end < tris.size() && id_of[tris[end]] == id_of[tris[k]]) ++end;
        runs.emplace_back(tinygltf::Value::Array{tinygltf::Value(id_of[tris[k]]),
                                                 tinygltf::Value(static_cast<int>(k)),
                                                 tinygltf::Value(static_cast<int>(end - k))});
        k = end;
    }
    return tinygltf::Value(std::move(runs));
}

} // namespace

void add_face_extras(tinygltf::Primitive& prim, const std::vector<int>& tris,
                     const std::vector<int>& face_of, const std::vector<int>& solid_of) {
    if (face_of.empty() && solid_of.empty()) return;
    tinygltf::Value::Object extras;
    if (!face_of.empty()) extras["faces"] = id_runs(tris, face_of);
    if (!solid_of.empty()) extras["solids"] = id_runs(tris, solid_of);
    prim.extras = tinygltf::Value(std::move(extras));
}

void finish_and_write(tinygltf::Model& model, const std::filesystem::path& path, bool binary,
                      const std::string& name) {
    // The glb BIN chunk must be padded to 4 bytes (tinygltf pads, but keep the length honest).
    while (model.buffers[0].data.size() % 4 != 0) model.buffers[0].data.push_back(0);
    if (model.buffers[0].data.empty()) model.buffers.clear(); // an empty buffer is invalid
    model.defaultScene = 0;
    tinygltf::TinyGLTF gltf;
    if (!gltf.WriteGltfSceneToFile(&model, path.string(), /*embedImages=*/true,
                                   /*embedBuffers=*/true, /*prettyPrint=*/!binary, binary))
        throw InputError(name, "", "cannot write glTF file");
}

void write_gltf(const std::filesystem::path& path, const TriangleMesh& mesh, bool binary,
                const std::string& name, const GltfWriteOptions& options) {
    const size_t nf = mesh.triangles.size();
    const bool has_surface = mesh.triangle_surface.size() == nf && nf > 0;
    const CornerData has = CornerData::of(mesh);
    const std::vector<int> no_faces;
    const std::vector<int>& face_of =
        mesh.triangle_face.size() == nf ? mesh.triangle_face : no_faces;
    const std::vector<int>& solid_of =
        mesh_text::has_solid_ids(mesh) ? mesh.triangle_solid : no_faces;

    // Group triangles by source surface, in surface order.
    std::map<int, std::vector<int>> groups;
    for (size_t t = 0; t < nf; ++t)
        groups[has_surface ? mesh.triangle_surface[t] : 0].push_back(static_cast<int>(t));

    tinygltf::Model model = new_gltf_model();
    tinygltf::Scene scene;
    for (const auto& [surface, tris] : groups) {
        tinygltf::Primitive prim = add_triangles(model, mesh, tris, has, options.scale);
        add_face_extras(prim, tris, face_of, solid_of);
        add_surface_node(model, scene, mesh, surface, std::move(prim));
    }
    model.scenes.push_back(scene);
    finish_and_write(model, path, binary, name);
}

} // namespace seamless
