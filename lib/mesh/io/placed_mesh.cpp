// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>
#include <seamless/mesh/io/placed_mesh.h>

#include <filesystem>
#include <map>
#include <utility>

namespace seamless {
namespace {

// The linear part of a placement acting on normals: its cofactor matrix
// (the inverse transpose times the determinant), row-major 3x3.
struct NormalMap {
    double c[9];
    double det;
    explicit NormalMap(const AffineMap& p) {
        const double* a = p.m;
        const auto at = [&](int r, int k) { return a[4 * r + k]; };
        for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k) {
                const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
                c[3 * r + k] = at(r1, k1) * at(r2, k2) - at(r1, k2) * at(r2, k1);
            }
        det = at(0, 0) * c[0] + at(0, 1) * c[1] + at(0, 2) * c[2];
    }
    // The outward normal of the placed surface: (A^-T) n, made unit.
    Vec3 operator()(Vec3 n) const {
        const Vec3 m{c[0] * n.x + c[1] * n.y + c[2] * n.z, c[3] * n.x + c[4] * n.y + c[5] * n.z,
                     c[6] * n.x + c[7] * n.y + c[8] * n.z};
        return normalize(det < 0 ? -1.0 * m : m);
    }
};

// Copies triangle t of `from` into `to` with its corners' vertices
// `index`ed, placed by `map`; a mirror turns it (corners 1 and 2 swapped).
struct TriangleCopier {
    const TriangleMesh& from;
    TriangleMesh& to;
    bool normals, uvs;

    void copy(int t, const std::array<int, 3>& index, const NormalMap* map) {
        const bool turn = map && map->det < 0;
        const int order[3] = {0, turn ? 2 : 1, turn ? 1 : 2};
        std::array<int, 3> tri;
        std::array<Vec3, 3> n;
        std::array<std::array<double, 2>, 3> uv;
        for (int k = 0; k < 3; ++k) {
            tri[k] = index[order[k]];
            if (normals)
                n[k] = map ? (*map)(from.corner_normals[t][order[k]])
                           : from.corner_normals[t][order[k]];
            if (uvs) uv[k] = from.corner_uvs[t][order[k]];
        }
        to.triangles.push_back(tri);
        if (normals) to.corner_normals.push_back(n);
        if (uvs) to.corner_uvs.push_back(uv);
    }
};

std::string file_stem(const Model& m) {
    const std::string stem = std::filesystem::path(m.source).stem().string();
    return stem.empty() ? "part" : stem;
}

// A B-rep model without a tree: face ids from the surfaces, one part.
TriangleMesh with_face_ids(const TriangleMesh& mesh, const Model& model) {
    TriangleMesh out = mesh;
    out.part_names = {file_stem(model)};
    out.triangle_face = triangle_faces(mesh, model);
    const std::vector<int> solid_of = face_solids(model.brep);
    for (int f : out.triangle_face) {
        out.triangle_part.push_back(f >= 0 ? 0 : -1);
        out.triangle_solid.push_back(f >= 0 ? solid_of[f] : -1);
    }
    return out;
}

// Vertex v of part copy: its index in `to`, added (placed) on first use.
class VertexCopies {
  public:
    VertexCopies(const TriangleMesh& from, TriangleMesh& to)
        : from_(from), to_(to), index_(from.positions.size(), -1) {}
    void start_copy(const AffineMap* map) {
        map_ = map;
        std::fill(index_.begin(), index_.end(), -1);
    }
    int operator()(int v) {
        if (index_[v] < 0) {
            index_[v] = to_.vertex_count();
            to_.positions.push_back(map_ ? (*map_)(from_.positions[v]) : from_.positions[v]);
        }
        return index_[v];
    }

  private:
    const TriangleMesh& from_;
    TriangleMesh& to_;
    std::vector<int> index_;
    const AffineMap* map_ = nullptr;
};

} // namespace

std::vector<int> face_solids(const BRep& brep) {
    std::vector<int> solid_of(brep.faces.size(), -1);
    const int nf = static_cast<int>(brep.faces.size());
    for (int s = static_cast<int>(brep.solids.size()) - 1; s >= 0; --s)
        for (int shell : brep.solids[s].shells)
            if (shell >= 0 && shell < static_cast<int>(brep.shells.size()))
                for (int f : brep.shells[shell].faces)
                    if (f >= 0 && f < nf) solid_of[f] = s;
    return solid_of;
}

std::vector<int> face_of_surface(const Model& model) {
    std::vector<int> face_on(model.surfaces.size(), -1);
    std::vector<char> several(model.surfaces.size(), 0);
    for (int f = 0; f < static_cast<int>(model.brep.faces.size()); ++f) {
        const int s = model.brep.faces[f].surface;
        if (s < 0 || s >= static_cast<int>(face_on.size())) continue;
        if (face_on[s] >= 0) several[s] = 1;
        face_on[s] = f;
    }
    for (size_t s = 0; s < face_on.size(); ++s)
        if (several[s]) face_on[s] = -1;
    return face_on;
}

std::vector<int> triangle_faces(const TriangleMesh& mesh, const Model& model) {
    if (mesh.triangle_surface.size() != mesh.triangles.size()) return {};
    const std::vector<int> face_on = face_of_surface(model);
    std::vector<int> out;
    out.reserve(mesh.triangle_surface.size());
    for (int s : mesh.triangle_surface)
        out.push_back(s >= 0 && s < static_cast<int>(face_on.size()) ? face_on[s] : -1);
    return out;
}

std::vector<int> placed_face_sources(const Model& model) {
    std::vector<int> sources;
    if (!model.assembly.has_tree()) {
        for (size_t f = 0; f < model.brep.faces.size(); ++f) sources.push_back(int(f));
        return sources;
    }
    const std::vector<PartRange> ranges = part_ranges(model.assembly);
    for (const AssemblyNode& n : model.assembly.nodes)
        if (n.part >= 0)
            for (int f = 0; f < ranges[n.part].face_count; ++f)
                sources.push_back(ranges[n.part].first_face + f);
    return sources;
}

PlacedCounts placed_counts(const TriangleMesh& mesh, const Model& model) {
    PlacedCounts out{mesh.triangle_count(), mesh.vertex_count(), {}};
    if (model.brep.faces.empty() || mesh.triangle_surface.size() != mesh.triangles.size() ||
        !model.assembly.has_tree())
        return out;
    const std::vector<PartRange> ranges = part_ranges(model.assembly);
    const std::vector<int> part_of = face_parts(model.assembly, model.brep.faces.size());
    out.parts.resize(ranges.size());
    for (const AssemblyNode& n : model.assembly.nodes)
        if (n.part >= 0) ++out.parts[n.part].instances;
    // The triangles of each part, then those on no face (index parts.size()).
    std::vector<std::vector<int>> on_part(ranges.size() + 1);
    const std::vector<int> faces = triangle_faces(mesh, model);
    for (size_t t = 0; t < faces.size(); ++t)
        on_part[faces[t] >= 0 ? part_of[faces[t]] : ranges.size()].push_back(static_cast<int>(t));
    // Each vertex counted once per part using it, as placed_mesh copies it.
    std::vector<long long> triangles(on_part.size(), 0), vertices(on_part.size(), 0);
    std::vector<int> counted_for(mesh.positions.size(), -1);
    for (size_t p = 0; p < on_part.size(); ++p) {
        triangles[p] = static_cast<long long>(on_part[p].size());
        for (int t : on_part[p])
            for (int v : mesh.triangles[t])
                if (counted_for[v] != static_cast<int>(p))
                    counted_for[v] = static_cast<int>(p), ++vertices[p];
    }
    out.triangles = triangles.back();
    out.vertices = vertices.back();
    for (size_t p = 0; p < ranges.size(); ++p) {
        PlacedCounts::Part& part = out.parts[p];
        part.triangles = triangles[p];
        part.vertices = vertices[p];
        out.triangles += part.instances * part.triangles;
        out.vertices += part.instances * part.vertices;
    }
    return out;
}

TriangleMesh placed_mesh(const TriangleMesh& mesh, const Model& model) {
    if (model.brep.faces.empty() || mesh.triangle_surface.size() != mesh.triangles.size())
        return mesh;
    if (!model.assembly.has_tree()) return with_face_ids(mesh, model);
    const Assembly& a = model.assembly;
    const size_t nt = mesh.triangles.size();
    const std::vector<int> face_on = face_of_surface(model);
    // The triangles on each face of the model, in order; those on no face.
    std::vector<std::vector<int>> on_face(model.brep.faces.size());
    std::vector<int> on_no_face;
    for (size_t t = 0; t < nt; ++t) {
        const int s = mesh.triangle_surface[t];
        const int f = s >= 0 && s < static_cast<int>(face_on.size()) ? face_on[s] : -1;
        (f >= 0 ? on_face[f] : on_no_face).push_back(static_cast<int>(t));
    }
    TriangleMesh out;
    TriangleCopier copier{mesh, out, mesh.corner_normals.size() == nt,
                          mesh.corner_uvs.size() == nt};
    CopyNames part_names, face_names;
    for (const AssemblyPart& p : a.parts) out.part_names.push_back(part_names(p.name));
    const std::vector<int> sources = placed_face_sources(model);
    const std::vector<PartRange> ranges = part_ranges(a);
    const std::vector<AffineMap> world = world_placements(a);
    VertexCopies vertex(mesh, out);
    const std::vector<int> solid_of = face_solids(model.brep);
    int flat = 0;        // the face copied, in flatten_assembly's order
    int first_solid = 0; // this copy's first solid, in that order
    for (size_t n = 0; n < a.nodes.size(); ++n) {
        const int p = a.nodes[n].part;
        if (p < 0) continue;
        const NormalMap normal_map(world[n]);
        vertex.start_copy(&world[n]);
        for (int f = ranges[p].first_face; f < ranges[p].first_face + ranges[p].face_count;
             ++f, ++flat) {
            out.surface_names.push_back(face_names(model.brep.faces[f].name));
            for (int t : on_face[f]) {
                const auto& c = mesh.triangles[t];
                copier.copy(t, {vertex(c[0]), vertex(c[1]), vertex(c[2])}, &normal_map);
                out.triangle_face.push_back(flat);
                out.triangle_surface.push_back(flat);
                out.triangle_part.push_back(p);
                out.triangle_solid.push_back(
                    solid_of[f] >= 0 ? first_solid + solid_of[f] - ranges[p].first_solid : -1);
            }
        }
        first_solid += ranges[p].solid_count;
    }
    SEAMLESS_CHECK(flat == static_cast<int>(sources.size()), "placed faces counted twice");
    // Surfaces no face lies on, once, as flatten_assembly copies them.
    std::map<int, int> free_surface;
    vertex.start_copy(nullptr);
    for (int t : on_no_face) {
        const int s = mesh.triangle_surface[t];
        auto [it, added] = free_surface.try_emplace(s, static_cast<int>(out.surface_names.size()));
        if (added)
            out.surface_names.push_back(s >= 0 && s < static_cast<int>(mesh.surface_names.size())
                                            ? mesh.surface_names[s]
                                            : "surface" + std::to_string(s));
        const auto& c = mesh.triangles[t];
        copier.copy(t, {vertex(c[0]), vertex(c[1]), vertex(c[2])}, nullptr);
        out.triangle_face.push_back(-1);
        out.triangle_surface.push_back(it->second);
        out.triangle_part.push_back(-1);
        out.triangle_solid.push_back(-1);
    }
    return out;
}

} // namespace seamless
