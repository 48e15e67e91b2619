// SPDX-License-Identifier: MIT
// PLY: ascii, binary_little_endian and binary_big_endian; the vertex element's
// x, y, z and the face element's vertex_indices (or vertex_index) list; other
// elements and properties are skipped.
#include <seamless/mesh/io/mesh_text.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace seamless::mesh_text {

namespace {

enum class PlyType { i8, u8, i16, u16, i32, u32, f32, f64 };

struct PlyProperty {
    std::string name;
    bool list = false;
    PlyType count_type = PlyType::u8, type = PlyType::f32;
};

struct PlyElement {
    std::string name;
    long long count = 0;
    std::vector<PlyProperty> properties;
};

PlyType ply_type(const Tokens& in, std::string_view t) {
    if (t == "char" || t == "int8") return PlyType::i8;
    if (t == "uchar" || t == "uint8") return PlyType::u8;
    if (t == "short" || t == "int16") return PlyType::i16;
    if (t == "ushort" || t == "uint16") return PlyType::u16;
    if (t == "int" || t == "int32") return PlyType::i32;
    if (t == "uint" || t == "uint32") return PlyType::u32;
    if (t == "float" || t == "float32") return PlyType::f32;
    if (t == "double" || t == "float64") return PlyType::f64;
    in.fail("unknown PLY type '" + std::string(t) + "'");
}

size_t ply_size(PlyType t) {
    switch (t) {
    case PlyType::i8:
    case PlyType::u8:
        return 1;
    case PlyType::i16:
    case PlyType::u16:
        return 2;
    case PlyType::i32:
    case PlyType::u32:
    case PlyType::f32:
        return 4;
    case PlyType::f64:
        return 8;
    }
    return 0;
}

// A value of type T from its bytes (already in host order).
template <class T> double load_as(const unsigned char* b) {
    T v;
    std::memcpy(&v, b, sizeof v);
    return static_cast<double>(v);
}

// Reads one binary PLY scalar at `p` as a double.
double ply_binary_value(const unsigned char* p, PlyType t, bool big_endian) {
    unsigned char b[8];
    const size_t n = ply_size(t);
    for (size_t i = 0; i < n; ++i) b[i] = big_endian ? p[n - 1 - i] : p[i];
    switch (t) {
    case PlyType::i8:
        return load_as<int8_t>(b);
    case PlyType::u8:
        return load_as<uint8_t>(b);
    case PlyType::i16:
        return load_as<int16_t>(b);
    case PlyType::u16:
        return load_as<uint16_t>(b);
    case PlyType::i32:
        return load_as<int32_t>(b);
    case PlyType::u32:
        return load_as<uint32_t>(b);
    case PlyType::f32:
        return load_as<float>(b);
    case PlyType::f64:
        return load_as<double>(b);
    }
    return 0;
}

} // namespace

TriangleMesh read_ply(const std::string& text, const std::string& file) {
    Tokens in(text, file);
    if (in.next_in_line() != "ply") in.fail("expected 'ply'");
    std::string format;
    std::vector<PlyElement> elements;
    for (;;) {
        if (!in.next_line()) in.fail("header has no end_header");
        auto key = in.next_in_line();
        if (key == "format") {
            format = in.next_in_line();
        } else if (key == "element") {
            PlyElement e;
            e.name = in.next_in_line();
            e.count = checked_count(file, "element " + e.name, in.integer(in.next_in_line()),
                                    text.size(), 1);
            elements.push_back(e);
        } else if (key == "property") {
            if (elements.empty()) in.fail("property before any element");
            PlyProperty p;
            auto t = in.next_in_line();
            if (t == "list") {
                p.list = true;
                p.count_type = ply_type(in, in.next_in_line());
                p.type = ply_type(in, in.next_in_line());
            } else {
                p.type = ply_type(in, t);
            }
            p.name = in.next_in_line();
            elements.back().properties.push_back(p);
        } else if (key == "end_header") {
            in.next_line();
            break;
        } else if (key == "comment" || key == "obj_info" || key.empty()) {
            continue;
        } else {
            in.fail("unknown header line '" + std::string(key) + "'");
        }
    }
    const bool ascii = format == "ascii";
    const bool big = format == "binary_big_endian";
    if (!ascii && !big && format != "binary_little_endian")
        throw InputError(file, "format", "unknown PLY format '" + format + "'");

    TriangleMesh mesh;
    bool have_vertices = false;
    const auto* data = reinterpret_cast<const unsigned char*>(text.data());
    size_t pos = in.position();
    // Each element takes at least one byte per binary scalar, two per ascii one
    // ("0 "): a count the body cannot hold is refused before reserving for it.
    for (const PlyElement& e : elements) {
        size_t min_bytes = 0;
        for (const PlyProperty& p : e.properties)
            min_bytes += ascii ? 2 : ply_size(p.list ? p.count_type : p.type);
        if (min_bytes > 0)
            checked_count(file, "element " + e.name, e.count, text.size() - pos, min_bytes);
    }
    // One scalar from the body, ascii or binary.
    auto value = [&](PlyType t) -> double {
        if (ascii) {
            auto tok = in.next();
            if (tok.empty()) in.fail("file ends inside the PLY body");
            return in.number(tok);
        }
        const size_t n = ply_size(t);
        if (pos + n > text.size()) throw InputError(file, "body", "file ends inside the PLY body");
        double v = ply_binary_value(data + pos, t, big);
        pos += n;
        return v;
    };
    std::vector<long long> face;
    for (const PlyElement& e : elements) {
        const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
        int ix = -1, iy = -1, iz = -1, ifaces = -1;
        for (size_t k = 0; k < e.properties.size(); ++k) {
            const auto& p = e.properties[k];
            if (!p.list && p.name == "x") ix = static_cast<int>(k);
            if (!p.list && p.name == "y") iy = static_cast<int>(k);
            if (!p.list && p.name == "z") iz = static_cast<int>(k);
            if (p.list && (p.name == "vertex_indices" || p.name == "vertex_index"))
                ifaces = static_cast<int>(k);
        }
        if (is_vertex) {
            if (ix < 0 || iy < 0 || iz < 0)
                throw InputError(file, "element vertex", "needs properties x, y and z");
            have_vertices = true;
            mesh.positions.reserve(static_cast<size_t>(e.count));
        }
        if (is_face && ifaces < 0)
            throw InputError(file, "element face", "needs a vertex_indices list");
        for (long long i = 0; i < (e.properties.empty() ? 0 : e.count); ++i) {
            Vec3 p;
            for (size_t k = 0; k < e.properties.size(); ++k) {
                const auto& prop = e.properties[k];
                if (prop.list) {
                    // Range and integrality are checked on the double, before any
                    // conversion (nan or 1e300 converted to an integer is undefined).
                    const double n = value(prop.count_type);
                    if (!(n >= 0 && n <= 1000000) || n != std::floor(n))
                        throw InputError(file, e.name + " " + std::to_string(i),
                                         "list count " + number_text(n) +
                                             " is not an integer in 0..1000000");
                    const bool keep = is_face && static_cast<int>(k) == ifaces;
                    if (keep) face.clear();
                    for (int j = 0; j < static_cast<int>(n); ++j) {
                        const double v = value(prop.type);
                        if (!keep) continue;
                        if (!have_vertices || !(v >= 0 && v < mesh.vertex_count()) ||
                            v != std::floor(v))
                            throw InputError(file, "face " + std::to_string(i),
                                             "vertex index " + number_text(v) +
                                                 " is not an index in [0, " +
                                                 std::to_string(mesh.vertex_count()) + ")");
                        face.push_back(static_cast<long long>(v));
                    }
                    if (keep) {
                        if (face.size() < 3)
                            throw InputError(file, "face " + std::to_string(i),
                                             "fewer than 3 vertices");
                        add_polygon(mesh, face);
                    }
                } else {
                    const double v = value(prop.type);
                    if (is_vertex) {
                        if (static_cast<int>(k) == ix) p.x = v;
                        if (static_cast<int>(k) == iy) p.y = v;
                        if (static_cast<int>(k) == iz) p.z = v;
                    }
                }
            }
            if (is_vertex) mesh.positions.push_back(p);
        }
    }
    if (!have_vertices) throw InputError(file, "header", "no vertex element");
    return mesh;
}

std::string format_ply(const TriangleMesh& mesh) {
    std::string out = "ply\nformat ascii 1.0\ncomment seamless\nelement vertex " +
                      std::to_string(mesh.vertex_count()) +
                      "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
                      std::to_string(mesh.triangle_count()) +
                      "\nproperty list uchar int vertex_indices\nend_header\n";
    append_points_and_triangles(out, mesh);
    return out;
}

} // namespace seamless::mesh_text
