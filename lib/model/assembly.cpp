// SPDX-License-Identifier: MIT
#include <seamless/model/assembly.h>

#include <seamless/base/error.h>
#include <seamless/model/model.h>

#include <cmath>

namespace seamless {

std::vector<PartRange> part_ranges(const Assembly& a) {
    std::vector<PartRange> out;
    PartRange r;
    for (const AssemblyPart& p : a.parts) {
        r.first_face += r.face_count;
        r.first_shell += r.shell_count;
        r.first_solid += r.solid_count;
        r.face_count = p.face_count;
        r.shell_count = p.shell_count;
        r.solid_count = p.solid_count;
        out.push_back(r);
    }
    return out;
}

std::vector<int> face_parts(const Assembly& a, size_t faces) {
    std::vector<int> out(faces, -1);
    const std::vector<PartRange> ranges = part_ranges(a);
    for (size_t p = 0; p < ranges.size(); ++p)
        for (int f = 0; f < ranges[p].face_count; ++f)
            out[ranges[p].first_face + f] = static_cast<int>(p);
    return out;
}

int instance_count(const Assembly& a) {
    int n = 0;
    for (const AssemblyNode& node : a.nodes) n += node.part >= 0;
    return n;
}

AffineMap then(const AffineMap& a, const AffineMap& b) {
    AffineMap c;
    for (int r = 0; r < 3; ++r)
        for (int col = 0; col < 4; ++col) {
            double s = col == 3 ? b.m[4 * r + 3] : 0;
            for (int k = 0; k < 3; ++k) s += b.m[4 * r + k] * a.m[4 * k + col];
            c.m[4 * r + col] = s;
        }
    return c;
}

std::vector<AffineMap> world_placements(const Assembly& a) {
    std::vector<AffineMap> world(a.nodes.size());
    for (size_t k = 0; k < a.nodes.size(); ++k) {
        const AssemblyNode& n = a.nodes[k];
        world[k] = n.parent < 0 ? n.placement : then(n.placement, world[n.parent]);
    }
    return world;
}

std::vector<int> face_colours(const Model& m) {
    const Assembly& a = m.assembly;
    const BRep& b = m.brep;
    std::vector<int> out(b.faces.size(), -1);
    // Part, then solid, then face: each later one overrides.
    const std::vector<PartRange> ranges = part_ranges(a);
    for (size_t p = 0; p < a.parts.size(); ++p)
        for (int f = 0; f < ranges[p].face_count; ++f)
            out[ranges[p].first_face + f] = a.parts[p].colour;
    if (!a.solid_colours.empty())
        for (size_t s = 0; s < b.solids.size(); ++s) {
            if (a.solid_colours[s] < 0) continue;
            for (int shell : b.solids[s].shells)
                for (int f : b.shells[shell].faces) out[f] = a.solid_colours[s];
        }
    if (!a.face_colours.empty())
        for (size_t f = 0; f < out.size(); ++f)
            if (a.face_colours[f] >= 0) out[f] = a.face_colours[f];
    return out;
}

namespace {

std::string field(const std::string& list, size_t k) {
    return "assembly." + list + "[" + std::to_string(k) + "]";
}

void check_index(const std::string& file, const std::string& f, int i, int lo, size_t n,
                 const char* what) {
    if (i < lo || i >= static_cast<int>(n))
        throw InputError(file, f,
                         "index " + std::to_string(i) + " out of range " + std::to_string(lo) +
                             ".." + std::to_string(static_cast<long long>(n) - 1) + " (" + what +
                             ")");
}

void check_placement(const std::string& file, const std::string& f, const AffineMap& map) {
    for (int k = 0; k < 12; ++k)
        if (!std::isfinite(map.m[k]) || std::abs(map.m[k]) > kMaxCoordinate)
            throw InputError(file, f + "[" + std::to_string(k) + "]",
                             "not a finite number within the coordinate limit");
    const double* a = map.m;
    const double det = a[0] * (a[5] * a[10] - a[6] * a[9]) - a[1] * (a[4] * a[10] - a[6] * a[8]) +
                       a[2] * (a[4] * a[9] - a[5] * a[8]);
    if (!(std::abs(det) > 0) || !std::isfinite(det))
        throw InputError(file, f, "not invertible (its 3x3 part has determinant 0)");
}

// One colour index (-1: none) per item, or none at all.
void check_colour_list(const std::string& file, const char* list, const std::vector<int>& v,
                       size_t items, size_t colours) {
    if (v.empty()) return;
    if (v.size() != items)
        throw InputError(file, std::string("assembly.") + list,
                         "expected " + std::to_string(items) + " colour indices, got " +
                             std::to_string(v.size()));
    for (size_t k = 0; k < v.size(); ++k)
        check_index(file, field(list, k), v[k], -1, colours, "colours");
}

// The part's shells use its own faces, its solids its own shells.
void check_part_items(const Model& m, const std::string& file, size_t p, const PartRange& r) {
    const BRep& b = m.brep;
    for (int s = r.first_shell; s < r.first_shell + r.shell_count; ++s)
        for (int f : b.shells[s].faces)
            if (f < r.first_face || f >= r.first_face + r.face_count)
                throw InputError(file, field("parts", p),
                                 "its shell " + std::to_string(s) + " uses face " +
                                     std::to_string(f) + ", which is not the part's");
    for (int s = r.first_solid; s < r.first_solid + r.solid_count; ++s)
        for (int sh : b.solids[s].shells)
            if (sh < r.first_shell || sh >= r.first_shell + r.shell_count)
                throw InputError(file, field("parts", p),
                                 "its solid " + std::to_string(s) + " uses shell " +
                                     std::to_string(sh) + ", which is not the part's");
}

void check_parts(const Model& m, const std::string& file) {
    const Assembly& a = m.assembly;
    const BRep& b = m.brep;
    if (a.parts.empty()) {
        if (!a.nodes.empty())
            throw InputError(file, "assembly.nodes",
                             "a tree needs parts (assembly.parts is empty)");
        return;
    }
    if (b.empty()) throw InputError(file, "assembly.parts", "parts need a B-rep (brep.faces)");
    long long faces = 0, shells = 0, solids = 0;
    for (size_t p = 0; p < a.parts.size(); ++p) {
        const AssemblyPart& part = a.parts[p];
        if (part.face_count < 0 || part.shell_count < 0 || part.solid_count < 0)
            throw InputError(file, field("parts", p), "negative count");
        check_index(file, field("parts", p) + ".colour", part.colour, -1, a.colours.size(),
                    "colours");
        faces += part.face_count;
        shells += part.shell_count;
        solids += part.solid_count;
    }
    const auto total = [&](const char* what, long long got, size_t want) {
        if (got != static_cast<long long>(want))
            throw InputError(file, "assembly.parts",
                             "the parts hold " + std::to_string(got) + " " + what + ", the B-rep " +
                                 std::to_string(want));
    };
    total("faces", faces, b.faces.size());
    total("shells", shells, b.shells.size());
    total("solids", solids, b.solids.size());
    const std::vector<PartRange> ranges = part_ranges(a);
    for (size_t p = 0; p < ranges.size(); ++p) check_part_items(m, file, p, ranges[p]);
}

// Each layer's parts, solids and faces in range.
void check_layers(const Model& m, const std::string& file) {
    const Assembly& a = m.assembly;
    for (size_t k = 0; k < a.layers.size(); ++k) {
        const AssemblyLayer& layer = a.layers[k];
        const std::string f = field("layers", k);
        for (size_t i = 0; i < layer.parts.size(); ++i)
            check_index(file, f + ".parts[" + std::to_string(i) + "]", layer.parts[i], 0,
                        a.parts.size(), "parts");
        for (size_t i = 0; i < layer.solids.size(); ++i)
            check_index(file, f + ".solids[" + std::to_string(i) + "]", layer.solids[i], 0,
                        m.brep.solids.size(), "brep.solids");
        for (size_t i = 0; i < layer.faces.size(); ++i)
            check_index(file, f + ".faces[" + std::to_string(i) + "]", layer.faces[i], 0,
                        m.brep.faces.size(), "brep.faces");
    }
}

} // namespace

void validate_assembly(const Model& m, const std::string& file) {
    const Assembly& a = m.assembly;
    for (size_t k = 0; k < a.colours.size(); ++k) {
        const Rgba& c = a.colours[k];
        for (double x : {c.r, c.g, c.b, c.a})
            if (!(x >= 0 && x <= 1))
                throw InputError(file, field("colours", k), "components must lie in 0..1");
    }
    check_parts(m, file);
    for (size_t k = 0; k < a.nodes.size(); ++k) {
        const AssemblyNode& n = a.nodes[k];
        check_index(file, field("nodes", k) + ".parent", n.parent, -1, k, "nodes before it");
        check_index(file, field("nodes", k) + ".part", n.part, -1, a.parts.size(), "parts");
        check_placement(file, field("nodes", k) + ".placement", n.placement);
    }
    check_colour_list(file, "solid_colours", a.solid_colours, m.brep.solids.size(),
                      a.colours.size());
    check_colour_list(file, "face_colours", a.face_colours, m.brep.faces.size(), a.colours.size());
    check_layers(m, file);
}

} // namespace seamless
