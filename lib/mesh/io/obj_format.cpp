// SPDX-License-Identifier: MIT
// OBJ: "v x y z", "f a b c ..." with 1-based or negative indices, "a/t/n" forms;
// face ids as "o part" objects and "g face_N" groups over one vertex list.
#include <seamless/mesh/io/mesh_text.h>

#include <algorithm>
#include <charconv>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace seamless::mesh_text {

namespace {

// The object of triangles on no part ("o -"); a part of that name is written "part_<k>".
constexpr std::string_view kNoPart = "-";

// Face ids as the reader meets them: the current "o" (parts numbered in the
// order their names first appear) and "g face_N".
struct ObjIds {
    std::map<std::string, int> part_of;
    std::vector<std::string> names;
    int part = -1, face = -1;
    bool seen = false;

    void object(const std::string& name) {
        seen = true;
        if (name == kNoPart) {
            part = -1;
            return;
        }
        auto [it, added] = part_of.try_emplace(name, static_cast<int>(names.size()));
        if (added) names.push_back(name);
        part = it->second;
    }
    void group(std::string_view first) {
        face = -1;
        if (first.substr(0, 5) != "face_") return;
        seen = true;
        const std::string_view n = first.substr(5);
        int v = -1;
        auto r = std::from_chars(n.data(), n.data() + n.size(), v);
        if (r.ec == std::errc() && r.ptr == n.data() + n.size() && v >= 0) face = v;
    }
};

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
    ObjIds ids;
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
            const size_t before = mesh.triangles.size();
            add_polygon(mesh, face);
            add_polygon_ids(mesh, before, ids.part, ids.face);
        } else if (key == "o") {
            ids.object(in.rest_of_line());
        } else if (key == "g") {
            ids.group(in.next_in_line());
        } else if (!is_other_obj_statement(key)) {
            in.fail("unknown OBJ statement '" + std::string(key) + "'");
        }
    } while (in.next_line());
    if (ids.seen) {
        mesh.part_names = std::move(ids.names);
    } else {
        mesh.triangle_part.clear();
        mesh.triangle_face.clear();
    }
    return mesh;
}

namespace {

// "f a b c" of triangle t.
std::string obj_triangle(const TriangleMesh& mesh, size_t t) {
    const auto& f = mesh.triangles[t];
    return "f " + std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " +
           std::to_string(f[2] + 1) + "\n";
}

// "o NAME" of part p (-1: none).
std::string obj_object(const TriangleMesh& mesh, int p) {
    const std::string name = part_name(mesh, p);
    return "o " +
           (p < 0             ? std::string(kNoPart)
            : name == kNoPart ? "part_" + std::to_string(p)
                              : name) +
           "\n";
}

// Whether the parts first appear in the order of their ids, all of them
// (the reader numbers parts in the order their names first appear).
bool parts_in_order(const TriangleMesh& mesh) {
    int next = 0;
    for (int p : mesh.triangle_part)
        if (p >= next) {
            if (p != next) return false;
            ++next;
        }
    return next == static_cast<int>(mesh.part_names.size());
}

// The triangles of a mesh with face ids: "o part" where the part changes,
// "g face_N" (or "g no_face") where the face or part changes. Parts that
// would not appear in order are named first, as empty objects.
std::string format_obj_faces(const TriangleMesh& mesh) {
    std::string out;
    if (!parts_in_order(mesh))
        for (int p = 0; p < static_cast<int>(mesh.part_names.size()); ++p)
            out += obj_object(mesh, p);
    int part = -2, face = -2;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const bool new_part = mesh.triangle_part[t] != part;
        if (new_part) {
            part = mesh.triangle_part[t];
            out += obj_object(mesh, part);
        }
        if (new_part || mesh.triangle_face[t] != face) {
            face = mesh.triangle_face[t];
            out += face < 0 ? "g no_face\n" : "g face_" + std::to_string(face) + "\n";
        }
        out += obj_triangle(mesh, t);
    }
    return out;
}

} // namespace

std::string format_obj(const TriangleMesh& mesh) {
    std::string out = "# seamless\n";
    for (Vec3 p : mesh.positions) {
        out += "v ";
        append_point(out, p);
        out += '\n';
    }
    if (has_face_ids(mesh)) return out + format_obj_faces(mesh);
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
        out += obj_triangle(mesh, t);
    }
    return out;
}

} // namespace seamless::mesh_text
