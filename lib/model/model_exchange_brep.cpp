// SPDX-License-Identifier: MIT
// The B-rep in the model exchange form (model_exchange.h): vertices, curves,
// pcurves, edges, faces with their loops, shells and solids, in that order;
// every index is checked against its list as it is read.
#include <seamless/model/model_exchange_codec.h>

namespace seamless::exchange {

void ExchangeWriter::brep(const BRep& b) {
    list(b.vertices, [&](const BRepVertex& v) {
        scalar(v.point.x), scalar(v.point.y), scalar(v.point.z), scalar(v.tolerance);
    });
    list(b.curves, [&](const BSplineCurve& c) { curve(c); });
    list(b.pcurves, [&](const BSplineCurve& c) { curve(c); });
    list(b.edges, [&](const BRepEdge& e) {
        for (int i : {e.curve, e.start, e.end}) scalar<std::int32_t>(i);
        scalar(e.t0), scalar(e.t1), scalar(e.tolerance);
    });
    list(b.faces, [&](const BRepFace& f) {
        scalar<std::int32_t>(f.surface);
        scalar<std::uint8_t>(f.reversed);
        string(f.name);
        list(f.loops, [&](const BRepLoop& l) {
            list(l.coedges, [&](const BRepCoedge& c) {
                scalar<std::int32_t>(c.edge);
                scalar<std::uint8_t>(c.reversed);
                scalar<std::int32_t>(c.pcurve);
            });
        });
    });
    list(b.shells, [&](const BRepShell& s) {
        ints(s.faces);
        scalar<std::uint8_t>(s.closed);
    });
    list(b.solids, [&](const BRepSolid& s) {
        ints(s.shells);
        string(s.name);
    });
}

void ExchangeReader::brep(Model& m) {
    BRep& b = m.brep;
    b.vertices.resize(items({nullptr, "brep.vertices"}, 4 * sizeof(double)));
    for (std::size_t k = 0; k < b.vertices.size(); ++k) {
        const Path f{nullptr, "brep.vertices", static_cast<long long>(k)};
        b.vertices[k].point = point({&f, "point"});
        if (!is_finite(b.vertices[k].point)) fail({&f, "point"}, "not a finite point");
        b.vertices[k].tolerance = number({&f, "tolerance"});
    }
    b.curves.resize(items({nullptr, "brep.curves"}, 28));
    for (std::size_t k = 0; k < b.curves.size(); ++k)
        b.curves[k] = curve({nullptr, "brep.curves", static_cast<long long>(k)});
    b.pcurves.resize(items({nullptr, "brep.pcurves"}, 28));
    for (std::size_t k = 0; k < b.pcurves.size(); ++k)
        b.pcurves[k] = curve({nullptr, "brep.pcurves", static_cast<long long>(k)});
    b.edges.resize(items({nullptr, "brep.edges"}, 36));
    for (std::size_t k = 0; k < b.edges.size(); ++k) {
        const Path f{nullptr, "brep.edges", static_cast<long long>(k)};
        BRepEdge& e = b.edges[k];
        e.curve = index({&f, "curve"}, b.curves.size(), true);
        e.start = index({&f, "start"}, b.vertices.size());
        e.end = index({&f, "end"}, b.vertices.size());
        e.t0 = number({&f, "t0"});
        e.t1 = number({&f, "t1"});
        e.tolerance = number({&f, "tolerance"});
        if (!(e.t0 < e.t1)) fail(f, "empty parameter range");
    }
    b.faces.resize(items({nullptr, "brep.faces"}, 21));
    for (std::size_t k = 0; k < b.faces.size(); ++k) {
        const Path f{nullptr, "brep.faces", static_cast<long long>(k)};
        BRepFace& face = b.faces[k];
        face.surface = index({&f, "surface"}, m.surfaces.size());
        face.reversed = flag({&f, "reversed"});
        face.name = string({&f, "name"});
        face.loops.resize(items({&f, "loops"}, 8));
        for (std::size_t l = 0; l < face.loops.size(); ++l) {
            const Path fl{&f, "loops", static_cast<long long>(l)};
            std::vector<BRepCoedge>& coedges = face.loops[l].coedges;
            coedges.resize(items({&fl, "coedges"}, 9));
            for (std::size_t c = 0; c < coedges.size(); ++c) {
                const Path fc{&fl, "coedges", static_cast<long long>(c)};
                coedges[c].edge = index({&fc, "edge"}, b.edges.size());
                coedges[c].reversed = flag({&fc, "reversed"});
                coedges[c].pcurve = index({&fc, "pcurve"}, b.pcurves.size());
            }
        }
    }
    b.shells.resize(items({nullptr, "brep.shells"}, 9));
    for (std::size_t k = 0; k < b.shells.size(); ++k) {
        const Path f{nullptr, "brep.shells", static_cast<long long>(k)};
        b.shells[k].faces.resize(items({&f, "faces"}, 4));
        for (int& face : b.shells[k].faces) face = index({&f, "faces"}, b.faces.size());
        b.shells[k].closed = flag({&f, "closed"});
    }
    b.solids.resize(items({nullptr, "brep.solids"}, 16));
    for (std::size_t k = 0; k < b.solids.size(); ++k) {
        const Path f{nullptr, "brep.solids", static_cast<long long>(k)};
        b.solids[k].shells.resize(items({&f, "shells"}, 4));
        for (int& shell : b.solids[k].shells) shell = index({&f, "shells"}, b.shells.size());
        b.solids[k].name = string({&f, "name"});
    }
}

} // namespace seamless::exchange
