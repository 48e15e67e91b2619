// SPDX-License-Identifier: MIT
// glTF 2.0 reader on tinygltf: the file loaded by tinygltf with images never
// decoded and external files read as input files are, then every triangle
// primitive read through bounds-checked accessors (gltf_accessor.h).
#include <seamless/base/error.h>
#include <seamless/base/files/input_file.h>
#include <seamless/mesh/io/gltf_accessor.h>
#include <seamless/mesh/io/gltf_io.h>
#include <seamless/mesh/io/mesh_formats.h>
#include <seamless/mesh/io/mesh_io.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <string_view>

namespace seamless {
namespace {

[[noreturn]] void fail(const std::string& file, const std::string& field,
                       const std::string& message) {
    throw InputError(file, field, message);
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

// The JSON text, the whole .gltf or a .glb's first chunk (its length is
// checked here only as far as the depth scan needs; tinygltf checks the
// rest), must nest at most kMaxJsonDepth levels.
void refuse_deep_json(const std::string& bytes, bool binary, const std::string& file) {
    std::string_view json_text = bytes;
    if (binary && bytes.size() >= 20) {
        uint32_t length;
        std::memcpy(&length, bytes.data() + 12, 4);
        json_text = json_text.substr(20, length);
    }
    constexpr size_t kMaxJsonDepth = 64;
    if (json_depth(json_text, kMaxJsonDepth) > kMaxJsonDepth)
        fail(file, "", "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
}

// Images are never decoded: a check needs none, and a small file can hold a
// PNG that decodes to gigabytes. The parameters are tinygltf's
// LoadImageDataFunction's.
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

// The glTF document of `bytes` as tinygltf reads it; throws InputError with
// tinygltf's message on one line.
tinygltf::Model load_document(const std::string& bytes, bool binary, const std::string& file,
                              const std::filesystem::path& base_dir) {
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
    return model;
}

// The triangles of every triangle primitive of a glTF document, appended to
// one TriangleMesh. Each POSITION accessor is read once, however many
// primitives share it; the triangles are bounded by what the file and its
// buffers could hold without sharing (one triangle per byte: a strip of 8-bit
// indices), so a small file cannot expand into gigabytes of triangles.
class PrimitiveReader {
  public:
    PrimitiveReader(const tinygltf::Model& model, const std::string& file, size_t file_bytes)
        : model_(model), file_(file), max_triangles_(file_bytes) {
        for (const auto& b : model.buffers) max_triangles_ += b.data.size();
    }

    void read_mesh(size_t m) {
        const auto& gm = model_.meshes[m];
        mesh_.surface_names.push_back(gm.name.empty() ? "mesh" + std::to_string(m) : gm.name);
        for (size_t p = 0; p < gm.primitives.size(); ++p)
            read_primitive(static_cast<int>(m), gm.primitives[p],
                           "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) +
                               "]");
    }

    // The mesh; corner normals and uvs when every primitive had them.
    TriangleMesh finish() && {
        if (all_normals_ && !mesh_.triangles.empty()) mesh_.corner_normals = std::move(normals_);
        if (all_uvs_ && !mesh_.triangles.empty()) mesh_.corner_uvs = std::move(uvs_);
        if (faces_.complete && !mesh_.triangles.empty()) { // the parts are not written
            mesh_.triangle_face = std::move(faces_.ids);
            mesh_.triangle_part.assign(mesh_.triangles.size(), -1);
            if (solids_.complete) mesh_.triangle_solid = std::move(solids_.ids);
        }
        return std::move(mesh_);
    }

  private:
    using Triangles = std::vector<std::array<uint32_t, 3>>;

    void read_primitive(int m, const tinygltf::Primitive& prim, const std::string& field) {
        const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            mode != TINYGLTF_MODE_TRIANGLE_FAN)
            return; // points and lines carry no triangles
        AccessorView pv;
        const int base = read_positions(prim, field, pv);
        const Triangles tris = triangles(mode, corner_order(prim, field, pv.count), field);
        // Optional corner attributes (float32 only).
        AccessorView nv, uv;
        const bool has_n =
            corner_attribute(prim, "NORMAL", TINYGLTF_TYPE_VEC3, pv.count, field, nv);
        const bool has_u =
            corner_attribute(prim, "TEXCOORD_0", TINYGLTF_TYPE_VEC2, pv.count, field, uv);
        if (mesh_.triangles.size() + tris.size() > max_triangles_)
            fail(file_, field,
                 "primitives make more than " + std::to_string(max_triangles_) +
                     " triangles, one per byte of the file and its buffers (accessors "
                     "shared by many primitives)");
        all_normals_ = all_normals_ && has_n;
        all_uvs_ = all_uvs_ && has_u;
        for (const auto& t : tris) {
            mesh_.triangles.push_back({base + static_cast<int>(t[0]), base + static_cast<int>(t[1]),
                                       base + static_cast<int>(t[2])});
            mesh_.triangle_surface.push_back(m);
            std::array<Vec3, 3> cn{};
            std::array<std::array<double, 2>, 3> cu{};
            for (int c = 0; c < 3; ++c) {
                if (has_n)
                    cn[c] = {read_float(nv[t[c]]), read_float(nv[t[c]] + 4),
                             read_float(nv[t[c]] + 8)};
                if (has_u) cu[c] = {read_float(uv[t[c]]), read_float(uv[t[c]] + 4)};
            }
            normals_.push_back(cn);
            uvs_.push_back(cu);
        }
        read_ids(prim, "faces", tris.size(), faces_);
        read_ids(prim, "solids", tris.size(), solids_);
    }

    // Ids of every triangle read so far, from the primitives' extras;
    // complete while every primitive's runs covered its triangles.
    struct Ids {
        std::vector<int> ids;
        bool complete = true;
    };

    // The ids of a primitive's n triangles from its extras' member `key`
    // (docs/formats.md, "Face ids": {"faces": [[face, first, count], ...]},
    // "solids" likewise); a primitive without them, or whose runs do not
    // cover its triangles in order, leaves the mesh without those ids
    // (extras are any application's).
    void read_ids(const tinygltf::Primitive& prim, const char* key, size_t n, Ids& out) {
        const size_t before = out.ids.size();
        out.ids.resize(before + n, -1);
        const tinygltf::Value& runs = prim.extras.Has(key) ? prim.extras.Get(key) : none_;
        size_t next = 0;
        for (size_t k = 0; out.complete && k < runs.ArrayLen(); ++k) {
            const tinygltf::Value& run = runs.Get(static_cast<int>(k));
            double v[3];
            for (int i = 0; i < 3; ++i) {
                const tinygltf::Value& x = run.ArrayLen() == 3 ? run.Get(i) : none_;
                v[i] = x.IsNumber() ? x.GetNumberAsDouble() : -2;
                // Checked on the double, before any conversion.
                if (!(v[i] >= (i == 0 ? -1 : 0) && v[i] <= 2147483647.0) ||
                    v[i] != std::floor(v[i]))
                    out.complete = false;
            }
            if (!out.complete || v[1] != double(next) || v[2] < 1 || v[1] + v[2] > double(n)) {
                out.complete = false;
                break;
            }
            std::fill_n(out.ids.begin() + before + next, size_t(v[2]), static_cast<int>(v[0]));
            next += size_t(v[2]);
        }
        if (next != n) out.complete = false;
    }

    // The primitive's POSITION accessor in `pv`, its vertices appended to the
    // mesh on first use; returns the mesh index of its first vertex.
    int read_positions(const tinygltf::Primitive& prim, const std::string& field,
                       AccessorView& pv) {
        auto pit = prim.attributes.find("POSITION");
        if (pit == prim.attributes.end()) fail(file_, field, "no POSITION attribute");
        if (pit->second < 0 || pit->second >= static_cast<int>(model_.accessors.size()))
            fail(file_, field + ".POSITION", "accessor index out of range");
        const auto& pa = model_.accessors[pit->second];
        if (pa.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || pa.type != TINYGLTF_TYPE_VEC3)
            fail(file_, field + ".POSITION", "expected float32 VEC3");
        pv = view_of(model_, pit->second, 12, file_, field + ".POSITION");
        if (pv.count > (1u << 30)) fail(file_, field, "absurd vertex count");
        auto [known, first_use] = first_vertex_.try_emplace(pit->second, mesh_.vertex_count());
        if (first_use) {
            if (mesh_.positions.size() + pv.count > (1u << 30))
                fail(file_, field, "more than 2^30 vertices in all");
            for (size_t i = 0; i < pv.count; ++i)
                mesh_.positions.push_back(
                    {read_float(pv[i]), read_float(pv[i] + 4), read_float(pv[i] + 8)});
        }
        return known->second;
    }

    // Corner order of the primitive: its indices, each below `vertices`, or 0, 1, 2, ...
    std::vector<uint32_t> corner_order(const tinygltf::Primitive& prim, const std::string& field,
                                       size_t vertices) const {
        std::vector<uint32_t> order;
        if (prim.indices < 0) {
            for (size_t i = 0; i < vertices; ++i) order.push_back(static_cast<uint32_t>(i));
            return order;
        }
        if (prim.indices >= static_cast<int>(model_.accessors.size()))
            fail(file_, field + ".indices", "accessor index out of range");
        const auto& ia = model_.accessors[prim.indices];
        size_t sz = ia.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                    : ia.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                    : ia.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                                 : 0;
        if (sz == 0 || ia.type != TINYGLTF_TYPE_SCALAR)
            fail(file_, field + ".indices", "expected unsigned scalar indices");
        const AccessorView iv = view_of(model_, prim.indices, sz, file_, field + ".indices");
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
            if (k >= vertices)
                fail(file_, field + ".indices",
                     "index " + std::to_string(k) + " out of range [0, " +
                         std::to_string(vertices) + ")");
            order.push_back(k);
        }
        return order;
    }

    // The triangles of a list, strip or fan over the corners in `order`.
    Triangles triangles(int mode, const std::vector<uint32_t>& order,
                        const std::string& field) const {
        Triangles tris;
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            if (order.size() % 3 != 0)
                fail(file_, field,
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
        return tris;
    }

    // Whether the primitive has attribute `name` as float32 `type` with one
    // element per vertex, its view in `view`; a present attribute's view must
    // lie in its buffer whatever its type.
    bool corner_attribute(const tinygltf::Primitive& prim, const std::string& name, int type,
                          size_t vertices, const std::string& field, AccessorView& view) const {
        auto it = prim.attributes.find(name);
        if (it == prim.attributes.end()) return false;
        const size_t elem = type == TINYGLTF_TYPE_VEC3 ? 12 : 8;
        view = view_of(model_, it->second, elem, file_, field + "." + name);
        const auto& a = model_.accessors[it->second];
        return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT && a.type == type &&
               view.count == vertices;
    }

    const tinygltf::Model& model_;
    const std::string& file_;
    size_t max_triangles_;
    std::map<int, int> first_vertex_; // POSITION accessor -> index of its first vertex
    TriangleMesh mesh_;
    bool all_normals_ = true, all_uvs_ = true;
    Ids faces_, solids_;
    const tinygltf::Value none_;
    std::vector<std::array<Vec3, 3>> normals_;
    std::vector<std::array<std::array<double, 2>, 3>> uvs_;
};

} // namespace

TriangleMesh read_gltf(const std::filesystem::path& path) {
    const std::string file = path.string();
    const bool binary = mesh_format_of(path.extension().string()) == MeshFormat::glb;
    const std::string bytes = read_input_file(path, kMaxMeshFileBytes, "mesh");
    return parse_gltf(bytes, binary, file, path.parent_path());
}

TriangleMesh parse_gltf(const std::string& bytes, bool binary, const std::string& file,
                        const std::filesystem::path& base_dir) {
    refuse_deep_json(bytes, binary, file);
    const tinygltf::Model model = load_document(bytes, binary, file, base_dir);
    PrimitiveReader reader(model, file, bytes.size());
    for (size_t m = 0; m < model.meshes.size(); ++m) reader.read_mesh(m);
    return std::move(reader).finish();
}

} // namespace seamless
