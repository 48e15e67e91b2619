// SPDX-License-Identifier: MIT
#include <seamless/base/error.h>
#include <seamless/base/parallel/parallel.h>
#include <seamless/base/phase_clock.h>
#include <seamless/tessellate/tessellation.h>
#include <seamless/tessellate/tessellation_pass.h>
#include <seamless/tessellate/trimmed/brep_tessellation.h>
#include <seamless/tessellate/trimmed/face_trees.h>
#include <seamless/tessellate/trimmed/free_surfaces.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace seamless {

namespace {

// Face f's triangles: the runs of one surface in the B-rep mesh (faces are
// written in order; two faces on one surface in a row share a tree, which
// only a traversal's work sees).
std::vector<int> surface_runs(const TriangleMesh& mesh) {
    std::vector<int> first{0};
    const std::vector<int>& s = mesh.triangle_surface;
    for (size_t t = 1; t < s.size(); ++t)
        if (s[t] != s[t - 1]) first.push_back(static_cast<int>(t));
    if (!s.empty()) first.push_back(static_cast<int>(s.size()));
    return first;
}

// The trimmed faces through tessellate/trimmed/, the surfaces no face uses
// through the Bezier pipeline, joined (free_surfaces.h); with patch trees,
// one tree per face for the renderer (face_trees.h).
Tessellation tessellate_brep_model(const Model& model, const TessellationOptions& options) {
    Tessellation t = tessellate_brep(model, options);
    if (options.patch_trees) t.trees = face_trees(t.mesh, surface_runs(t.mesh));
    const std::vector<int> free = free_surfaces(model);
    if (!free.empty()) {
        const Model part = free_surface_model(model, free);
        TessellationOptions po = options;
        po.progress = nullptr;
        append_tessellation(t, tessellate(part, bezier_patches(part), po), free);
    }
    return t;
}

} // namespace

Tessellation tessellate(const Model& model, const TessellationOptions& options) {
    if (!model.brep.empty()) return tessellate_brep_model(model, options); // trimmed faces
    return tessellate(model, bezier_patches(model), options);
}

namespace {

void add(PhaseSeconds& sum, const PhaseSeconds& p) {
    sum.subdivision += p.subdivision;
    sum.boundaries += p.boundaries;
    sum.rings += p.rings;
    sum.numbering += p.numbering;
    sum.bounds += p.bounds;
    sum.normals += p.normals;
    sum.fans += p.fans;
    sum.orientation += p.orientation;
}

// With a tolerance: a subpatch accepted by its four-triangle bound can end
// above the tolerance once neighbours add vertices to its sides (its final
// fan and phi differ from the four triangles'); such subpatches are split in
// another pass (rarely more than one).
// The trees' hulls come out multiplied by `hull_scale` (TessellationPass).
Tessellation tessellate_at_unit_scale(const Model& model, const std::vector<BezierPatch>& patches,
                                      const TessellationOptions& options, double hull_scale) {
    const auto start = std::chrono::steady_clock::now();
    TessellationPass passes(model, patches, options, hull_scale);
    Tessellation t;
    PhaseSeconds phases;
    constexpr int kPasses = 5;
    int pass = 0;
    for (;; ++pass) {
        const bool last = options.tolerance <= 0 || pass == kPasses - 1;
        t = passes.run(pass, last);
        add(phases, t.stats.phases);
        if (last || t.stats.above_tolerance == 0) break;
        passes.split_again(t);
    }
    // More than four triangles to a fan can pass the subdivision's count.
    if (t.stats.triangles > options.max_triangles) refuse_triangle_budget(model, options);
    t.stats.passes = pass + 1;
    if (options.progress) options.progress(1.0);
    t.stats.phases = phases;
    t.stats.seconds = seconds_since(start);
    return t;
}

} // namespace

Tessellation tessellate(const Model& model, const std::vector<BezierPatch>& patches,
                        const TessellationOptions& options) {
    // Stiff cases: huge and tiny coordinates. Cross products and squared
    // distances of coordinates far from 1 overflow or underflow (a plane
    // through three points of size 1e-151 has a normal of length 0 in
    // doubles), so the work is done at the power-of-two scale that brings
    // d_max into [1, 2): exact both ways, the result is the same mesh, scaled.
    const Box3 box = control_box(model);
    const double dm = box.max_extent();
    if (!box.empty()) {
        // Tolerances are fractions of d_max: a model of zero extent (all
        // control points equal) would never be planar within 0 and split every
        // patch to max_depth; one whose extent is below the rounding of its
        // coordinates would do the same. Both get an answer at once.
        const double magnitude =
            std::max({std::abs(box.lo.x), std::abs(box.lo.y), std::abs(box.lo.z),
                      std::abs(box.hi.x), std::abs(box.hi.y), std::abs(box.hi.z)});
        if (!(dm > 0))
            throw InputError(model.source, "surfaces",
                             "every control point is the same point (zero extent): nothing to "
                             "tessellate");
        if (!std::isfinite(dm))
            throw InputError(model.source, "surfaces",
                             "extent overflows a double (coordinates beyond the limit)");
        if (dm < 0x1p-30 * magnitude)
            throw InputError(model.source, "surfaces",
                             "extent d_max is below 2^-30 of the coordinates' magnitude: "
                             "tolerances would be below their rounding (move the model "
                             "nearer the origin)");
    }
    const int e = dm > 0 && std::isfinite(dm) ? std::ilogb(dm) : 0;
    if (e == 0) return tessellate_at_unit_scale(model, patches, options, 1);
    const auto start = std::chrono::steady_clock::now();
    Lap lap;
    const double down = std::ldexp(1.0, -e), up = std::ldexp(1.0, e);
    Model m = model;
    for (BSplineSurface& s : m.surfaces)
        for (Vec3& p : s.points) p = down * p;
    std::vector<BezierPatch> ps = patches;
    parallel_chunks(static_cast<int>(ps.size()), options.threads, [&](int begin, int end) {
        for (int i = begin; i < end; ++i)
            for (HPoint& h : ps[i].cp) h = {down * h.x, down * h.y, down * h.z, h.w};
    });
    TessellationOptions o = options;
    if (o.eps1 >= 0) o.eps1 *= down;
    if (o.eps2 >= 0) o.eps2 *= down;
    if (o.seam_tolerance >= 0) o.seam_tolerance *= down;
    o.tolerance *= down;
    const double scale_in = lap();
    // The trees' hulls, exactly up times theirs at unit scale, are written so
    // by the fans (one pass over the nodes fewer).
    Tessellation t = tessellate_at_unit_scale(m, ps, o, up);
    lap();
    parallel_chunks(t.mesh.vertex_count(), options.threads, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) t.mesh.positions[i] = up * t.mesh.positions[i];
    });
    parallel_chunks(static_cast<int>(t.subpatches.size()), options.threads,
                    [&](int begin, int end) {
                        for (int i = begin; i < end; ++i) {
                            Subpatch& sp = t.subpatches[i];
                            sp.fan_error *= up;
                            sp.error_bound *= up;
                            sp.centre = up * sp.centre;
                            for (Vec3& c : sp.corners) c = up * c;
                        }
                    });
    t.stats.d_max *= up;
    t.stats.eps1 *= up;
    t.stats.eps2 *= up;
    t.stats.seam_tolerance *= up;
    t.stats.tolerance = options.tolerance > 0 ? options.tolerance : 0.0;
    t.stats.max_error_bound *= up;
    t.stats.phases.scaling = scale_in + lap();
    t.stats.seconds = seconds_since(start);
    return t;
}

} // namespace seamless
