// SPDX-License-Identifier: MIT
#include "check_report.h"

#include <seamless/mesh/check/defect_faces.h>

#include <sstream>

namespace seamless::cli {
namespace {

std::string point(Vec3 p) {
    std::ostringstream os;
    os.precision(10);
    os << "(" << p.x << ", " << p.y << ", " << p.z << ")";
    return os.str();
}

// Prints up to `max` entries of a defect list with a heading and its count.
template <class T, class F>
void print_list(std::ostream& os, const char* heading, const std::vector<T>& v, F&& line,
                size_t max) {
    os << heading << ": " << v.size() << "\n";
    for (size_t i = 0; i < v.size() && i < max; ++i) os << "  " << line(v[i]) << "\n";
    if (v.size() > max) os << "  ... " << (v.size() - max) << " more (--json lists them)\n";
}

// " on face 12 of part 0 (nut), ..." for a defect on `triangles`; "" without face ids.
std::string on(const TriangleMesh* mesh, const std::vector<int>& triangles) {
    const std::string p = mesh ? places(*mesh, triangles) : "";
    return p.empty() ? "" : " on " + p;
}

std::string tolerance(const GapTolerance& g) {
    std::ostringstream s;
    s.precision(6);
    if (g.relative > 0)
        s << g.relative * 100 << "% of the local edge length, at least " << g.absolute;
    else
        s << g.absolute;
    return s.str();
}

// Welding, counts, the gap tolerance and the border loops.
void print_counts(std::ostream& os, const CheckReport& r, size_t max, const TriangleMesh* mesh) {
    if (r.welded)
        os << "welded " << r.welded_vertices << " of " << r.input_vertices
           << " vertices with bit-identical positions\n";
    else
        os << "no welding (--no-weld): " << r.input_vertices << " vertices as indexed\n";
    os << "vertices " << r.vertices << ", triangles " << r.triangles << ", edges " << r.edges
       << ", components (shells) " << r.components.size();
    if (r.unreferenced_vertices) os << ", unreferenced vertices " << r.unreferenced_vertices;
    os << "\n";
    os << "d_max " << r.d_max << ", gap tolerance " << tolerance(r.gap) << "\n";
    os << "border edges " << r.border_edges << " in " << r.border_loops.size() << " loop"
       << (r.border_loops.size() == 1 ? "" : "s") << ": " << (r.closed ? "closed" : "open") << "\n";
    for (size_t i = 0; i < r.border_loops.size() && i < max; ++i) {
        const auto& l = r.border_loops[i];
        os << "  loop of " << l.edges << " edges, length " << l.length << ", at " << point(l.start)
           << (l.closed ? "" : " (not closed)") << on(mesh, l.triangles) << "\n";
    }
    if (r.border_loops.size() > max) os << "  ... " << r.border_loops.size() - max << " more\n";
}

// Non-manifold elements, shell contacts, seams, cracks and T-junctions.
void print_edge_defects(std::ostream& os, const CheckReport& r, size_t max,
                        const TriangleMesh* mesh) {
    print_list(
        os, "non-manifold edges", r.non_manifold_edges,
        [](const EdgeDefect& e) {
            return point(e.p0) + " - " + point(e.p1) + ", " + std::to_string(e.triangles) +
                   " triangles";
        },
        max);
    print_list(
        os, "non-manifold vertices (a shell pinched)", r.non_manifold_vertices,
        [](const VertexDefect& v) { return point(v.position); }, max);
    print_list(
        os, "shell contacts (shells touching at a vertex, not a defect)", r.shell_contacts,
        [](const VertexDefect& v) { return point(v.position); }, max);
    print_list(
        os, "seams (cracks: border edges along border edges)", r.seams,
        [](const Seam& s) {
            std::ostringstream o;
            o.precision(10);
            o << "seam of " << s.edges << " crack edges, length " << s.length << ", at "
              << point(s.location) << " from " << point(s.from) << " to " << point(s.to)
              << ", widest gap " << s.gap;
            return o.str();
        },
        max);
    print_list(
        os, "cracks (border edges)", r.cracks,
        [mesh](const Crack& c) {
            std::ostringstream s;
            s.precision(10);
            s << "triangle " << c.triangle << " edge at " << point(c.location)
              << " runs along triangle " << c.other_triangle << ", gap " << c.gap << " (seam "
              << c.seam << ")" << on(mesh, {c.triangle, c.other_triangle});
            return s.str();
        },
        max);
    if (!r.cracks.empty()) os << "widest crack gap: " << r.widest_crack << "\n";
    print_list(
        os, "T-junctions", r.t_junctions,
        [mesh](const TJunction& t) {
            std::ostringstream s;
            s.precision(10);
            s << "vertex " << t.vertex << " at " << point(t.position) << " on an edge of triangle "
              << t.triangle << ", distance " << t.distance << on(mesh, {t.triangle});
            return s.str();
        },
        max);
}

// The solids (or parts) judged apart and the pairs of them that touch.
void print_bodies(std::ostream& os, const CheckReport& r, size_t max) {
    if (r.bodies == CheckBodies::whole) return;
    const std::string kind = r.bodies == CheckBodies::solids ? "solid" : "part";
    os << "judged apart: " << r.body_count << " " << kind << (r.body_count == 1 ? "" : "s")
       << " (--union judges the mesh whole)";
    if (r.body_vertex_copies)
        os << ", " << r.body_vertex_copies << " vertices they share judged in each";
    os << "\n";
    os << "contacts between " << kind << "s (not a defect): " << r.contacts.size()
       << " triangle pairs\n";
    print_list(
        os, ("  " + kind + "s in contact").c_str(), r.body_contacts,
        [&](const BodyContact& c) {
            return kind + "s " + std::to_string(c.body0) + " and " + std::to_string(c.body1) +
                   ": " + std::to_string(c.triangle_pairs) + " triangle pairs, at " +
                   point(c.location);
        },
        max);
}

// Triangle defects and overlaps, then the shells with their measures.
void print_triangles_and_shells(std::ostream& os, const CheckReport& r, size_t max,
                                const TriangleMesh* mesh) {
    auto tri = [mesh](const TriangleDefect& d) {
        return "triangle " + std::to_string(d.triangle) + " at " + point(d.location) +
               on(mesh, {d.triangle});
    };
    auto pair = [mesh](const TrianglePair& p) {
        return "triangles " + std::to_string(p.t0) + " and " + std::to_string(p.t1) + " at " +
               point(p.location) + on(mesh, {p.t0, p.t1});
    };
    print_list(os, "degenerate triangles", r.degenerate_triangles, tri, max);
    print_list(os, "duplicated triangles", r.duplicated_triangles, pair, max);
    print_list(os, "inconsistently oriented neighbours", r.inconsistent_orientation, pair, max);
    print_list(os, "self-intersections within a shell", r.self_intersections, pair, max);
    print_list(os, "overlaps between shells (not a defect)", r.overlaps, pair,
               std::min<size_t>(max, 5));
    print_bodies(os, r, max);
    const char* body = r.bodies == CheckBodies::parts ? "part" : "solid";
    for (size_t c = 0; c < r.components.size(); ++c) {
        const auto& C = r.components[c];
        if (c >= 20) {
            os << "... " << r.components.size() - 20 << " more shells\n";
            break;
        }
        os << "shell " << c;
        if (r.bodies != CheckBodies::whole && c < r.component_body.size())
            os << " (" << body << " " << r.component_body[c] << ")";
        os << ": " << C.triangles << " triangles, "
           << (C.closed ? "closed" : "open (" + std::to_string(C.border_edges) + " border edges)");
        if (C.euler) os << ", Euler characteristic " << *C.euler;
        if (C.genus) os << ", genus " << *C.genus;
        if (C.volume) os << ", volume " << *C.volume;
        if (C.outward) os << (*C.outward ? ", outward" : ", inward");
        os << "\n";
    }
}

// The faces with defects on them (a mesh with face ids).
void print_defect_faces(std::ostream& os, const CheckReport& r, size_t max,
                        const TriangleMesh& mesh) {
    const std::vector<DefectFace> faces = defect_faces(mesh, r);
    if (faces.empty()) return;
    std::vector<std::string> lines;
    for (const DefectFace& f : faces) {
        lines.push_back(triangle_place(mesh, f.triangle) + ": " + std::to_string(f.defects) +
                        (f.defects == 1 ? " defect or border loop" : " defects or border loops"));
    }
    print_list(
        os, "faces with defects or border loops", lines, [](const std::string& s) { return s; },
        max);
}

} // namespace

void print_check_report(std::ostream& os, const CheckReport& r, size_t max,
                        const TriangleMesh* mesh) {
    os.precision(10);
    print_counts(os, r, max, mesh);
    print_edge_defects(os, r, max, mesh);
    print_triangles_and_shells(os, r, max, mesh);
    if (mesh) print_defect_faces(os, r, max, *mesh);
    os << "defects: " << defect_count(r) << "\n";
}

} // namespace seamless::cli
