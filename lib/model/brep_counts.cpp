// SPDX-License-Identifier: MIT
#include <seamless/model/brep_counts.h>

#include <algorithm>
#include <vector>

namespace seamless {

BRepCounts count(const BRep& b) {
    BRepCounts c;
    c.solids = static_cast<int>(b.solids.size());
    c.shells = static_cast<int>(b.shells.size());
    c.faces = static_cast<int>(b.faces.size());
    c.edges = static_cast<int>(b.edges.size());
    c.vertices = static_cast<int>(b.vertices.size());
    for (const BRepShell& s : b.shells) c.closed_shells += s.closed;
    // A seam edge is one that some face uses twice.
    std::vector<int> last_face(b.edges.size(), -1);
    std::vector<char> seam(b.edges.size(), 0);
    for (size_t f = 0; f < b.faces.size(); ++f) {
        const BRepFace& face = b.faces[f];
        c.faces_with_holes += face.loops.size() > 1;
        c.loops += static_cast<int>(face.loops.size());
        for (const BRepLoop& loop : face.loops)
            for (const BRepCoedge& ce : loop.coedges) {
                ++c.coedges;
                if (ce.edge < 0 || ce.edge >= c.edges) continue; // validate_brep's to report
                if (last_face[ce.edge] == static_cast<int>(f)) seam[ce.edge] = 1;
                last_face[ce.edge] = static_cast<int>(f);
            }
    }
    for (size_t e = 0; e < b.edges.size(); ++e) {
        c.seam_edges += seam[e];
        c.degenerate_edges += b.edges[e].degenerate();
        c.max_edge_tolerance = std::max(c.max_edge_tolerance, b.edges[e].tolerance);
    }
    for (const BRepVertex& v : b.vertices)
        c.max_vertex_tolerance = std::max(c.max_vertex_tolerance, v.tolerance);
    return c;
}

} // namespace seamless
