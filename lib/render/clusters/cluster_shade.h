// SPDX-License-Identifier: MIT
// SHADE for a certified cluster (paper section 7, SHADE over the hulls of the
// intersection points and normals of a sub-screen B whose rays all hit one
// patch, INTRACY step 8): the local illumination over the hulls; with
// secondary rays in play (a triangle scene), step 2's lights that reach every
// point of B (Proposition 11 with remarks 1-2, Theorem 6 iii for a certain
// blocker, one triangle or a surface of them: ray_cluster.h), and steps 3-4's reflected and
// refracted clusters, recursively up to the scene's maximum depth. Every answer encloses the
// intensity of every ray of B; where a case is undecided for the cluster the answer is "split B".
#pragma once

#include <seamless/render/scene/projection.h>
#include <seamless/render/scene/render_options.h>
#include <seamless/render/scene/render_stats.h>
#include <seamless/render/shading/shading.h>
#include <seamless/render/tray/blocking_surface.h>
#include <seamless/render/tray/ray_cluster.h>
#include <seamless/render/tray/trace.h>
#include <seamless/spline/enclosure/subpatch.h>

#include <array>
#include <vector>

namespace seamless {

// The enclosure of a cluster's intensity, or none (decided = false: split B).
struct ClusterShading {
    bool decided = false;
    std::array<Interval, 3> I;
    bool secondary = false; // reflected or refracted clusters were traced
    bool shadowed = false;  // some light is certainly blocked for every ray of B
    // For step 9's second-order criterion (second_order.h): the enclosures
    // of point and derivatives over the box, and the ambient and lights that
    // reach every ray of B in camera coordinates (the shader's own scene or
    // scratch: valid until its next call).
    PatchEnclosure e;
    const Scene* lighting = nullptr;
};

// The lights that reach every point of a cluster: decided = false when some
// light may reach some points and not others.
struct ClusterLights {
    bool decided = true;
    int blocked = 0;    // lights certainly blocked for every point
    int by_surface = 0; // of those, blocked by a surface of triangles (blocking_surface.h)
};

class ClusterShader {
  public:
    // ts: null when no secondary rays are in play. levels, dither: the
    // painting rule of step 9, to stop before tracing secondary clusters
    // when the local terms alone already span too many levels.
    // neighbours: triangle_neighbours(ts->tess.mesh.triangles) (blocking_surface.h),
    // for lights blocked by a surface of triangles; null with ts null.
    ClusterShader(const ProjectedScene& ps, const Scene& scene, const TriangleScene* ts,
                  const std::vector<int>* neighbours, int levels, bool dither);

    // SHADE for every ray of B hitting patch `patch` (camera coordinates);
    // e: enclosures of the hits and the patch's derivatives there, world: of
    // the hits in world coordinates, which step 7 has already computed
    // (world_hull). Secondary clusters' CPU seconds go to st.secondary_seconds.
    ClusterShading enclose_intensity(int patch, const PatchEnclosure& e, const IVec<3>& world,
                                     RenderStats& st);

    // The hull of a subpatch's control points (c, shape sh; camera
    // coordinates) taken to world coordinates, outward rounded: the points
    // of the subpatch in world coordinates (convex hull property; an affine
    // map keeps it). Entire where a weight is not certainly positive.
    IVec<3> world_hull(const Interval* c, SubpatchShape sh) const;

    // Step 2 at the world-space hull Pw of a cluster's points on `patch`:
    // fills `visible` with the lights that reach every point.
    ClusterLights lights(const IVec<3>& Pw, int patch, const Material& mat,
                         std::vector<Light>& visible) const;

  private:
    IVec<3> to_world(const IVec3& c, bool point) const;
    bool add_secondary(const IVec<3>& H, const IVec<3>& D, const IVec<3>& N, const Material& mat,
                       int patch, int depth, std::array<Interval, 3>& I);
    bool secondary_cluster(const IVec<3>& origin, const IVec<3>& dir, int skip_patch, int depth,
                           std::array<Interval, 3>& out);
    // secondary_cluster's covering triangle (-1: none) with its meeting
    // parameters, and the count of triangles that may be met.
    struct Covering {
        int triangle = -1, candidates = 0;
        Interval q, beta, delta;
    };
    Covering covering_triangle(const RayCluster& rc, double dmin, int skip_patch) const;
    bool other_before(const RayCluster& rc, const Covering& c, int skip_patch) const;
    bool shade_covered(const RayCluster& rc, const Covering& c, int depth,
                       std::array<Interval, 3>& out);

    static constexpr int kBlockerTries = 4;         // per light and cluster (lights())
    static constexpr int kMaxBlockerSurface = 4096; // triangles of a blocking surface

    const ProjectedScene& ps_;
    const Scene& scene_;
    const TriangleScene* ts_;
    const std::vector<int>* neighbours_;
    int levels_;
    bool dither_;
    double scene_diagonal_; // bounds every segment inside the scene (convex hull property)
    Scene lighting_; // scratch: ambient and the lights that reach a cluster, camera coordinates
    // the same for secondary clusters' hits, one per depth, world coordinates
    std::vector<Scene> lighting_depth_;
    // scratch of lights(): the triangles that may meet a light's pyramid
    mutable SurfaceScratch surface_;
};

} // namespace seamless
