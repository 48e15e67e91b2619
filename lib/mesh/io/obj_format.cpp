// SPDX-License-Identifier: MIT
// OBJ: "v x y z", "f a b c ..." with 1-based or negative indices, "a/t/n" forms;
// "g name" groups map to triangle_surface when written by us.
#include <seamless/mesh/io/mesh_text.h>

#include <algorithm>
#include <iterator>
#include <string>
#include <vector>

namespace seamless::mesh_text {

namespace {

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

} // namespace

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

} // namespace seamless::mesh_text
