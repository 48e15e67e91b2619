// SPDX-License-Identifier: MIT
// glTF 2.0 writer and reader on tinygltf (the Debian package ships it compiled,
// so no TINYGLTF_IMPLEMENTATION here).
#include <seamless/base/error.h>
#include <seamless/base/files/input_file.h>
#include <seamless/mesh/io/gltf_io.h>
#include <seamless/mesh/io/mesh_io.h>

#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <string_view>
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

// A vertex of one primitive: the source vertex and, when present, the corner's
// float normal and uv (so corners that agree share a vertex, others are split).
using VertexKey = std::tuple<int, float, float, float, float, float>;

} // namespace

void write_gltf(const std::filesystem::path& path, const TriangleMesh& mesh, bool binary,
                const std::string& name) {
    const size_t nf = mesh.triangles.size();
    const bool has_surface = mesh.triangle_surface.size() == nf && nf > 0;
    const bool has_normals = mesh.corner_normals.size() == nf && nf > 0;
    const bool has_uvs = mesh.corner_uvs.size() == nf && nf > 0;

    // Group triangles by source surface, in surface order.
    std::map<int, std::vector<int>> groups;
    for (size_t t = 0; t < nf; ++t)
        groups[has_surface ? mesh.triangle_surface[t] : 0].push_back(static_cast<int>(t));

    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "seamless";
    model.buffers.resize(1);
    tinygltf::Scene scene;

    for (const auto& [surface, tris] : groups) {
        std::map<VertexKey, uint32_t> index_of;
        std::vector<float> pos, nrm, uv;
        std::vector<uint32_t> indices;
        indices.reserve(3 * tris.size());
        for (int t : tris) {
            for (int c = 0; c < 3; ++c) {
                const int v = mesh.triangles[t][c];
                float n[3] = {0, 0, 0}, w[2] = {0, 0};
                if (has_normals) {
                    Vec3 d = normalize(mesh.corner_normals[t][c]);
                    if (!(norm(d) > 0.5)) { // zero or non-finite: fall back to the face normal
                        const auto& f = mesh.triangles[t];
                        d = normalize(cross(mesh.positions[f[1]] - mesh.positions[f[0]],
                                            mesh.positions[f[2]] - mesh.positions[f[0]]));
                        if (!(norm(d) > 0.5)) d = {0, 0, 1};
                    }
                    // Renormalise in float so the validator's unit-length test holds.
                    float fx = static_cast<float>(d.x), fy = static_cast<float>(d.y),
                          fz = static_cast<float>(d.z);
                    const float l = std::sqrt(fx * fx + fy * fy + fz * fz);
                    n[0] = fx / l;
                    n[1] = fy / l;
                    n[2] = fz / l;
                }
                if (has_uvs) {
                    w[0] = static_cast<float>(mesh.corner_uvs[t][c][0]);
                    w[1] = static_cast<float>(mesh.corner_uvs[t][c][1]);
                }
                const VertexKey key{v, n[0], n[1], n[2], w[0], w[1]};
                auto [it, inserted] =
                    index_of.try_emplace(key, static_cast<uint32_t>(pos.size() / 3));
                if (inserted) {
                    const Vec3 p = mesh.positions[v];
                    pos.insert(pos.end(), {static_cast<float>(p.x), static_cast<float>(p.y),
                                           static_cast<float>(p.z)});
                    if (has_normals) nrm.insert(nrm.end(), n, n + 3);
                    if (has_uvs) uv.insert(uv.end(), w, w + 2);
                }
                indices.push_back(it->second);
            }
        }
        const size_t nv = pos.size() / 3;
        tinygltf::Primitive prim;
        prim.mode = TINYGLTF_MODE_TRIANGLES;
        const int pa = add_accessor(
            model, add_view(model, pos.data(), pos.size() * sizeof(float), kArrayBuffer),
            TINYGLTF_COMPONENT_TYPE_FLOAT, nv, TINYGLTF_TYPE_VEC3);
        // POSITION needs min and max (glTF 2.0, 3.7.2.1), exactly the float values stored.
        std::vector<double> lo(3, HUGE_VAL), hi(3, -HUGE_VAL);
        for (size_t i = 0; i < nv; ++i)
            for (int k = 0; k < 3; ++k) {
                lo[k] = std::min(lo[k], static_cast<double>(pos[3 * i + k]));
                hi[k] = std::max(hi[k], static_cast<double>(pos[3 * i + k]));
            }
        model.accessors[pa].minValues = lo;
        model.accessors[pa].maxValues = hi;
        prim.attributes["POSITION"] = pa;
        if (has_normals)
            prim.attributes["NORMAL"] = add_accessor(
                model, add_view(model, nrm.data(), nrm.size() * sizeof(float), kArrayBuffer),
                TINYGLTF_COMPONENT_TYPE_FLOAT, nv, TINYGLTF_TYPE_VEC3);
        if (has_uvs)
            prim.attributes["TEXCOORD_0"] = add_accessor(
                model, add_view(model, uv.data(), uv.size() * sizeof(float), kArrayBuffer),
                TINYGLTF_COMPONENT_TYPE_FLOAT, nv, TINYGLTF_TYPE_VEC2);
        prim.indices = add_accessor(
            model,
            add_view(model, indices.data(), indices.size() * sizeof(uint32_t), kElementArrayBuffer),
            TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, indices.size(), TINYGLTF_TYPE_SCALAR);
        tinygltf::Mesh gmesh;
        gmesh.name = surface >= 0 && surface < static_cast<int>(mesh.surface_names.size())
                         ? mesh.surface_names[surface]
                         : "surface" + std::to_string(surface);
        gmesh.primitives.push_back(prim);
        model.meshes.push_back(gmesh);
        tinygltf::Node node;
        node.name = gmesh.name;
        node.mesh = static_cast<int>(model.meshes.size()) - 1;
        model.nodes.push_back(node);
        scene.nodes.push_back(static_cast<int>(model.nodes.size()) - 1);
    }
    // The glb BIN chunk must be padded to 4 bytes (tinygltf pads, but keep the length honest).
    while (model.buffers[0].data.size() % 4 != 0) model.buffers[0].data.push_back(0);
    if (model.buffers[0].data.empty()) model.buffers.clear(); // an empty buffer is invalid
    model.scenes.push_back(scene);
    model.defaultScene = 0;

    tinygltf::TinyGLTF gltf;
    if (!gltf.WriteGltfSceneToFile(&model, path.string(), /*embedImages=*/true,
                                   /*embedBuffers=*/true, /*prettyPrint=*/!binary, binary))
        throw InputError(name, "", "cannot write glTF file");
}

namespace {

[[noreturn]] void fail(const std::string& file, const std::string& field,
                       const std::string& message) {
    throw InputError(file, field, message);
}

// a + b, or fail when it overflows size_t.
size_t add(size_t a, size_t b, const std::string& file, const std::string& field) {
    size_t r;
    if (__builtin_add_overflow(a, b, &r)) fail(file, field, "byte offsets overflow");
    return r;
}
size_t mul(size_t a, size_t b, const std::string& file, const std::string& field) {
    size_t r;
    if (__builtin_mul_overflow(a, b, &r)) fail(file, field, "byte offsets overflow");
    return r;
}

// Elements of one accessor: element i starts at base + i * stride and has
// `elem` bytes, every one of them inside the accessor's bufferView and buffer.
struct AccessorView {
    const unsigned char* base = nullptr;
    size_t stride = 0, count = 0;
    const unsigned char* operator[](size_t i) const { return base + i * stride; }
};

AccessorView view_of(const tinygltf::Model& model, int index, size_t elem, const std::string& file,
                     const std::string& field) {
    if (index < 0 || index >= static_cast<int>(model.accessors.size()))
        fail(file, field, "accessor index " + std::to_string(index) + " out of range");
    const auto& a = model.accessors[index];
    if (a.sparse.isSparse) fail(file, field, "sparse accessors are not supported");
    if (a.bufferView < 0 || a.bufferView >= static_cast<int>(model.bufferViews.size()))
        fail(file, field, "accessor has no valid bufferView");
    const auto& v = model.bufferViews[a.bufferView];
    if (v.buffer < 0 || v.buffer >= static_cast<int>(model.buffers.size()))
        fail(file, field, "bufferView has no valid buffer");
    const auto& b = model.buffers[v.buffer];
    // Every sum and product below is checked: offsets near 2^64 must not wrap.
    const size_t view_end = add(v.byteOffset, v.byteLength, file, field);
    if (view_end > b.data.size()) fail(file, field, "bufferView exceeds its buffer");
    AccessorView r;
    r.stride = v.byteStride ? v.byteStride : elem;
    if (r.stride < elem) fail(file, field, "byteStride smaller than an element");
    r.count = a.count;
    const size_t start = add(v.byteOffset, a.byteOffset, file, field);
    // Also for an empty accessor: base must point into the buffer.
    if (start > view_end) fail(file, field, "accessor byteOffset exceeds its bufferView");
    if (a.count > 0) {
        const size_t last = add(mul(a.count - 1, r.stride, file, field), elem, file, field);
        if (add(start, last, file, field) > view_end)
            fail(file, field,
                 "accessor of " + std::to_string(a.count) + " elements exceeds its bufferView");
    }
    r.base = b.data.data() + start;
    return r;
}

// Deepest nesting of JSON arrays and objects in `text`, or more than `limit`
// as soon as that is reached. tinygltf parses "extras" recursively: nesting
// beyond any real file's must be refused before it gets the text.
size_t json_depth(std::string_view text, size_t limit) {
    size_t depth = 0, deepest = 0;
    bool in_string = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
            if (deepest > limit) return deepest;
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

// Images are never decoded: a check needs none, and a small file can hold a
// PNG that decodes to gigabytes.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                const unsigned char*, int, void*) {
    return true;
}

// External files a .gltf names (buffers, images) are read as input files are:
// regular files only, at most the mesh size limit.
bool read_external(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                   void*) {
    try {
        const std::string bytes = read_input_file(path, kMaxMeshFileBytes, "glTF buffer");
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const InputError& e) {
        if (err) *err += e.what();
        return false;
    }
}

bool refuse_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is not allowed while reading";
    return false;
}

float read_float(const unsigned char* p) {
    float f;
    std::memcpy(&f, p, 4);
    return f;
}

} // namespace

TriangleMesh read_gltf(const std::filesystem::path& path) {
    const std::string file = path.string();
    const std::string bytes = read_input_file(path, kMaxMeshFileBytes, "mesh");
    const bool binary = path.extension() == ".glb" || path.extension() == ".GLB";
    return parse_gltf(bytes, binary, file, path.parent_path());
}

TriangleMesh parse_gltf(const std::string& bytes, bool binary, const std::string& file,
                        const std::filesystem::path& base_dir) {
    // The JSON text: the whole .gltf, or a .glb's first chunk (its length is
    // checked here only as far as the depth scan needs; tinygltf checks the rest).
    std::string_view json_text = bytes;
    if (binary && bytes.size() >= 20) {
        uint32_t length;
        std::memcpy(&length, bytes.data() + 12, 4);
        json_text = json_text.substr(20, length);
    }
    constexpr size_t kMaxJsonDepth = 64;
    if (json_depth(json_text, kMaxJsonDepth) > kMaxJsonDepth)
        fail(file, "", "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    if (bytes.size() > std::numeric_limits<unsigned int>::max())
        fail(file, "", "file too large for the glTF reader");

    tinygltf::Model model;
    tinygltf::TinyGLTF gltf;
    gltf.SetImageLoader(skip_image, nullptr);
    gltf.SetFsCallbacks(
        {tinygltf::FileExists, tinygltf::ExpandFilePath, read_external, refuse_write, nullptr});
    std::string err, warn;
    bool ok = false;
    const std::string dir = base_dir.string();
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const auto size = static_cast<unsigned int>(bytes.size());
    try {
        ok = binary ? gltf.LoadBinaryFromMemory(&model, &err, &warn, data, size, dir)
                    : gltf.LoadASCIIFromString(&model, &err, &warn, bytes.data(), size, dir);
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& e) { // tinygltf lets some std::out_of_range escape
        err = e.what();
        ok = false;
    }
    if (!ok) {
        while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
        for (char& c : err)
            if (c == '\n') c = ' ';
        fail(file, "", "not a valid glTF file" + (err.empty() ? "" : ": " + err));
    }

    // Each accessor is read once, however many primitives share it; the
    // triangles are bounded by what the file and its buffers could hold
    // without sharing (one triangle per byte: a strip of 8-bit indices),
    // so a small file cannot expand into gigabytes of triangles.
    size_t max_triangles = bytes.size();
    for (const auto& b : model.buffers) max_triangles += b.data.size();
    std::map<int, int> first_vertex; // POSITION accessor -> index of its first vertex
    TriangleMesh mesh;
    bool all_normals = true, all_uvs = true;
    std::vector<std::array<Vec3, 3>> normals;
    std::vector<std::array<std::array<double, 2>, 3>> uvs;
    for (size_t m = 0; m < model.meshes.size(); ++m) {
        const auto& gm = model.meshes[m];
        mesh.surface_names.push_back(gm.name.empty() ? "mesh" + std::to_string(m) : gm.name);
        for (size_t p = 0; p < gm.primitives.size(); ++p) {
            const auto& prim = gm.primitives[p];
            const std::string field =
                "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "]";
            const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
            if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
                mode != TINYGLTF_MODE_TRIANGLE_FAN)
                continue; // points and lines carry no triangles
            auto pit = prim.attributes.find("POSITION");
            if (pit == prim.attributes.end()) fail(file, field, "no POSITION attribute");
            if (pit->second < 0 || pit->second >= static_cast<int>(model.accessors.size()))
                fail(file, field + ".POSITION", "accessor index out of range");
            const auto& pa = model.accessors[pit->second];
            if (pa.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || pa.type != TINYGLTF_TYPE_VEC3)
                fail(file, field + ".POSITION", "expected float32 VEC3");
            const AccessorView pv = view_of(model, pit->second, 12, file, field + ".POSITION");
            if (pv.count > (1u << 30)) fail(file, field, "absurd vertex count");
            auto [known, first_use] = first_vertex.try_emplace(pit->second, mesh.vertex_count());
            const int base = known->second;
            if (first_use) {
                if (mesh.positions.size() + pv.count > (1u << 30))
                    fail(file, field, "more than 2^30 vertices in all");
                for (size_t i = 0; i < pv.count; ++i)
                    mesh.positions.push_back(
                        {read_float(pv[i]), read_float(pv[i] + 4), read_float(pv[i] + 8)});
            }

            // Corner order of the primitive.
            std::vector<uint32_t> order;
            if (prim.indices >= 0) {
                if (prim.indices >= static_cast<int>(model.accessors.size()))
                    fail(file, field + ".indices", "accessor index out of range");
                const auto& ia = model.accessors[prim.indices];
                size_t sz = ia.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                            : ia.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                            : ia.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                                         : 0;
                if (sz == 0 || ia.type != TINYGLTF_TYPE_SCALAR)
                    fail(file, field + ".indices", "expected unsigned scalar indices");
                const AccessorView iv = view_of(model, prim.indices, sz, file, field + ".indices");
                order.reserve(iv.count);
                for (size_t i = 0; i < iv.count; ++i) {
                    uint32_t k = 0;
                    if (sz == 1)
                        k = *iv[i];
                    else if (sz == 2) {
                        uint16_t s;
                        std::memcpy(&s, iv[i], 2);
                        k = s;
                    } else
                        std::memcpy(&k, iv[i], 4);
                    if (k >= pv.count)
                        fail(file, field + ".indices",
                             "index " + std::to_string(k) + " out of range [0, " +
                                 std::to_string(pv.count) + ")");
                    order.push_back(k);
                }
            } else {
                for (size_t i = 0; i < pv.count; ++i) order.push_back(static_cast<uint32_t>(i));
            }
            std::vector<std::array<uint32_t, 3>> tris;
            if (mode == TINYGLTF_MODE_TRIANGLES) {
                if (order.size() % 3 != 0)
                    fail(file, field,
                         "triangle list of " + std::to_string(order.size()) +
                             " indices (not a multiple of 3)");
                for (size_t i = 0; i + 2 < order.size(); i += 3)
                    tris.push_back({order[i], order[i + 1], order[i + 2]});
            } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
                for (size_t i = 0; i + 2 < order.size(); ++i)
                    tris.push_back(i % 2 == 0 ? std::array{order[i], order[i + 1], order[i + 2]}
                                              : std::array{order[i + 1], order[i], order[i + 2]});
            } else {
                for (size_t i = 1; i + 1 < order.size(); ++i)
                    tris.push_back({order[0], order[i], order[i + 1]});
            }

            // Optional corner attributes (float32 only).
            auto nit = prim.attributes.find("NORMAL");
            auto uit = prim.attributes.find("TEXCOORD_0");
            AccessorView nv, uv;
            bool has_n = nit != prim.attributes.end(), has_u = uit != prim.attributes.end();
            if (has_n) {
                nv = view_of(model, nit->second, 12, file, field + ".NORMAL");
                const auto& a = model.accessors[nit->second];
                has_n = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT &&
                        a.type == TINYGLTF_TYPE_VEC3 && nv.count == pv.count;
            }
            if (has_u) {
                uv = view_of(model, uit->second, 8, file, field + ".TEXCOORD_0");
                const auto& a = model.accessors[uit->second];
                has_u = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT &&
                        a.type == TINYGLTF_TYPE_VEC2 && uv.count == pv.count;
            }
            if (mesh.triangles.size() + tris.size() > max_triangles)
                fail(file, field,
                     "primitives make more than " + std::to_string(max_triangles) +
                         " triangles, one per byte of the file and its buffers (accessors "
                         "shared by many primitives)");
            all_normals = all_normals && has_n;
            all_uvs = all_uvs && has_u;
            for (const auto& t : tris) {
                mesh.triangles.push_back({base + static_cast<int>(t[0]),
                                          base + static_cast<int>(t[1]),
                                          base + static_cast<int>(t[2])});
                mesh.triangle_surface.push_back(static_cast<int>(m));
                std::array<Vec3, 3> cn{};
                std::array<std::array<double, 2>, 3> cu{};
                for (int c = 0; c < 3; ++c) {
                    if (has_n)
                        cn[c] = {read_float(nv[t[c]]), read_float(nv[t[c]] + 4),
                                 read_float(nv[t[c]] + 8)};
                    if (has_u) cu[c] = {read_float(uv[t[c]]), read_float(uv[t[c]] + 4)};
                }
                normals.push_back(cn);
                uvs.push_back(cu);
            }
        }
    }
    if (all_normals && !mesh.triangles.empty()) mesh.corner_normals = std::move(normals);
    if (all_uvs && !mesh.triangles.empty()) mesh.corner_uvs = std::move(uvs);
    return mesh;
}

} // namespace seamless
