// SPDX-License-Identifier: MIT
// OFF: "OFF", counts "V F E", V lines of x y z [extra], F lines of n i0 .. i(n-1).
#include <seamless/mesh/io/mesh_text.h>

#include <string>
#include <vector>

namespace seamless::mesh_text {
namespace {

std::string_view skip_comments(Tokens& in) {
    for (;;) {
        auto t = in.next();
        if (t.empty() || t[0] != '#') return t;
        if (!in.next_line()) return {};
    }
}

} // namespace

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
void append_points_and_triangles(std::string& out, const TriangleMesh& mesh, bool face_ids) {
    for (Vec3 p : mesh.positions) {
        append_point(out, p);
        out += '\n';
    }
    const bool solid_ids = face_ids && has_solid_ids(mesh);
    for (size_t k = 0; k < mesh.triangles.size(); ++k) {
        const auto& t = mesh.triangles[k];
        out += '3';
        for (int v : t) (out += ' ') += std::to_string(v);
        if (face_ids)
            for (int id : {mesh.triangle_part[k], mesh.triangle_face[k]})
                (out += ' ') += std::to_string(id);
        if (solid_ids) (out += ' ') += std::to_string(mesh.triangle_solid[k]);
        out += '\n';
    }
}

std::string format_off(const TriangleMesh& mesh) {
    std::string out = "OFF\n" + std::to_string(mesh.vertex_count()) + " " +
                      std::to_string(mesh.triangle_count()) + " 0\n";
    append_points_and_triangles(out, mesh, false);
    return out;
}

} // namespace seamless::mesh_text
