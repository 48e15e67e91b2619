// SPDX-License-Identifier: MIT
#include <seamless/mesh/check/check_json.h>

#include <nlohmann/json.hpp>

namespace seamless {
namespace {

using nlohmann::json;

json point_json(Vec3 p) {
    return json::array({p.x, p.y, p.z});
}

// {"count": all entries, "listed": the first max_listed as one(entry)}.
template <class T, class F> json list_json(const std::vector<T>& v, int max_listed, F&& one) {
    json a = json::array();
    for (size_t i = 0; i < v.size() && static_cast<int>(i) < max_listed; ++i)
        a.push_back(one(v[i]));
    return json{{"count", v.size()}, {"listed", a}};
}

json pair_json(const TrianglePair& p) {
    return json{{"triangles", {p.t0, p.t1}}, {"location", point_json(p.location)}};
}

json vertex_json(const VertexDefect& v) {
    return json{{"vertex", v.vertex}, {"location", point_json(v.position)}};
}

// Border loops, non-manifold elements and shell contacts.
void add_topology(json& j, const CheckReport& r, int max_listed) {
    j["border_loops"] = list_json(r.border_loops, max_listed, [&](const BorderLoop& l) {
        return json{{"edges", l.edges},
                    {"length", l.length},
                    {"start", point_json(l.start)},
                    {"closed", l.closed}};
    });
    j["non_manifold_edges"] = list_json(r.non_manifold_edges, max_listed, [&](const EdgeDefect& e) {
        return json{{"vertices", {e.v0, e.v1}},
                    {"from", point_json(e.p0)},
                    {"to", point_json(e.p1)},
                    {"triangles", e.triangles}};
    });
    j["non_manifold_vertices"] = list_json(r.non_manifold_vertices, max_listed, vertex_json);
    j["shell_contacts"] = list_json(r.shell_contacts, max_listed, vertex_json);
}

// T-junctions, seams and cracks.
void add_border_defects(json& j, const CheckReport& r, int max_listed) {
    j["t_junctions"] = list_json(r.t_junctions, max_listed, [&](const TJunction& t) {
        return json{{"vertex", t.vertex},
                    {"location", point_json(t.position)},
                    {"triangle", t.triangle},
                    {"edge", {t.v0, t.v1}},
                    {"distance", t.distance}};
    });
    j["seams"] = list_json(r.seams, max_listed, [&](const Seam& s) {
        return json{{"edges", s.edges},
                    {"length", s.length},
                    {"gap", s.gap},
                    {"location", point_json(s.location)},
                    {"from", point_json(s.from)},
                    {"to", point_json(s.to)}};
    });
    j["cracks"] = list_json(r.cracks, max_listed, [&](const Crack& c) {
        return json{{"triangle", c.triangle},
                    {"edge", {c.v0, c.v1}},
                    {"other_triangle", c.other_triangle},
                    {"other_edge", {c.w0, c.w1}},
                    {"location", point_json(c.location)},
                    {"gap", c.gap},
                    {"seam", c.seam}};
    });
    j["widest_crack"] = r.widest_crack;
}

// Degenerate, duplicated, misoriented and intersecting triangles.
void add_triangle_defects(json& j, const CheckReport& r, int max_listed) {
    j["degenerate_triangles"] =
        list_json(r.degenerate_triangles, max_listed, [&](const TriangleDefect& d) {
            return json{{"triangle", d.triangle}, {"location", point_json(d.location)}};
        });
    j["duplicated_triangles"] = list_json(r.duplicated_triangles, max_listed, pair_json);
    j["inconsistent_orientation"] = list_json(r.inconsistent_orientation, max_listed, pair_json);
    j["self_intersections"] = list_json(r.self_intersections, max_listed, pair_json);
    j["overlaps"] = list_json(r.overlaps, max_listed, pair_json);
}

const char* bodies_name(CheckBodies b) {
    return b == CheckBodies::solids ? "solids" : b == CheckBodies::parts ? "parts" : "whole";
}

// The bodies judged apart and where they touch.
void add_bodies(json& j, const CheckReport& r, int max_listed) {
    j["bodies"] = bodies_name(r.bodies);
    j["body_count"] = r.body_count;
    j["body_vertex_copies"] = r.body_vertex_copies;
    j["contacts"] = list_json(r.contacts, max_listed, pair_json);
    j["body_contacts"] = list_json(r.body_contacts, max_listed, [&](const BodyContact& c) {
        return json{{"bodies", {c.body0, c.body1}},
                    {"triangle_pairs", c.triangle_pairs},
                    {"location", point_json(c.location)}};
    });
}

json components_json(const CheckReport& r) {
    json comps = json::array();
    for (size_t k = 0; k < r.components.size(); ++k) {
        const ComponentReport& c = r.components[k];
        json o{{"vertices", c.vertices},
               {"triangles", c.triangles},
               {"edges", c.edges},
               {"border_edges", c.border_edges},
               {"closed", c.closed}};
        if (c.euler) o["euler"] = *c.euler;
        if (c.genus) o["genus"] = *c.genus;
        if (c.volume) o["volume"] = *c.volume;
        if (c.outward) o["outward"] = *c.outward;
        if (r.bodies != CheckBodies::whole && k < r.component_body.size())
            o["body"] = r.component_body[k];
        comps.push_back(o);
    }
    return comps;
}

} // namespace

std::string check_report_json(const CheckReport& r, int max_listed) {
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
    add_topology(j, r, max_listed);
    add_border_defects(j, r, max_listed);
    add_triangle_defects(j, r, max_listed);
    add_bodies(j, r, max_listed);
    j["component_list"] = components_json(r);
    j["defects"] = defect_count(r);
    return j.dump(2);
}

} // namespace seamless
