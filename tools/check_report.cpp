// SPDX-License-Identifier: MIT
#include "check_report.h"

#include <nlohmann/json.hpp>

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

std::string tolerance(const GapTolerance& g) {
    std::ostringstream s;
    s.precision(6);
    if (g.relative > 0)
        s << g.relative * 100 << "% of the local edge length, at least " << g.absolute;
    else
        s << g.absolute;
    return s.str();
}

} // namespace

void print_check_report(std::ostream& os, const CheckReport& r, size_t max) {
    os.precision(10);
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
           << (l.closed ? "" : " (not closed)") << "\n";
    }
    if (r.border_loops.size() > max) os << "  ... " << r.border_loops.size() - max << " more\n";
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
        [](const Crack& c) {
            std::ostringstream s;
            s.precision(10);
            s << "triangle " << c.triangle << " edge at " << point(c.location)
              << " runs along triangle " << c.other_triangle << ", gap " << c.gap << " (seam "
              << c.seam << ")";
            return s.str();
        },
        max);
    if (!r.cracks.empty()) os << "widest crack gap: " << r.widest_crack << "\n";
    print_list(
        os, "T-junctions", r.t_junctions,
        [](const TJunction& t) {
            std::ostringstream s;
            s.precision(10);
            s << "vertex " << t.vertex << " at " << point(t.position) << " on an edge of triangle "
              << t.triangle << ", distance " << t.distance;
            return s.str();
        },
        max);
    auto tri = [](const TriangleDefect& d) {
        return "triangle " + std::to_string(d.triangle) + " at " + point(d.location);
    };
    auto pair = [](const TrianglePair& p) {
        return "triangles " + std::to_string(p.t0) + " and " + std::to_string(p.t1) + " at " +
               point(p.location);
    };
    print_list(os, "degenerate triangles", r.degenerate_triangles, tri, max);
    print_list(os, "duplicated triangles", r.duplicated_triangles, pair, max);
    print_list(os, "inconsistently oriented neighbours", r.inconsistent_orientation, pair, max);
    print_list(os, "self-intersections within a shell", r.self_intersections, pair, max);
    print_list(os, "overlaps between shells (not a defect)", r.overlaps, pair,
               std::min<size_t>(max, 5));
    for (size_t c = 0; c < r.components.size(); ++c) {
        const auto& C = r.components[c];
        if (c >= 20) {
            os << "... " << r.components.size() - 20 << " more shells\n";
            break;
        }
        os << "shell " << c << ": " << C.triangles << " triangles, "
           << (C.closed ? "closed" : "open (" + std::to_string(C.border_edges) + " border edges)");
        if (C.euler) os << ", Euler characteristic " << *C.euler;
        if (C.genus) os << ", genus " << *C.genus;
        if (C.volume) os << ", volume " << *C.volume;
        if (C.outward) os << (*C.outward ? ", outward" : ", inward");
        os << "\n";
    }
    os << "defects: " << defect_count(r) << "\n";
}

std::string check_report_json(const CheckReport& r, int max_listed) {
    using nlohmann::json;
    auto pt = [](Vec3 p) { return json::array({p.x, p.y, p.z}); };
    auto list = [&](const auto& v, auto&& one) {
        json a = json::array();
        for (size_t i = 0; i < v.size() && static_cast<int>(i) < max_listed; ++i)
            a.push_back(one(v[i]));
        return json{{"count", v.size()}, {"listed", a}};
    };
    auto pair = [&](const TrianglePair& p) {
        return json{{"triangles", {p.t0, p.t1}}, {"location", pt(p.location)}};
    };
    json j;
    j["d_max"] = r.d_max;
    j["gap"] = r.gap.absolute;
    j["relative_gap"] = r.gap.relative;
    j["weld"] = r.welded;
    j["input_vertices"] = r.input_vertices;
    j["welded_vertices"] = r.welded_vertices;
    j["unreferenced_vertices"] = r.unreferenced_vertices;
    j["vertices"] = r.vertices;
    j["triangles"] = r.triangles;
    j["edges"] = r.edges;
    j["components"] = r.components.size();
    j["border_edges"] = r.border_edges;
    j["closed"] = r.closed;
    j["border_loops"] = list(r.border_loops, [&](const BorderLoop& l) {
        return json{
            {"edges", l.edges}, {"length", l.length}, {"start", pt(l.start)}, {"closed", l.closed}};
    });
    j["non_manifold_edges"] = list(r.non_manifold_edges, [&](const EdgeDefect& e) {
        return json{{"vertices", {e.v0, e.v1}},
                    {"from", pt(e.p0)},
                    {"to", pt(e.p1)},
                    {"triangles", e.triangles}};
    });
    auto vertex = [&](const VertexDefect& v) {
        return json{{"vertex", v.vertex}, {"location", pt(v.position)}};
    };
    j["non_manifold_vertices"] = list(r.non_manifold_vertices, vertex);
    j["shell_contacts"] = list(r.shell_contacts, vertex);
    j["t_junctions"] = list(r.t_junctions, [&](const TJunction& t) {
        return json{{"vertex", t.vertex},
                    {"location", pt(t.position)},
                    {"triangle", t.triangle},
                    {"edge", {t.v0, t.v1}},
                    {"distance", t.distance}};
    });
    j["seams"] = list(r.seams, [&](const Seam& s) {
        return json{{"edges", s.edges},           {"length", s.length}, {"gap", s.gap},
                    {"location", pt(s.location)}, {"from", pt(s.from)}, {"to", pt(s.to)}};
    });
    j["cracks"] = list(r.cracks, [&](const Crack& c) {
        return json{{"triangle", c.triangle},
                    {"edge", {c.v0, c.v1}},
                    {"other_triangle", c.other_triangle},
                    {"other_edge", {c.w0, c.w1}},
                    {"location", pt(c.location)},
                    {"gap", c.gap},
                    {"seam", c.seam}};
    });
    j["widest_crack"] = r.widest_crack;
    j["degenerate_triangles"] = list(r.degenerate_triangles, [&](const TriangleDefect& d) {
        return json{{"triangle", d.triangle}, {"location", pt(d.location)}};
    });
    j["duplicated_triangles"] = list(r.duplicated_triangles, pair);
    j["inconsistent_orientation"] = list(r.inconsistent_orientation, pair);
    j["self_intersections"] = list(r.self_intersections, pair);
    j["overlaps"] = list(r.overlaps, pair);
    json comps = json::array();
    for (const auto& c : r.components) {
        json o{{"vertices", c.vertices},
               {"triangles", c.triangles},
               {"edges", c.edges},
               {"border_edges", c.border_edges},
               {"closed", c.closed}};
        if (c.euler) o["euler"] = *c.euler;
        if (c.genus) o["genus"] = *c.genus;
        if (c.volume) o["volume"] = *c.volume;
        if (c.outward) o["outward"] = *c.outward;
        comps.push_back(o);
    }
    j["component_list"] = comps;
    j["defects"] = defect_count(r);
    return j.dump(2);
}

} // namespace seamless::cli
