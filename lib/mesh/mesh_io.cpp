// SPDX-License-Identifier: MIT
// OFF, OBJ, PLY and STL readers and writers, glTF dispatch.
//
// Why not OpenMesh IO for these: OpenMesh 9's readers and writers pass every
// point through Vec3f (BaseImporter::add_vertex(Vec3f), BaseExporter::point), so
// even with a precision of 17 digits a text file holds float values and reading
// 0.1 yields 0.10000000149011612. Its OBJ reader also drops faces with a repeated
// vertex and its STL reader merges equal vertices. The code here writes every
// coordinate as the shortest decimal that reads back to the same double
// (std::to_chars, at most 17 significant digits) and parses with std::from_chars
// (correctly rounded), so text files round-trip bit-identically, and reads every
// face exactly as the file indexes it.
#include <seamless/base/atomic_file.h>
#include <seamless/base/error.h>
#include <seamless/base/input_file.h>
#include <seamless/mesh/gltf_io.h>
#include <seamless/mesh/mesh_io.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string_view>

namespace seamless {
namespace {

namespace fs = std::filesystem;

std::string lower_extension(const fs::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

// ---------------------------------------------------------------------------
// Number formatting and parsing.

void append_number(std::string& out, double v) {
    char buf[32];
    auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, r.ptr);
}

// A number as the shortest text that reads back to it ("nan", "1e+300"), for messages.
std::string number_text(double v) {
    std::string s;
    append_number(s, v);
    return s;
}

void append_point(std::string& out, Vec3 p) {
    append_number(out, p.x);
    out += ' ';
    append_number(out, p.y);
    out += ' ';
    append_number(out, p.z);
}

// Whitespace-separated tokens with line numbers, for the text formats.
class Tokens {
  public:
    Tokens(std::string_view text, std::string file) : s_(text), file_(std::move(file)) {}

    // Next token on the current line; empty at the end of the line.
    std::string_view next_in_line() {
        while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\r'))
            ++pos_;
        size_t b = pos_;
        while (pos_ < s_.size() && !std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
        return s_.substr(b, pos_ - b);
    }
    // Moves to the start of the next line; false at the end of the text.
    bool next_line() {
        while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
        if (pos_ >= s_.size()) return false;
        ++pos_;
        ++line_;
        return true;
    }
    // Next token, crossing lines; empty at the end of the text.
    std::string_view next() {
        for (;;) {
            auto t = next_in_line();
            if (!t.empty() || !next_line()) return t;
        }
    }
    bool at_end() const { return pos_ >= s_.size(); }
    size_t position() const { return pos_; }
    long long line() const { return line_; }
    [[noreturn]] void fail(const std::string& message) const {
        throw InputError(file_, "line " + std::to_string(line_), message);
    }
    double number(std::string_view t) const {
        double v = 0;
        if (!t.empty() && t[0] == '+') t.remove_prefix(1);
        auto r = std::from_chars(t.data(), t.data() + t.size(), v);
        if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size())
            fail("expected a number, got '" + std::string(t) + "'");
        return v;
    }
    long long integer(std::string_view t) const {
        long long v = 0;
        if (!t.empty() && t[0] == '+') t.remove_prefix(1);
        auto r = std::from_chars(t.data(), t.data() + t.size(), v);
        if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size())
            fail("expected an integer, got '" + std::string(t) + "'");
        return v;
    }

  private:
    std::string_view s_;
    std::string file_;
    size_t pos_ = 0;
    long long line_ = 1; // a 2 GiB file may hold more lines than an int counts
};

// A count read from a header must be possible for a file of `size` bytes,
// each element taking at least `min_bytes`.
long long checked_count(const std::string& file, const std::string& field, long long n, size_t size,
                        size_t min_bytes) {
    if (n < 0 || static_cast<unsigned long long>(n) > size / min_bytes + 1 || n > (1LL << 31) - 1)
        throw InputError(file, field,
                         "count " + std::to_string(n) + " impossible for a file of " +
                             std::to_string(size) + " bytes");
    return n;
}

// Adds the polygon `face` as a fan of triangles.
void add_polygon(TriangleMesh& mesh, const std::vector<long long>& face) {
    for (size_t k = 1; k + 1 < face.size(); ++k)
        mesh.triangles.push_back(
            {static_cast<int>(face[0]), static_cast<int>(face[k]), static_cast<int>(face[k + 1])});
}

// Shared checks of what every reader produced.
void validate(const TriangleMesh& mesh, const std::string& file) {
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        if (!is_finite(mesh.positions[i]))
            throw InputError(file, "vertex " + std::to_string(i), "non-finite coordinate");
    const int n = mesh.vertex_count();
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int v : mesh.triangles[t])
            if (v < 0 || v >= n)
                throw InputError(file, "triangle " + std::to_string(t),
                                 "vertex index " + std::to_string(v) + " out of range [0, " +
                                     std::to_string(n) + ")");
}

// ---------------------------------------------------------------------------
// OFF: "OFF", counts "V F E", V lines of x y z [extra], F lines of n i0 .. i(n-1).

std::string_view skip_comments(Tokens& in) {
    for (;;) {
        auto t = in.next();
        if (t.empty() || t[0] != '#') return t;
        if (!in.next_line()) return {};
    }
}

TriangleMesh read_off(const std::string& text, const std::string& file) {
    Tokens in(text, file);
    auto magic = skip_comments(in);
    if (magic.size() < 3 || magic.substr(magic.size() - 3) != "OFF")
        in.fail("expected an OFF header");
    if (magic.find("n") != std::string_view::npos || magic == "4OFF")
        in.fail("unsupported OFF variant '" + std::string(magic) + "'");
    const long long nv =
        checked_count(file, "vertex count", in.integer(skip_comments(in)), text.size(), 6);
    const long long nf =
        checked_count(file, "face count", in.integer(skip_comments(in)), text.size(), 4);
    in.integer(skip_comments(in)); // edge count, unused
    TriangleMesh mesh;
    mesh.positions.reserve(static_cast<size_t>(nv));
    for (long long i = 0; i < nv; ++i) {
        auto t = skip_comments(in);
        if (t.empty())
            in.fail("file ends after " + std::to_string(i) + " of " + std::to_string(nv) +
                    " vertices");
        Vec3 p;
        p.x = in.number(t);
        p.y = in.number(in.next_in_line());
        p.z = in.number(in.next_in_line());
        mesh.positions.push_back(p);
        in.next_line(); // colours and other extras
    }
    std::vector<long long> face;
    for (long long f = 0; f < nf; ++f) {
        auto t = skip_comments(in);
        if (t.empty())
            in.fail("file ends after " + std::to_string(f) + " of " + std::to_string(nf) +
                    " faces");
        const long long n = in.integer(t);
        if (n < 3 || n > 1000000) in.fail("face with " + std::to_string(n) + " vertices");
        face.resize(static_cast<size_t>(n));
        for (auto& v : face) {
            v = in.integer(in.next_in_line());
            if (v < 0 || v >= nv) in.fail("vertex index " + std::to_string(v) + " out of range");
        }
        add_polygon(mesh, face);
        in.next_line();
    }
    return mesh;
}

// The body that OFF and ASCII PLY share: one "x y z" line per vertex, then
// one "3 a b c" line per triangle (0-based indices).
void append_points_and_triangles(std::string& out, const TriangleMesh& mesh) {
    for (Vec3 p : mesh.positions) {
        append_point(out, p);
        out += '\n';
    }
    for (auto& t : mesh.triangles)
        out += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " +
               std::to_string(t[2]) + "\n";
}

std::string format_off(const TriangleMesh& mesh) {
    std::string out = "OFF\n" + std::to_string(mesh.vertex_count()) + " " +
                      std::to_string(mesh.triangle_count()) + " 0\n";
    append_points_and_triangles(out, mesh);
    return out;
}

// ---------------------------------------------------------------------------
// OBJ: "v x y z", "f a b c ..." with 1-based or negative indices, "a/t/n" forms;
// "g name" groups map to triangle_surface when written by us.

// Statements of the OBJ format (Wavefront, "Object Files (.obj)", B1) that
// carry no triangles: accepted and ignored. Anything else is an error.
bool is_other_obj_statement(std::string_view k) {
    static constexpr std::string_view known[] = {
        "vt",       "vn",         "vp",        "l",      "p",      "g",    "o",     "s",
        "mg",       "mtllib",     "usemtl",    "usemap", "maplib", "lod",  "bevel", "c_interp",
        "d_interp", "shadow_obj", "trace_obj", "cstype", "deg",    "bmat", "step",  "curv",
        "curv2",    "surf",       "parm",      "trim",   "hole",   "scrv", "sp",    "end",
        "con",      "ctech",      "stech",     "call",   "csh"};
    return std::find(std::begin(known), std::end(known), k) != std::end(known);
}

TriangleMesh read_obj(std::string_view text, const std::string& file) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3); // UTF-8 byte order mark
    Tokens in(text, file);
    TriangleMesh mesh;
    std::vector<long long> face;
    do {
        auto key = in.next_in_line();
        if (key.empty() || key[0] == '#') continue;
        if (key == "v") {
            Vec3 p;
            p.x = in.number(in.next_in_line());
            p.y = in.number(in.next_in_line());
            p.z = in.number(in.next_in_line());
            mesh.positions.push_back(p);
        } else if (key == "f") {
            face.clear();
            for (auto t = in.next_in_line(); !t.empty(); t = in.next_in_line()) {
                long long v = in.integer(t.substr(0, t.find('/')));
                const long long n = mesh.vertex_count();
                if (v < 0)
                    v += n;
                else
                    --v;
                if (v < 0 || v >= n)
                    in.fail("vertex index " + std::string(t) + " out of range (" +
                            std::to_string(n) + " vertices so far)");
                face.push_back(v);
            }
            if (face.size() < 3) in.fail("face with fewer than 3 vertices");
            add_polygon(mesh, face);
        } else if (!is_other_obj_statement(key)) {
            in.fail("unknown OBJ statement '" + std::string(key) + "'");
        }
    } while (in.next_line());
    return mesh;
}

std::string format_obj(const TriangleMesh& mesh) {
    std::string out = "# seamless\n";
    for (Vec3 p : mesh.positions) {
        out += "v ";
        append_point(out, p);
        out += '\n';
    }
    const bool groups = !mesh.triangle_surface.empty();
    int current = -1;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (groups && mesh.triangle_surface[t] != current) {
            current = mesh.triangle_surface[t];
            out += "g ";
            out += current >= 0 && current < static_cast<int>(mesh.surface_names.size())
                       ? mesh.surface_names[current]
                       : "surface" + std::to_string(current);
            out += '\n';
        }
        auto& f = mesh.triangles[t];
        out += "f " + std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " +
               std::to_string(f[2] + 1) + "\n";
    }
    return out;
}

// ---------------------------------------------------------------------------
// PLY: ascii, binary_little_endian and binary_big_endian; the vertex element's
// x, y, z and the face element's vertex_indices (or vertex_index) list; other
// elements and properties are skipped.

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

// ---------------------------------------------------------------------------
// STL: every triangle carries its own three corners, so reading gives 3 vertices
// per triangle (no welding). Binary STL stores float32; we write ASCII STL with
// shortest round-trip doubles, which this reader restores bit-identically (other
// programs usually round them to float).

TriangleMesh read_stl(const std::string& text, const std::string& file) {
    TriangleMesh mesh;
    bool binary = false;
    if (text.size() >= 84) {
        uint32_t n;
        std::memcpy(&n, text.data() + 80, 4);
        if constexpr (std::endian::native == std::endian::big) n = __builtin_bswap32(n);
        binary = 84 + 50ull * n == text.size();
    }
    if (!binary && text.compare(0, 5, "solid") != 0)
        throw InputError(file, "", "neither ASCII STL ('solid') nor binary STL of consistent size");
    if (binary) {
        uint32_t n;
        std::memcpy(&n, text.data() + 80, 4);
        mesh.positions.reserve(3ull * n);
        for (uint32_t f = 0; f < n; ++f) {
            const auto* rec = reinterpret_cast<const unsigned char*>(text.data()) + 84 + 50ull * f;
            for (int c = 0; c < 3; ++c) {
                Vec3 p;
                for (int k = 0; k < 3; ++k)
                    p[k] = ply_binary_value(rec + 12 + 12 * c + 4 * k, PlyType::f32, false);
                mesh.positions.push_back(p);
            }
            const int b = static_cast<int>(3 * f);
            mesh.triangles.push_back({b, b + 1, b + 2});
        }
        return mesh;
    }
    // ASCII STL, strictly: one or more "solid [name]" ... "endsolid [name]",
    // each holding facets "facet normal nx ny nz / outer loop / vertex x y z
    // (three times) / endloop / endfacet". Anything else is an error.
    Tokens in(text, file);
    auto expect = [&](std::string_view want) {
        const auto t = in.next();
        if (t != want)
            in.fail("expected '" + std::string(want) + "', got " +
                    (t.empty() ? std::string("the end of the file") : "'" + std::string(t) + "'"));
    };
    for (auto t = in.next(); !t.empty(); t = in.next()) {
        if (t != "solid") in.fail("expected 'solid', got '" + std::string(t) + "'");
        in.next_line(); // the solid's name
        for (;;) {
            const auto k = in.next();
            if (k == "endsolid") {
                in.next_line();
                break;
            }
            if (k != "facet")
                in.fail(k.empty() ? std::string("file ends inside a solid (no 'endsolid')")
                                  : "expected 'facet' or 'endsolid', got '" + std::string(k) + "'");
            expect("normal");
            for (int i = 0; i < 3; ++i) in.number(in.next());
            expect("outer");
            expect("loop");
            for (int c = 0; c < 3; ++c) {
                const auto v = in.next();
                if (v == "endloop") in.fail("facet with " + std::to_string(c) + " vertices");
                if (v != "vertex")
                    in.fail("expected 'vertex', got " + (v.empty()
                                                             ? std::string("the end of the file")
                                                             : "'" + std::string(v) + "'"));
                Vec3 p;
                p.x = in.number(in.next());
                p.y = in.number(in.next());
                p.z = in.number(in.next());
                mesh.positions.push_back(p);
            }
            const auto e = in.next();
            if (e == "vertex") in.fail("facet with more than 3 vertices");
            if (e != "endloop")
                in.fail("expected 'endloop', got " + (e.empty() ? std::string("the end of the file")
                                                                : "'" + std::string(e) + "'"));
            expect("endfacet");
            const int b = mesh.vertex_count() - 3;
            mesh.triangles.push_back({b, b + 1, b + 2});
        }
    }
    return mesh;
}

std::string format_stl(const TriangleMesh& mesh) {
    std::string out = "solid seamless\n";
    for (auto& t : mesh.triangles) {
        const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
        out += "facet normal ";
        append_point(out, normalize(cross(b - a, c - a)));
        out += "\n outer loop\n";
        for (Vec3 p : {a, b, c}) {
            out += "  vertex ";
            append_point(out, p);
            out += '\n';
        }
        out += " endloop\nendfacet\n";
    }
    out += "endsolid seamless\n";
    return out;
}

} // namespace

bool is_mesh_extension(const std::string& ext) {
    std::string e = ext;
    for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return e == ".off" || e == ".obj" || e == ".ply" || e == ".stl" || e == ".gltf" || e == ".glb";
}

void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh) {
    const std::string ext = lower_extension(path);
    const std::string file = path.string();
    if (!is_mesh_extension(ext))
        throw InputError(file, "",
                         "unknown mesh extension '" + ext +
                             "' (expected .off .obj .ply .stl .gltf .glb)");
    validate(mesh, file);
    if (ext == ".gltf" || ext == ".glb") {
        write_atomically(path,
                         [&](const fs::path& tmp) { write_gltf(tmp, mesh, ext == ".glb", file); });
        return;
    }
    const std::string text = ext == ".off"   ? format_off(mesh)
                             : ext == ".obj" ? format_obj(mesh)
                             : ext == ".ply" ? format_ply(mesh)
                                             : format_stl(mesh);
    write_atomically(path, [&](const fs::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) throw InputError(file, "", "cannot open for writing");
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        out.close();
        if (!out) throw InputError(file, "", "write failed");
    });
}

TriangleMesh parse_mesh(const std::string& bytes, const std::string& format,
                        const std::string& file, const std::filesystem::path& base_dir) {
    std::string ext = format;
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (!is_mesh_extension(ext))
        throw InputError(file, "",
                         "unknown mesh extension '" + ext +
                             "' (expected .off .obj .ply .stl .gltf .glb)");
    TriangleMesh mesh = naming_file_on_oom(file, [&] {
        return ext == ".gltf"  ? parse_gltf(bytes, false, file, base_dir)
               : ext == ".glb" ? parse_gltf(bytes, true, file, base_dir)
               : ext == ".off" ? read_off(bytes, file)
               : ext == ".obj" ? read_obj(bytes, file)
               : ext == ".ply" ? read_ply(bytes, file)
                               : read_stl(bytes, file);
    });
    validate(mesh, file);
    // A file with nothing to check is never a clean mesh.
    if (mesh.triangles.empty()) throw InputError(file, "", "holds no triangles");
    return mesh;
}

TriangleMesh read_mesh(const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    const std::string file = path.string();
    if (!is_mesh_extension(ext))
        throw InputError(file, "",
                         "unknown mesh extension '" + ext +
                             "' (expected .off .obj .ply .stl .gltf .glb)");
    const std::string bytes = read_input_file(path, kMaxMeshFileBytes, "mesh");
    return parse_mesh(bytes, ext, file, path.parent_path());
}

} // namespace seamless
