// SPDX-License-Identifier: MIT
// PLY: ascii, binary_little_endian and binary_big_endian; the vertex element's
// x, y, z and the face element's vertex_indices (or vertex_index) list, and
// its part_id, face_id and solid_id (face ids, with the parts' names in
// "comment part_name K NAME" lines); other elements and properties are skipped.
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

struct PlyHeader {
    std::string format;
    std::vector<PlyElement> elements;
    std::vector<std::string> part_names; // "comment part_name K NAME", K in order
};

// A "comment part_name K NAME" line (the rest of a comment line in `in`).
void read_part_name(Tokens& in, PlyHeader& h) {
    if (in.next_in_line() != "part_name") return;
    const auto k = in.next_in_line();
    if (k != std::to_string(h.part_names.size())) return;
    h.part_names.push_back(in.rest_of_line());
}

// The header, from "ply" to "end_header"; `in` left at the first body line.
PlyHeader read_header(Tokens& in, const std::string& file, size_t size) {
    if (in.next_in_line() != "ply") in.fail("expected 'ply'");
    PlyHeader h;
    for (;;) {
        if (!in.next_line()) in.fail("header has no end_header");
        auto key = in.next_in_line();
        if (key == "format") {
            h.format = in.next_in_line();
        } else if (key == "element") {
            PlyElement e;
            e.name = in.next_in_line();
            e.count =
                checked_count(file, "element " + e.name, in.integer(in.next_in_line()), size, 1);
            h.elements.push_back(e);
        } else if (key == "property") {
            if (h.elements.empty()) in.fail("property before any element");
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
            h.elements.back().properties.push_back(p);
        } else if (key == "end_header") {
            in.next_line();
            return h;
        } else if (key == "comment") {
            read_part_name(in, h);
        } else if (key == "obj_info" || key.empty()) {
            continue;
        } else {
            in.fail("unknown header line '" + std::string(key) + "'");
        }
    }
}

// Where an element keeps what a mesh needs: the x, y, z properties and the
// vertex_indices (or vertex_index) list, or -1.
struct PlyLayout {
    int x = -1, y = -1, z = -1, faces = -1, part = -1, face = -1, solid = -1;
};

PlyLayout layout_of(const PlyElement& e) {
    PlyLayout l;
    for (size_t k = 0; k < e.properties.size(); ++k) {
        const auto& p = e.properties[k];
        if (!p.list && p.name == "x") l.x = static_cast<int>(k);
        if (!p.list && p.name == "y") l.y = static_cast<int>(k);
        if (!p.list && p.name == "z") l.z = static_cast<int>(k);
        if (p.list && (p.name == "vertex_indices" || p.name == "vertex_index"))
            l.faces = static_cast<int>(k);
        if (!p.list && p.name == "part_id") l.part = static_cast<int>(k);
        if (!p.list && p.name == "face_id") l.face = static_cast<int>(k);
        if (!p.list && p.name == "solid_id") l.solid = static_cast<int>(k);
    }
    return l;
}

// The body after the header: the elements in order, scalar by scalar, ascii
// or binary; vertices and faces kept, other elements read past.
class PlyBody {
  public:
    PlyBody(Tokens& in, const std::string& text, const std::string& file, const std::string& format)
        : in_(in), text_(text), file_(file), ascii_(format == "ascii"),
          big_(format == "binary_big_endian"), pos_(in.position()) {
        if (!ascii_ && !big_ && format != "binary_little_endian")
            throw InputError(file, "format", "unknown PLY format '" + format + "'");
    }

    TriangleMesh read(const std::vector<PlyElement>& elements,
                      std::vector<std::string> part_names) {
        mesh_.part_names = std::move(part_names);
        check_counts(elements);
        for (const PlyElement& e : elements) read_element(e);
        if (!have_vertices_) throw InputError(file_, "header", "no vertex element");
        return std::move(mesh_);
    }

  private:
    // Each element takes at least one byte per binary scalar, two per ascii one
    // ("0 "): a count the body cannot hold is refused before reserving for it.
    void check_counts(const std::vector<PlyElement>& elements) const {
        for (const PlyElement& e : elements) {
            size_t min_bytes = 0;
            for (const PlyProperty& p : e.properties)
                min_bytes += ascii_ ? 2 : ply_size(p.list ? p.count_type : p.type);
            if (min_bytes > 0)
                checked_count(file_, "element " + e.name, e.count, text_.size() - pos_, min_bytes);
        }
    }

    // One scalar from the body, ascii or binary.
    double value(PlyType t) {
        if (ascii_) {
            auto tok = in_.next();
            if (tok.empty()) in_.fail("file ends inside the PLY body");
            return in_.number(tok);
        }
        const size_t n = ply_size(t);
        if (pos_ + n > text_.size())
            throw InputError(file_, "body", "file ends inside the PLY body");
        double v =
            ply_binary_value(reinterpret_cast<const unsigned char*>(text_.data()) + pos_, t, big_);
        pos_ += n;
        return v;
    }

    void read_element(const PlyElement& e) {
        const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
        const PlyLayout l = layout_of(e);
        if (is_vertex) {
            if (l.x < 0 || l.y < 0 || l.z < 0)
                throw InputError(file_, "element vertex", "needs properties x, y and z");
            have_vertices_ = true;
            mesh_.positions.reserve(static_cast<size_t>(e.count));
        }
        if (is_face && l.faces < 0)
            throw InputError(file_, "element face", "needs a vertex_indices list");
        const bool face_ids = is_face && (l.part >= 0 || l.face >= 0);
        const bool ids = face_ids || (is_face && l.solid >= 0);
        for (long long i = 0; i < (e.properties.empty() ? 0 : e.count); ++i) {
            Vec3 p;
            int ids_of[3] = {-1, -1, -1}; // part, face, solid
            const size_t before = mesh_.triangles.size();
            for (size_t k = 0; k < e.properties.size(); ++k) {
                const auto& prop = e.properties[k];
                const int kk = static_cast<int>(k);
                if (prop.list) {
                    read_list(e, i, prop, is_face && kk == l.faces);
                } else {
                    const double v = value(prop.type);
                    if (is_vertex) {
                        if (kk == l.x) p.x = v;
                        if (kk == l.y) p.y = v;
                        if (kk == l.z) p.z = v;
                    }
                    if (ids && (kk == l.part || kk == l.face || kk == l.solid))
                        ids_of[kk == l.part ? 0 : kk == l.face ? 1 : 2] = face_id(v, e, i, prop);
                }
            }
            if (is_vertex) mesh_.positions.push_back(p);
            if (face_ids) add_polygon_ids(mesh_, before, ids_of[0], ids_of[1]);
            if (is_face && l.solid >= 0)
                mesh_.triangle_solid.resize(mesh_.triangles.size(), ids_of[2]);
        }
    }

    // A part_id, face_id or solid_id: an integer from -1 (none) to 2^31 - 1.
    int face_id(double v, const PlyElement& e, long long i, const PlyProperty& prop) const {
        if (!(v >= -1 && v <= 2147483647.0) || v != std::floor(v))
            throw InputError(file_, e.name + " " + std::to_string(i),
                             prop.name + " " + number_text(v) + " is not an integer in -1..2^31-1");
        return static_cast<int>(v);
    }

    // List `prop` of item i of element e; `keep`: it is a face's vertex list.
    void read_list(const PlyElement& e, long long i, const PlyProperty& prop, bool keep) {
        // Range and integrality are checked on the double, before any
        // conversion (nan or 1e300 converted to an integer is undefined).
        const double n = value(prop.count_type);
        if (!(n >= 0 && n <= 1000000) || n != std::floor(n))
            throw InputError(file_, e.name + " " + std::to_string(i),
                             "list count " + number_text(n) + " is not an integer in 0..1000000");
        if (keep) face_.clear();
        for (int j = 0; j < static_cast<int>(n); ++j) {
            const double v = value(prop.type);
            if (!keep) continue;
            if (!have_vertices_ || !(v >= 0 && v < mesh_.vertex_count()) || v != std::floor(v))
                throw InputError(file_, "face " + std::to_string(i),
                                 "vertex index " + number_text(v) + " is not an index in [0, " +
                                     std::to_string(mesh_.vertex_count()) + ")");
            face_.push_back(static_cast<long long>(v));
        }
        if (keep) {
            if (face_.size() < 3)
                throw InputError(file_, "face " + std::to_string(i), "fewer than 3 vertices");
            add_polygon(mesh_, face_);
        }
    }

    Tokens& in_;
    const std::string& text_;
    const std::string& file_;
    const bool ascii_, big_;
    size_t pos_; // next byte of a binary body
    TriangleMesh mesh_;
    bool have_vertices_ = false;
    std::vector<long long> face_;
};

} // namespace

TriangleMesh read_ply(const std::string& text, const std::string& file) {
    Tokens in(text, file);
    const PlyHeader header = read_header(in, file, text.size());
    return PlyBody(in, text, file, header.format).read(header.elements, header.part_names);
}

std::string format_ply(const TriangleMesh& mesh) {
    const bool ids = has_face_ids(mesh);
    std::string out = "ply\nformat ascii 1.0\ncomment seamless\n";
    for (size_t p = 0; ids && p < mesh.part_names.size(); ++p)
        out += "comment part_name " + std::to_string(p) + " " + part_name(mesh, int(p)) + "\n";
    out += "element vertex " + std::to_string(mesh.vertex_count()) +
           "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
           std::to_string(mesh.triangle_count()) + "\nproperty list uchar int vertex_indices\n";
    if (ids) out += "property int part_id\nproperty int face_id\n";
    if (ids && has_solid_ids(mesh)) out += "property int solid_id\n";
    out += "end_header\n";
    append_points_and_triangles(out, mesh, ids);
    return out;
}

} // namespace seamless::mesh_text
