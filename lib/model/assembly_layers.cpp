// SPDX-License-Identifier: MIT
// Layers (assembly.h, AssemblyLayer) in terms of faces, and carried through
// flatten_assembly: a part's layer becomes its copies' solids and the faces
// outside them, a solid's and a face's their copies'.
#include <seamless/model/assembly.h>

#include <seamless/model/model.h>

#include <algorithm>

namespace seamless {
namespace {

void sort_unique(std::vector<int>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

// Flags for the indices in v, of a list of n.
std::vector<char> members(const std::vector<int>& v, size_t n) {
    std::vector<char> in(n, 0);
    for (int k : v) in[k] = 1;
    return in;
}

// Each face's solid in b, -1 outside every solid.
std::vector<int> solid_of_face(const BRep& b) {
    std::vector<int> out(b.faces.size(), -1);
    for (size_t s = 0; s < b.solids.size(); ++s)
        for (int shell : b.solids[s].shells)
            for (int f : b.shells[shell].faces) out[f] = static_cast<int>(s);
    return out;
}

} // namespace

std::vector<int> layer_faces(const Model& m, const AssemblyLayer& layer, bool with_parts) {
    const BRep& b = m.brep;
    std::vector<int> out = layer.faces;
    for (int s : layer.solids)
        for (int shell : b.solids[s].shells)
            out.insert(out.end(), b.shells[shell].faces.begin(), b.shells[shell].faces.end());
    if (with_parts) {
        const std::vector<PartRange> ranges = part_ranges(m.assembly);
        for (int p : layer.parts)
            for (int f = 0; f < ranges[p].face_count; ++f) out.push_back(ranges[p].first_face + f);
    }
    sort_unique(out);
    return out;
}

std::vector<AssemblyLayer> placed_layers(const Model& m, const std::vector<int>& first_face,
                                         const std::vector<int>& first_solid) {
    const Assembly& a = m.assembly;
    const std::vector<PartRange> ranges = part_ranges(a);
    const std::vector<int> solid_of = solid_of_face(m.brep);
    std::vector<AssemblyLayer> out;
    for (const AssemblyLayer& layer : a.layers) {
        AssemblyLayer placed;
        placed.name = layer.name;
        placed.visible = layer.visible;
        const std::vector<char> part = members(layer.parts, a.parts.size()),
                                solid = members(layer.solids, m.brep.solids.size()),
                                face = members(layer.faces, m.brep.faces.size());
        for (size_t n = 0; n < a.nodes.size(); ++n) {
            const int p = a.nodes[n].part;
            if (p < 0) continue;
            const PartRange& r = ranges[p];
            const bool whole = part[p];
            for (int s = r.first_solid; s < r.first_solid + r.solid_count; ++s)
                if (whole || solid[s]) placed.solids.push_back(first_solid[n] + s - r.first_solid);
            for (int f = r.first_face; f < r.first_face + r.face_count; ++f)
                if ((whole && solid_of[f] < 0) || face[f])
                    placed.faces.push_back(first_face[n] + f - r.first_face);
        }
        sort_unique(placed.solids);
        sort_unique(placed.faces);
        out.push_back(std::move(placed));
    }
    return out;
}

} // namespace seamless
