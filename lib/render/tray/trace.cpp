// SPDX-License-Identifier: MIT
#include <seamless/render/tray/trace.h>

#include <seamless/base/check.h>

#include <seamless/render/shading/optics.h>
#include <seamless/render/shading/shading.h>
#include <seamless/render/tray/ray_triangle.h>

#include <algorithm>
#include <limits>

namespace seamless {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Proposition 11, remark 2 for one ray in the tree of patch r: descends into
// the nodes whose triangle hull the ray meets before t_max (which the visitor
// may shrink); visit(triangle) returns true to stop.
template <class Visit>
bool visit_tree(const TriangleScene& ts, int r, const TriangleRay& ray, const double& t_max,
                Visit&& visit) {
    return visit_flat_tree(
        ts.flat_trees, r, [&](const Box3& b) { return ray_hits_box(ray, b, t_max); }, visit);
}

// The patches (leaves of the root hierarchy, root_hierarchy.h) but the
// marked one whose triangle hull the ray may meet before t_max, in the
// hierarchy's order: meet(patch) returns true to stop.
template <class Meet>
bool visit_roots_met(const RootHierarchy& h, const TriangleRay& ray, const double& t_max,
                     int skip_patch, Meet&& meet) {
    return visit_roots(
        h, skip_patch, [&](const Box3& b) { return ray_hits_box(ray, b, t_max); }, meet);
}

// Every tree but the marked patch's, in root order, so that ties in
// nearest_hit keep the first triangle of that order: the hierarchy only
// culls (the patches it leaves out are those whose root hull the ray misses
// before the initial t_max, which visit_tree would skip too), so the trees
// visited and their order are those of the plain loop over the roots.
// visit_triangles' roots met by a ray, per thread, through one call whose
// result the caller keeps (as shade_scratch below: a thread_local's address
// is otherwise recomputed, a __tls_get_addr call each time).
[[gnu::noinline]] std::vector<int>& met_roots() {
    thread_local std::vector<int> met;
    return met;
}

template <class Visit>
bool visit_triangles(const TriangleScene& ts, const TriangleRay& ray, const double& t_max,
                     int skip_patch, Visit&& visit) {
    const PatchTrees& trees = ts.tess.trees;
    if (ts.root_hierarchy.nodes.empty()) {
        const int roots = static_cast<int>(trees.roots.size());
        for (int r = 0; r < roots; ++r)
            if (r != skip_patch && visit_tree(ts, r, ray, t_max, visit)) return true;
        return false;
    }
    std::vector<int>& met = met_roots(); // grows once per thread, then reused
    met.clear();
    visit_roots_met(ts.root_hierarchy, ray, t_max, skip_patch, [&](int r) {
        met.push_back(r);
        return false;
    });
    std::sort(met.begin(), met.end());
    for (int r : met)
        if (visit_tree(ts, r, ray, t_max, visit)) return true;
    return false;
}

// The same trees in the hierarchy's order: for any_hit, whose answer does not
// depend on the order.
template <class Visit>
bool visit_triangles_any_order(const TriangleScene& ts, const TriangleRay& ray, const double& t_max,
                               int skip_patch, Visit&& visit) {
    if (ts.root_hierarchy.nodes.empty()) return visit_triangles(ts, ray, t_max, skip_patch, visit);
    return visit_roots_met(ts.root_hierarchy, ray, t_max, skip_patch,
                           [&](int r) { return visit_tree(ts, r, ray, t_max, visit); });
}

// Shadow ray, reflected or refracted ray from P (step 3.2): the intensity of
// what it meets, or the background.
std::array<double, 3> trace_secondary(const Scene& scene, const TriangleScene& ts, Vec3 P, Vec3 dir,
                                      int patch, int depth, long long* tests) {
    TraceHit h;
    if (!nearest_hit(ts, {P, dir, ts.ray_epsilon, kInf, patch}, h, tests))
        return {scene.background.x, scene.background.y, scene.background.z};
    return shade_ray(scene, ts, {h.point, h.normal, h.material, h.patch, -dir}, depth, tests);
}

} // namespace

bool needs_secondary_rays(const Scene& scene) {
    bool light_on = false;
    for (const Light& l : scene.lights) light_on |= l.on();
    std::vector<char> used(scene.materials.size(), 0);
    for (int m : scene.surface_material) used[m] = 1;
    for (size_t m = 0; m < scene.materials.size(); ++m) {
        if (!used[m]) continue;
        const Material& mat = scene.materials[m];
        if (mat.reflect > 0 || mat.transmit > 0) return true;
        if (light_on && (mat.diffuse > 0 || mat.specular > 0)) return true;
    }
    return false;
}

TriangleScene build_triangle_scene(const Scene& scene, int threads) {
    // A B-rep's faces are tessellated from their loops, not from patches.
    return build_triangle_scene(
        scene, scene.model.brep.empty() ? bezier_patches(scene.model) : std::vector<BezierPatch>{},
        threads);
}

TriangleScene build_triangle_scene(const Scene& scene, const std::vector<BezierPatch>& patches,
                                   int threads) {
    TriangleScene ts;
    // The renderers shade with the surfaces' own normals (INTRACY on the
    // patches, TRAY on the triangles' corner normals): keep every surface's side.
    TessellationOptions to;
    to.orient_surfaces = false;
    // Nothing here reads the certified bound of the triangles (error_bound.h).
    to.certify = false;
    to.threads = threads;
    ts.tess = scene.model.brep.empty() ? tessellate(scene.model, patches, to)
                                       : tessellate(scene.model, to); // trimmed faces
    const TriangleMesh& mesh = ts.tess.mesh;
    const int F = mesh.triangle_count();
    ts.triangle_material.resize(F);
    for (int f = 0; f < F; ++f)
        ts.triangle_material[f] = scene.surface_material[mesh.triangle_surface[f]];
    ts.triangle_patch.assign(F, -1);
    for (const Subpatch& sp : ts.tess.subpatches)
        for (int f = sp.first_triangle; f < sp.first_triangle + sp.triangle_count; ++f)
            ts.triangle_patch[f] = sp.patch;
    ts.root_hierarchy = build_root_hierarchy(ts.tess.trees);
    ts.flat_trees = flatten_patch_trees(ts.tess.trees);
    ts.ray_epsilon = 1e-6 * ts.tess.stats.d_max;
    return ts;
}

void add_light_planes(const Scene& scene, TriangleScene& ts) {
    ts.light_planes.reset(scene.lights.size(), static_cast<size_t>(ts.tess.mesh.triangle_count()));
}

bool light_pyramid_may_meet(const TriangleScene& ts, int l, Vec3 apex, const IVec<3>& ends, int f) {
    const TriangleMesh& mesh = ts.tess.mesh;
    const auto& tri = mesh.triangles[f];
    if (!ts.light_planes.empty()) {
        ApexTriangle scratch;
        const ApexTriangle& p = ts.light_planes.get(
            static_cast<size_t>(l), static_cast<size_t>(f), apex, mesh.positions[tri[0]],
            mesh.positions[tri[1]], mesh.positions[tri[2]], scratch);
        SEAMLESS_DCHECK(p.apex == apex, "light l's planes are formed from its position");
        return pyramid_may_meet_triangle(p, ends);
    }
    return pyramid_may_meet_triangle(apex, ends, mesh.positions[tri[0]], mesh.positions[tri[1]],
                                     mesh.positions[tri[2]]);
}

bool nearest_hit(const TriangleScene& ts, const TraceRay& r, TraceHit& hit, long long* tests) {
    const Vec3 origin = r.origin, dir = r.dir;
    const double t_min = r.t_min, t_max = r.t_max;
    const int skip_patch = r.skip_patch;
    const TriangleMesh& mesh = ts.tess.mesh;
    const TriangleRay ray(origin, dir);
    double best_t = t_max;
    int best = -1;
    RayTriangleHit best_hit, h;
    long long n = 0;
    visit_triangles(ts, ray, best_t, skip_patch, [&](int f) {
        ++n;
        const auto& tri = mesh.triangles[f];
        if (intersect_triangle(ray, mesh.positions[tri[0]], mesh.positions[tri[1]],
                               mesh.positions[tri[2]], best_t, h) &&
            h.t > t_min) {
            best_t = h.t;
            best = f;
            best_hit = h;
        }
        return false;
    });
    if (tests) *tests += n;
    if (best < 0) return false;
    const auto& tri = mesh.triangles[best];
    const auto& cn = mesh.corner_normals[best];
    const RayTriangleHit& w = best_hit;
    hit.triangle = best;
    hit.t = w.t;
    hit.point = w.b0 * mesh.positions[tri[0]] + w.b1 * mesh.positions[tri[1]] +
                w.b2 * mesh.positions[tri[2]];
    Vec3 N = w.b0 * cn[0] + w.b1 * cn[1] + w.b2 * cn[2];
    // Corner normals that cancel (never seen, but possible): the facet's own.
    if (!(dot(N, N) > 0))
        N = cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                  mesh.positions[tri[2]] - mesh.positions[tri[0]]);
    hit.normal = normalize(N);
    hit.material = ts.triangle_material[best];
    hit.patch = ts.triangle_patch[best];
    return true;
}

bool any_hit(const TriangleScene& ts, const TraceRay& r, long long* tests, int* blocker) {
    const Vec3 origin = r.origin, dir = r.dir;
    const double t_min = r.t_min, t_max = r.t_max;
    const int skip_patch = r.skip_patch;
    const TriangleMesh& mesh = ts.tess.mesh;
    const TriangleRay ray(origin, dir);
    RayTriangleHit h;
    long long n = 0;
    int found_f = -1;
    const auto hits = [&](int f) {
        ++n;
        const auto& tri = mesh.triangles[f];
        if (!(intersect_triangle(ray, mesh.positions[tri[0]], mesh.positions[tri[1]],
                                 mesh.positions[tri[2]], t_max, h) &&
              h.t > t_min))
            return false;
        found_f = f;
        return true;
    };
    // The cached blocker is one of the triangles the traversal would test (it
    // is not on skip_patch), so testing it first changes only the order.
    const int c = blocker ? *blocker : -1;
    bool found =
        c >= 0 && c < mesh.triangle_count() && ts.triangle_patch[c] != skip_patch && hits(c);
    if (!found) found = visit_triangles_any_order(ts, ray, t_max, skip_patch, hits);
    if (tests) *tests += n;
    if (found && blocker) *blocker = found_f;
    return found;
}

namespace {

// shade_ray's per-thread scratch, one thread_local: in the shared library
// each access to a thread_local is a __tls_get_addr call (three objects
// and their guards would each be recomputed after calls).
struct ShadeScratch {
    // Step 2: the lights that reach P (lights_reaching), so the hot loop
    // does not allocate; done with before the recursion reuses it.
    Scene lighting;
    // Shadow cache: per recursion depth and light, the triangle that last
    // blocked a shadow ray (neighbouring pixels are mostly shadowed by the
    // same one; per depth, as a pixel's primary and reflected or refracted
    // hits lie far apart and would evict each other's). Not when ray tests
    // are counted (TRAY's stats): the cache's order depends on how pixels
    // are split between threads, and the counts must not.
    std::vector<int> blocker;
    const TriangleScene* blocker_scene = nullptr;
};
// The calling thread's, through one call whose result the caller keeps (the
// compiler would recompute a thread_local's address after every call it makes).
[[gnu::noinline]] ShadeScratch& shade_scratch() {
    thread_local ShadeScratch scratch;
    return scratch;
}

} // namespace

std::array<double, 3> shade_ray(const Scene& scene, const TriangleScene& ts, const ShadePoint& at,
                                int depth, long long* tests, const char* lit) {
    const Vec3 P = at.P, N = at.N, view = at.view;
    const int material = at.material, patch = at.patch;
    const Material& m = scene.materials[material];
    const double cos_v = dot(N, view);
    const Vec3 Nf = cos_v < 0 ? -N : N; // towards the viewer (surfaces have two sides)

    // Per-thread scratch (ShadeScratch), looked up once per call.
    ShadeScratch& scratch = shade_scratch();
    Scene& lighting = scratch.lighting;
    std::vector<int>& blocker = scratch.blocker;
    const TriangleScene*& blocker_scene = scratch.blocker_scene;
    int* depth_blocker = nullptr;
    if (!tests) {
        const size_t lights = scene.lights.size();
        const size_t slots = lights * (static_cast<size_t>(std::max(depth, scene.max_depth)) + 1);
        if (blocker_scene != &ts || blocker.size() < slots) {
            blocker.assign(slots, -1);
            blocker_scene = &ts;
        }
        depth_blocker = blocker.data() + static_cast<size_t>(depth) * lights;
    }
    lights_reaching(scene, m, P, Nf, lighting, [&](Vec3 dir, double dist, int light) {
        if (lit && lit[light]) return false;
        return any_hit(ts, {P, dir, ts.ray_epsilon, dist, patch}, tests,
                       depth_blocker ? depth_blocker + light : nullptr);
    });
    std::array<double, 3> I = shade<double>(lighting, m, to_v3(P), to_v3(N), P + view);

    // Steps 3-4: reflected and refracted rays, up to the maximum recursion level.
    if (depth < scene.max_depth && (m.reflect > 0 || m.transmit > 0)) {
        const V3<double> D{-view.x, -view.y, -view.z}, Nv = to_v3(N);
        if (m.reflect > 0) {
            V3<double> R;
            if (reflect_direction(D, Nv, R)) {
                const auto Ir = trace_secondary(scene, ts, P, normalize(Vec3{R.x, R.y, R.z}), patch,
                                                depth + 1, tests);
                for (int c = 0; c < 3; ++c) I[c] += m.reflect * Ir[c];
            }
        }
        if (m.transmit > 0) {
            V3<double> T;
            if (refract_direction(D, Nv, m.ior, T)) {
                const auto It = trace_secondary(scene, ts, P, normalize(Vec3{T.x, T.y, T.z}), patch,
                                                depth + 1, tests);
                for (int c = 0; c < 3; ++c) I[c] += m.transmit * It[c];
            }
        }
    }
    return {clamp01(I[0]), clamp01(I[1]), clamp01(I[2])};
}

} // namespace seamless
