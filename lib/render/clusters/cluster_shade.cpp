// SPDX-License-Identifier: MIT
#include <seamless/render/clusters/cluster_shade.h>

#include <seamless/render/scene/step_clock.h>
#include <seamless/render/shading/optics.h>
#include <seamless/render/tray/ray_cluster.h>
#include <seamless/render/tray/ray_triangle.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace seamless {
namespace {

V3<Interval> v3(const IVec<3>& a) {
    return {a[0], a[1], a[2]};
}
IVec<3> ivec(const V3<Interval>& a) {
    return IVec<3>{{a.x, a.y, a.z}};
}

} // namespace

ClusterShader::ClusterShader(const ProjectedScene& ps, const Scene& scene, const TriangleScene* ts,
                             const std::vector<int>* neighbours, int levels, bool dither)
    : ps_(ps), scene_(scene), ts_(ts), neighbours_(neighbours), levels_(levels), dither_(dither),
      scene_diagonal_(next_up(norm(control_box(scene.model).extent()))),
      lighting_depth_(static_cast<size_t>(scene.max_depth) + 1) {}

// Camera-space interval vector to world space (outward rounded).
IVec<3> ClusterShader::to_world(const IVec3& c, bool point) const {
    const CameraFrame& f = ps_.frame;
    IVec<3> w;
    for (int i = 0; i < 3; ++i)
        w[i] = (point ? Interval(f.eye[i]) : Interval(0.0)) + c[0] * Interval(f.right[i]) -
               c[1] * Interval(f.up[i]) + c[2] * Interval(f.forward[i]);
    return w;
}

// Steps 3 and 4 for hits H with normals N of rays arriving in directions D on
// a surface of material mat (patch `patch`): adds the reflected and refracted
// clusters' intensities, whose hits have recursion depth `depth`, to I and
// clamps. false when a secondary cluster is undecided (split B).
bool ClusterShader::add_secondary(const IVec<3>& H, const IVec<3>& D, const IVec<3>& N,
                                  const Material& mat, int patch, int depth,
                                  std::array<Interval, 3>& I) {
    std::array<Interval, 3> more;
    if (mat.reflect > 0) {
        V3<Interval> R;
        if (!reflect_direction(v3(D), v3(N), R) ||
            !secondary_cluster(H, ivec(R), patch, depth, more))
            return false;
        for (int c = 0; c < 3; ++c) I[c] += Interval(mat.reflect) * more[c];
    }
    if (mat.transmit > 0) {
        V3<Interval> T;
        if (!refract_direction(v3(D), v3(N), mat.ior, T) ||
            !secondary_cluster(H, ivec(T), patch, depth, more))
            return false;
        for (int c = 0; c < 3; ++c) I[c] += Interval(mat.transmit) * more[c];
    }
    for (int c = 0; c < 3; ++c) I[c] = clamp01(I[c]);
    return true;
}

// SHADE for a cluster of secondary rays from the box `origin` in the
// directions `dir`, leaving patch `skip_patch`, whose hits have recursion
// depth `depth` (section 7, steps 3.2-3.5 and 4). Step 3.3: when the
// cluster certainly meets no triangle, it sees the background. Step 3.4,
// for a nearest q-connected set of one triangle: when one triangle
// certainly meets every ray and no other triangle may be met before it,
// SHADE recurses on the hull of the meeting points with the interpolated
// corner normals (lights by step 2, seen from the rays' origins; its own
// reflection and refraction while depth < max_depth). Otherwise false:
// B is split (step 3.5).
bool ClusterShader::secondary_cluster(const IVec<3>& origin, const IVec<3>& dir, int skip_patch,
                                      int depth, std::array<Interval, 3>& out) {
    const double dmin = sqrt(sqr(dir[0]) + sqr(dir[1]) + sqr(dir[2])).lo();
    if (!(dmin > 0)) return false;
    RayCluster rc;
    rc.origin = origin;
    rc.direction = dir;
    // q up to diag / |dir| carries every ray across the whole scene.
    rc.q = Interval(0.0, next_up(next_up(scene_diagonal_ / dmin) * 1.001));
    const Covering cover = covering_triangle(rc, dmin, skip_patch);
    if (cover.candidates == 0) { // step 3.3
        const Vec3 bg = scene_.background;
        for (int c = 0; c < 3; ++c) out[c] = Interval(bg[c]);
        return true;
    }
    if (cover.triangle < 0 || other_before(rc, cover, skip_patch)) return false;
    return shade_covered(rc, cover, depth, out);
}

// Step 3.4's candidate: the nearest triangle certainly met by every ray of rc
// (q beyond twice the rays' start offset), and how many triangles may be met.
ClusterShader::Covering ClusterShader::covering_triangle(const RayCluster& rc, double dmin,
                                                         int skip_patch) const {
    const IVec<3>& origin = rc.origin;
    const IVec<3>& dir = rc.direction;
    const ClusterHull ch(rc);
    // The middle ray (midpoint origin and direction): a covering triangle
    // meets it at q > 2 ray_epsilon / dmin > 0, inside the triangle's box.
    const TriangleRay middle(Vec3{origin[0].mid(), origin[1].mid(), origin[2].mid()},
                             Vec3{dir[0].mid(), dir[1].mid(), dir[2].mid()});
    const auto& M = ts_->tess.mesh;
    int cover = -1, candidates = 0;
    Interval cq, cb, cd;
    visit_flat_candidates(
        ts_->flat_trees, [&](const Box3& b) { return ch.may_meet(b); },
        [&](int t) {
            if (ts_->triangle_patch[t] == skip_patch) return;
            const auto& tri = M.triangles[t];
            const Vec3 T1 = M.positions[tri[0]], T2 = M.positions[tri[1]], T3 = M.positions[tri[2]];
            // Once some triangle may be met (not step 3.3), only a covering
            // one matters: the middle ray's test refutes most at once.
            if (candidates > 0) {
                Box3 tb;
                for (const Vec3& v : {T1, T2, T3}) tb.extend(v);
                if (!ray_hits_box(middle, tb, std::numeric_limits<double>::infinity()) ||
                    !may_cover_triangle(rc, T1, T2, T3))
                    return;
            }
            Interval q, beta, delta;
            const TriangleMeeting m = meet_triangle(rc, T1, T2, T3, q, &beta, &delta);
            if (m == TriangleMeeting::miss) return;
            ++candidates;
            if (m == TriangleMeeting::covers && q.lo() * dmin > 2 * ts_->ray_epsilon &&
                (cover < 0 || q.hi() < cq.lo())) {
                cover = t;
                cq = q;
                cb = beta;
                cd = delta;
            }
        });
    return {cover, candidates, cq, cb, cd};
}

// Whether a triangle other than the covering one may be met before it (the
// covering triangle is then not the nearest q-connected set).
bool ClusterShader::other_before(const RayCluster& rc, const Covering& c, int skip_patch) const {
    const auto& M = ts_->tess.mesh;
    const int cover = c.triangle;
    RayCluster before = rc;
    before.q = Interval(0.0, c.q.hi());
    const ClusterHull chb(before);
    bool other = false;
    visit_flat_candidates(
        ts_->flat_trees, [&](const Box3& b) { return !other && chb.may_meet(b); },
        [&](int t) {
            if (other || t == cover || ts_->triangle_patch[t] == skip_patch) return;
            const auto& tri = M.triangles[t];
            other = may_hit_triangle(before, M.positions[tri[0]], M.positions[tri[1]],
                                     M.positions[tri[2]]);
        });
    return other;
}

// Step 3.4: SHADE over the hull of the meeting points of rc's rays with the
// covering triangle c, at recursion depth `depth`; false when a light is
// undecided there, or the hit's own secondary clusters are.
bool ClusterShader::shade_covered(const RayCluster& rc, const Covering& c, int depth,
                                  std::array<Interval, 3>& out) {
    const auto& M = ts_->tess.mesh;
    const IVec<3>& origin = rc.origin;
    const int cover = c.triangle;
    const Interval cb = c.beta, cd = c.delta;
    const Material& hm = scene_.materials[ts_->triangle_material[cover]];
    const int hit_patch = ts_->triangle_patch[cover];
    // The meeting points and the interpolated normals over (beta, delta).
    const auto& tri = M.triangles[cover];
    const Interval w[3] = {Interval(1.0) - cb - cd, cb, cd};
    IVec<3> H, HN;
    for (int i = 0; i < 3; ++i) {
        H[i] = Interval(0.0);
        HN[i] = Interval(0.0);
        for (int v = 0; v < 3; ++v) {
            H[i] += w[v] * Interval(M.positions[tri[v]][i]);
            HN[i] += w[v] * Interval(M.corner_normals[cover][v][i]);
        }
    }
    Scene& lighting = lighting_depth_.at(depth); // sized max_depth + 1: never reallocated here
    if (!lights(H, hit_patch, hm, lighting.lights).decided) return false;
    lighting.ambient = scene_.ambient;
    const V3<Interval> HP{H[0], H[1], H[2]}, HNv{HN[0], HN[1], HN[2]},
        eye{origin[0], origin[1], origin[2]};
    out = shade<Interval>(lighting, hm, HP, HNv, eye);
    if (depth < scene_.max_depth && (hm.reflect > 0 || hm.transmit > 0)) {
        // The hit's own steps 3 and 4, from the meeting points onwards.
        IVec<3> D;
        for (int i = 0; i < 3; ++i) D[i] = H[i] - origin[i];
        if (!add_secondary(H, D, HN, hm, hit_patch, depth + 1, out)) return false;
    }
    return true;
}

// SHADE step 2 for a cluster: which lights reach every point of B. The
// cluster of rays from a light to the hull of the intersection points is
// compared with the triangles but those of the patch itself (step 1 marks
// them; Proposition 11 with remarks 1-2). A light is visible when no
// triangle may meet the cluster, blocked when one triangle certainly meets
// every ray between the light and the points (Theorem 6 iii), and
// undecided otherwise (then B is split).
ClusterLights ClusterShader::lights(const IVec<3>& Pw, int patch, const Material& mat,
                                    std::vector<Light>& visible) const {
    ClusterLights r;
    visible.clear();
    if (mat.diffuse == 0 && mat.specular == 0) return r;
    for (size_t l = 0; l < scene_.lights.size(); ++l) {
        const Light& light = scene_.lights[l];
        if (!light.on()) continue;
        RayCluster rc;
        for (int i = 0; i < 3; ++i) {
            rc.origin[i] = Interval(light.position[i]);
            rc.direction[i] = Pw[i] - Interval(light.position[i]);
        }
        rc.q = Interval(0.0, 1.0);
        // A single ray's shadow test starts ray_epsilon from the point: a
        // certain blocker must meet every ray before that.
        const Interval dist2 = sqr(rc.direction[0]) + sqr(rc.direction[1]) + sqr(rc.direction[2]);
        const double q_max = 1 - 2 * ts_->ray_epsilon / std::sqrt(std::max(dist2.lo(), 1e-300));
        const ClusterHull ch(rc);
        // A certain blocker is rare (one triangle must cover every ray), so
        // only the first kBlockerTries triangles that may meet the cluster are
        // tried, as blockers and then as seeds of a blocking surface
        // (blocking_surface.h); after that the light is undecided (split B).
        bool maybe = false, blocked = false;
        int tries = 0;
        int seeds[kBlockerTries];
        visit_flat_candidates(
            ts_->flat_trees,
            [&](const Box3& b) { return !blocked && tries < kBlockerTries && ch.may_meet(b); },
            [&](int t) {
                if (blocked || tries >= kBlockerTries || ts_->triangle_patch[t] == patch) return;
                const auto& tri = ts_->tess.mesh.triangles[t];
                const auto& V = ts_->tess.mesh.positions;
                if (!light_pyramid_may_meet(*ts_, static_cast<int>(l), light.position, Pw, t))
                    return;
                Interval q;
                const TriangleMeeting m = meet_triangle(rc, V[tri[0]], V[tri[1]], V[tri[2]], q);
                if (m == TriangleMeeting::miss) return;
                maybe = true;
                seeds[tries++] = t;
                if (m == TriangleMeeting::covers && q.lo() > 0 && q.hi() < q_max) blocked = true;
            });
        for (int k = 0; k < tries && !blocked && neighbours_; ++k) {
            blocked =
                pyramid_blocked_by_surface({light.position, Pw, q_max}, seeds[k],
                                           {ts_->tess.mesh.positions, ts_->tess.mesh.triangles,
                                            *neighbours_, ts_->triangle_patch},
                                           patch, kMaxBlockerSurface, surface_);
            r.by_surface += blocked;
        }
        if (blocked) {
            ++r.blocked;
            continue;
        }
        if (maybe) {
            r.decided = false;
            return r;
        }
        visible.push_back(light);
    }
    return r;
}

IVec<3> ClusterShader::world_hull(const Interval* c, SubpatchShape sh) const {
    IVec<3> h = IVec<3>::empty();
    for (int i = 0; i <= sh.p; ++i)
        for (int j = 0; j <= sh.q; ++j) {
            IVec3 P;
            for (int d = 0; d < 3; ++d) P[d] = c[sh.index(d, i, j)];
            if (sh.dim == 4) {
                const Interval w = c[sh.index(3, i, j)];
                if (!(w.lo() > 0))
                    return IVec<3>{{Interval::entire(), Interval::entire(), Interval::entire()}};
                for (int d = 0; d < 3; ++d) P[d] = P[d] / w;
            }
            const IVec<3> W = to_world(P, true);
            for (int d = 0; d < 3; ++d) h[d] = hull(h[d], W[d]);
        }
    return h;
}

ClusterShading ClusterShader::enclose_intensity(int patch, const PatchEnclosure& e,
                                                const IVec<3>& world, RenderStats& st) {
    ClusterShading r;
    const ProjectedPatch& pp = ps_.patches[patch];
    const Material& mat = ps_.lighting.materials[pp.material];
    // The points in world coordinates: the rotated camera box, cut down to
    // the caller's world enclosure (both enclose every point).
    IVec<3> Pw = to_world(e.point, true);
    for (int i = 0; i < 3; ++i) {
        const Interval x = intersect(Pw[i], world[i]);
        if (!x.is_empty()) Pw[i] = x;
    }
    // With secondary rays, only the lights that reach B count (step 2), and
    // mirrors and glass add their reflected and refracted clusters (steps 3, 4).
    if (ts_) {
        const ClusterLights cl = lights(Pw, patch, mat, lighting_.lights);
        st.lights_blocked_by_surface += cl.by_surface;
        if (!cl.decided) return r;
        r.shadowed = cl.blocked > 0;
        for (Light& l : lighting_.lights) l.position = ps_.frame.to_camera(l.position);
    }
    // Step 8: SHADE over the hulls of the intersection points and normals.
    const V3<Interval> P = v3(e.point), N = v3(e.normal);
    lighting_.ambient = ps_.lighting.ambient;
    r.lighting = ts_ ? &lighting_ : &ps_.lighting;
    r.e = e;
    r.I = shade<Interval>(*r.lighting, mat, P, N, Vec3{});
    r.secondary = ts_ && (mat.reflect > 0 || mat.transmit > 0) && scene_.max_depth > 0;
    if (r.secondary) {
        // The secondary terms only add to the local ones: if those alone
        // span too many levels, split before tracing any cluster.
        for (int c = 0; c < 3; ++c)
            if (quantise(r.I[c].hi(), levels_) - quantise(r.I[c].lo(), levels_) > (dither_ ? 1 : 0))
                return r;
        const StepClock clock(st.secondary_seconds);
        const IVec<3> Nw = to_world(e.normal, false);
        IVec<3> D;
        for (int i = 0; i < 3; ++i) D[i] = Pw[i] - Interval(ps_.frame.eye[i]);
        if (!add_secondary(Pw, D, Nw, mat, patch, 1, r.I)) return r;
    }
    r.decided = true;
    return r;
}

} // namespace seamless
