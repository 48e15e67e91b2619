// SPDX-License-Identifier: MIT
// Seeds of a redone face (face_seeds.h): a face whose edge a neighbour's
// round re-split, redone from its earlier mesh, meets the limits as well as
// one redone from scratch, over the same boundary, for less work.
#include <tessellate/trimmed/brep_cases.h>

#include <seamless/tessellate/trimmed/faces/face_triangulation.h>

#include <catch2/catch.hpp>

using namespace seamless;
using namespace seamless::test;

TEST_CASE("face seeds: a face redone after an edge is halved meets the limits with less work",
          "[brep][heavy]") {
    for (const BRepCase& c : {freeform_face(), torus_solid(), sphere_solid()}) {
        INFO(c.name);
        const BRep& brep = c.model.brep;
        const double D = 3e-3;
        // Each edge discretised against the faces that use it, as tessellation does.
        std::vector<std::vector<EdgeOnFace>> uses(brep.edges.size());
        for (const BRepFace& f : brep.faces)
            for (const BRepLoop& loop : f.loops)
                for (const BRepCoedge& k : loop.coedges)
                    uses[k.edge].push_back({FaceSurface(c.model.surfaces[f.surface]),
                                            &brep.pcurves[k.pcurve], brep.edges[k.edge].tolerance,
                                            face_uv_centre(brep, f)});
        std::vector<EdgePolyline> lines(brep.edges.size());
        for (size_t e = 0; e < lines.size(); ++e)
            lines[e] = discretise_edge(brep, static_cast<int>(e), uses[e], {D, 0.5});
        const FaceCriteria criteria{D, 0.5};
        // The first face with interior points that meets the limits alone.
        int face = -1;
        FaceMesh earlier;
        for (int f = 0; f < static_cast<int>(brep.faces.size()) && face < 0; ++f) {
            earlier = triangulate_face(c.model, lines, f, criteria);
            if (!earlier.failed && earlier.above_tolerance == 0 &&
                earlier.domain.size() > earlier.domain.boundary_points + 10)
                face = f;
        }
        REQUIRE(face >= 0);
        // A neighbour's round halves every segment of the face's first edge.
        const int e = brep.faces[face].loops[0].coedges[0].edge;
        halve_segments(brep, e, lines[e]);
        const FaceMesh fresh = triangulate_face(c.model, lines, face, criteria);
        const FaceMesh seeded = triangulate_face(c.model, lines, face, criteria, &earlier);
        REQUIRE(!seeded.failed);
        CHECK(seeded.above_tolerance <= fresh.above_tolerance);
        CHECK(seeded.deviation <= D);
        CHECK(seeded.judged < fresh.judged);
        // The same boundary, point for point: the neighbours see one polyline.
        REQUIRE(seeded.domain.boundary_points == fresh.domain.boundary_points);
        for (int i = 0; i < fresh.domain.boundary_points; ++i)
            CHECK(seeded.domain.keys[i] == fresh.domain.keys[i]);
        // Away from the halved edge the earlier interior points are kept.
        int kept = 0;
        for (int i = seeded.domain.boundary_points; i < seeded.domain.size(); ++i)
            for (int j = earlier.domain.boundary_points; j < earlier.domain.size(); ++j)
                if (seeded.domain.uv[i] == earlier.domain.uv[j]) {
                    ++kept;
                    break;
                }
        CHECK(kept > 0);
    }
}
