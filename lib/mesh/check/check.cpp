// SPDX-License-Identifier: MIT
// Watertightness check: the steps of docs/check.md composed, each in its own file.
#include <seamless/mesh/check/check.h>
#include <seamless/mesh/check/shell_measures.h>
#include <seamless/mesh/check/weld.h>

#include <algorithm>
#include <functional>
#include <map>
#include <set>

namespace seamless {
namespace {

// The bodies to judge apart and each triangle's (empty: the whole mesh).
CheckBodies body_ids(const TriangleMesh& mesh, const CheckOptions& options,
                     std::vector<int>& triangle_body) {
    const size_t nf = mesh.triangles.size();
    triangle_body.clear();
    if (!options.by_solid || nf == 0) return CheckBodies::whole;
    // One id throughout leaves nothing to judge apart.
    const auto several = [](const std::vector<int>& ids) {
        return std::adjacent_find(ids.begin(), ids.end(), std::not_equal_to<>()) != ids.end();
    };
    if (mesh.triangle_solid.size() == nf && several(mesh.triangle_solid)) {
        triangle_body = mesh.triangle_solid;
        return CheckBodies::solids;
    }
    if (mesh.triangle_part.size() == nf && several(mesh.triangle_part)) {
        triangle_body = mesh.triangle_part;
        return CheckBodies::parts;
    }
    return CheckBodies::whole;
}

// The contacts counted per pair of bodies.
std::vector<BodyContact> body_contacts(const std::vector<TrianglePair>& contacts,
                                       const std::vector<int>& triangle_body) {
    std::map<std::pair<int, int>, BodyContact> by_pair;
    for (const TrianglePair& c : contacts) {
        const auto [b0, b1] = std::minmax(triangle_body[c.t0], triangle_body[c.t1]);
        BodyContact& bc =
            by_pair.try_emplace({b0, b1}, BodyContact{b0, b1, 0, c.location}).first->second;
        ++bc.triangle_pairs;
    }
    std::vector<BodyContact> out;
    for (const auto& entry : by_pair) out.push_back(entry.second);
    return out;
}

} // namespace

CheckReport check_mesh(const TriangleMesh& mesh, const CheckOptions& options) {
    CheckReport R;
    R.input_vertices = mesh.vertex_count();
    R.triangles = mesh.triangle_count();
    R.welded = options.weld;

    std::vector<int> triangle_body;
    R.bodies = body_ids(mesh, options, triangle_body);
    R.body_count =
        static_cast<int>(std::set<int>(triangle_body.begin(), triangle_body.end()).size());
    R.body_count = std::max(R.body_count, 1);
    const WeldedMesh W = weld_vertices(mesh, options.weld, triangle_body);
    R.welded_vertices = W.welded_vertices;
    R.unreferenced_vertices = W.unreferenced_vertices;
    R.body_vertex_copies = W.body_copies;
    R.vertices = static_cast<int>(W.positions.size()) - W.unreferenced_vertices - W.body_copies;
    Box3 box;
    for (size_t v = 0; v < W.positions.size(); ++v)
        if (W.referenced[v]) box.extend(W.positions[v]);
    R.d_max = box.max_extent();
    R.gap = options.gap > 0 ? GapTolerance{options.gap, 0}
                            : GapTolerance{options.gap_floor * R.d_max, options.relative_gap};

    const EdgeTopology E = edge_topology(W);
    R.edges = static_cast<int>(E.groups.size());
    R.border_edges = static_cast<int>(E.border.size());
    R.closed = E.border.empty();
    R.non_manifold_edges = E.non_manifold_edges;
    R.inconsistent_orientation = E.inconsistent_orientation;

    BorderDefects B = border_defects(W, E.border, R.gap);
    R.border_loops = std::move(B.loops);
    R.t_junctions = std::move(B.t_junctions);
    R.cracks = std::move(B.cracks);
    R.seams = std::move(B.seams);
    R.widest_crack = B.widest_crack;

    Shells S = find_shells(W, E, B.joins);
    measure_closed_shells(W, S);
    R.non_manifold_vertices = std::move(S.non_manifold_vertices);
    R.shell_contacts = std::move(S.shell_contacts);

    R.degenerate_triangles = degenerate_triangles(W);
    R.duplicated_triangles = duplicated_triangles(W);
    Intersections I = find_intersections(W, S.triangle_shell, R.degenerate_triangles,
                                         R.duplicated_triangles, R.t_junctions);
    R.self_intersections = std::move(I.self_intersections);
    R.overlaps = std::move(I.overlaps);
    R.contacts = std::move(I.contacts);
    R.body_contacts = body_contacts(R.contacts, triangle_body);
    R.components = std::move(S.shells);
    R.triangle_component = std::move(S.triangle_shell);
    R.component_body.assign(R.components.size(), -1);
    if (!triangle_body.empty())
        for (int t = 0; t < R.triangles; ++t)
            R.component_body[R.triangle_component[t]] = triangle_body[t];
    return R;
}

int defect_count(const CheckReport& r) {
    return static_cast<int>(r.cracks.size() + r.t_junctions.size() + r.non_manifold_edges.size() +
                            r.non_manifold_vertices.size() + r.degenerate_triangles.size() +
                            r.duplicated_triangles.size() + r.inconsistent_orientation.size() +
                            r.self_intersections.size());
}

bool check_passed(const CheckReport& r, const CheckOptions& options) {
    if (defect_count(r) > 0) return false;
    if (options.require_closed)
        for (const auto& c : r.components)
            if (!c.closed) return false;
    return true;
}

} // namespace seamless
