// SPDX-License-Identifier: MIT
// What the text mesh formats share (mesh_io.cpp's readers and writers, one
// file per format: off_format.cpp, obj_format.cpp, ply_format.cpp,
// stl_format.cpp): shortest round-trip numbers, tokens with line numbers,
// header counts checked against the file size. Internal to lib/mesh/io.
#pragma once

#include <seamless/base/error.h>
#include <seamless/base/triangle_mesh.h>

#include <cctype>
#include <charconv>
#include <string>
#include <string_view>
#include <vector>

namespace seamless::mesh_text {

// Numbers are written as the shortest text that reads back to the same
// double (std::to_chars) and read correctly rounded (std::from_chars).
inline void append_number(std::string& out, double v) {
    char buf[32];
    auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, r.ptr);
}

// A number as the shortest text that reads back to it ("nan", "1e+300"), for messages.
inline std::string number_text(double v) {
    std::string s;
    append_number(s, v);
    return s;
}

inline void append_point(std::string& out, Vec3 p) {
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
    // The rest of the line's tokens, one space apart (a name).
    std::string rest_of_line() {
        std::string s;
        for (auto t = next_in_line(); !t.empty(); t = next_in_line()) {
            if (!s.empty()) s += ' ';
            s += t;
        }
        return s;
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
inline long long checked_count(const std::string& file, const std::string& field, long long n,
                               size_t size, size_t min_bytes) {
    if (n < 0 || static_cast<unsigned long long>(n) > size / min_bytes + 1 || n > (1LL << 31) - 1)
        throw InputError(file, field,
                         "count " + std::to_string(n) + " impossible for a file of " +
                             std::to_string(size) + " bytes");
    return n;
}

// Adds the polygon `face` as a fan of triangles.
inline void add_polygon(TriangleMesh& mesh, const std::vector<long long>& face) {
    for (size_t k = 1; k + 1 < face.size(); ++k)
        mesh.triangles.push_back(
            {static_cast<int>(face[0]), static_cast<int>(face[k]), static_cast<int>(face[k + 1])});
}

// The body that OFF and ASCII PLY share: one "x y z" line per vertex, then
// one "3 a b c" line per triangle (0-based indices), with `face_ids` its
// part and face id after it ("3 a b c part face"), and its solid id when the
// mesh has them (has_solid_ids).
void append_points_and_triangles(std::string& out, const TriangleMesh& mesh, bool face_ids);

// Whether `mesh` holds face ids to write: triangle_face and triangle_part
// for every triangle.
inline bool has_face_ids(const TriangleMesh& mesh) {
    return !mesh.triangles.empty() && mesh.triangle_face.size() == mesh.triangles.size() &&
           mesh.triangle_part.size() == mesh.triangles.size();
}

// Whether `mesh` also holds solid ids: triangle_solid for every triangle.
inline bool has_solid_ids(const TriangleMesh& mesh) {
    return !mesh.triangles.empty() && mesh.triangle_solid.size() == mesh.triangles.size();
}

// A name on one line of a text format: control characters become spaces,
// an empty name "unnamed".
inline std::string one_line(const std::string& name) {
    std::string s = name;
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
    return s.find_first_not_of(' ') == std::string::npos ? "unnamed" : s;
}

// The name of part p of a mesh with face ids: part_names[p], else "part_<p>".
inline std::string part_name(const TriangleMesh& mesh, int p) {
    return p >= 0 && p < static_cast<int>(mesh.part_names.size()) ? one_line(mesh.part_names[p])
                                                                  : "part_" + std::to_string(p);
}

// Adds per-triangle ids for the triangles add_polygon added since `before`.
inline void add_polygon_ids(TriangleMesh& mesh, size_t before, int part, int face) {
    for (size_t t = before; t < mesh.triangles.size(); ++t) {
        mesh.triangle_part.push_back(part);
        mesh.triangle_face.push_back(face);
    }
}

// The formats: `text` the file's bytes, `file` its name in messages. The
// readers throw InputError naming the file and the line or element.
TriangleMesh read_off(const std::string& text, const std::string& file);
std::string format_off(const TriangleMesh& mesh);
TriangleMesh read_obj(std::string_view text, const std::string& file);
std::string format_obj(const TriangleMesh& mesh);
TriangleMesh read_ply(const std::string& text, const std::string& file);
std::string format_ply(const TriangleMesh& mesh);
TriangleMesh read_stl(const std::string& text, const std::string& file);
std::string format_stl(const TriangleMesh& mesh);

} // namespace seamless::mesh_text
