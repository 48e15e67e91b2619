// SPDX-License-Identifier: MIT
// INTRACY step 1, precalculation: the scene's Bezier patches in camera
// coordinates with their power forms, and the lights in camera coordinates, so
// that primary rays pose the two-dimensional problem of Theorem 10.
#pragma once

#include <seamless/base/raw_array.h>
#include <seamless/render/scene/camera.h>
#include <seamless/render/scene/scene.h>
#include <seamless/spline/enclosure/enclosure.h>
#include <seamless/spline/enclosure/ray_patch.h>
#include <seamless/spline/enclosure/subpatch.h>

#include <cstddef>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace seamless {

struct ProjectedPatch {
    BezierPatch patch; // homogeneous control points in camera coordinates
    PatchForms forms;  // power forms of `patch` (section 4)
    IVec3 hull;        // enclosure of the whole patch, camera coordinates
    // Upper bounds on |d X_k / ds| and |d X_k / dt| over [0,1]^2, k = 0..3 (the
    // sums of the magnitudes of forms.Xs's and forms.Xt's coefficients, rounded
    // up): the mean value form of a single ray's hit depth (pixel_solve.cpp).
    double slope_s[4] = {}, slope_t[4] = {};
    SubpatchShape shape; // layout of its subpatches' coefficients (mark.h)
    int material = 0;
};

// The projected scene's patches in raw storage, each constructed by the
// worker that builds it (project_scene): a vector's resize() zeroed all of
// them on one thread first, paying every page fault there; in the workers
// those faults are shared. Constructing one zeroes its
// BezierPatch only, not its forms (power_form.h). Every one of the n is
// constructed before the set is destroyed (project_scene places them all).
class ProjectedPatches {
  public:
    ProjectedPatches() = default;
    ProjectedPatches(ProjectedPatches&& o) noexcept
        : data_(std::move(o.data_)), size_(std::exchange(o.size_, 0)) {}
    ProjectedPatches& operator=(ProjectedPatches&& o) noexcept {
        if (this != &o) {
            destroy();
            data_ = std::move(o.data_);
            size_ = std::exchange(o.size_, 0);
        }
        return *this;
    }
    ~ProjectedPatches() { destroy(); }

    // Room for n patches, none constructed; place(i) constructs patch i.
    void reset(std::size_t n) {
        destroy();
        data_.reset(n ? static_cast<ProjectedPatch*>(::operator new(n * sizeof(ProjectedPatch)))
                      : nullptr);
        size_ = n;
    }
    ProjectedPatch& place(std::size_t i) { return *new (data_.get() + i) ProjectedPatch; }

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    const ProjectedPatch& operator[](std::size_t i) const { return data_[i]; }
    const ProjectedPatch& front() const { return data_[0]; }
    const ProjectedPatch* begin() const { return data_.get(); }
    const ProjectedPatch* end() const { return data_.get() + size_; }

  private:
    void destroy() {
        for (std::size_t i = 0; i < size_; ++i) data_[i].~ProjectedPatch();
        size_ = 0;
    }
    std::unique_ptr<ProjectedPatch[], ReleaseRaw> data_;
    std::size_t size_ = 0;
};

struct ProjectedScene {
    CameraFrame frame;
    ProjectedPatches patches; // every one constructed by project_scene
    Scene lighting;           // ambient, materials and lights (in camera coordinates); no model

    explicit ProjectedScene(const Camera& c) : frame(c) {}
    // The camera-space primary ray through screen point (a, b): origin 0, direction (a, b, 1).
    static Ray primary_ray(double a, double b) { return {{0, 0, 0}, {a, b, 1}}; }
};

// Sets pp's patch to b (camera coordinates) and everything derived from it:
// forms, hull, slope bounds, subpatch shape.
void set_camera_patch(ProjectedPatch& pp, const BezierPatch& b);

// Builds the projected scene for an image of width x height pixels, its
// patches in parallel on `threads` (RenderOptions::threads; the same result
// for any count).
ProjectedScene project_scene(const Scene& scene, int width, int height, int threads = 1);
// The same from the model's Bezier patches already extracted
// (bezier_patches(scene.model), in its order).
ProjectedScene project_scene(const Scene& scene, const std::vector<BezierPatch>& patches, int width,
                             int height, int threads);

// Surface point and normal of a patch at local (s, t), in camera coordinates,
// for shading; at a pole (vanishing normal) the normal is taken slightly inside.
// at (optional): receives evaluate(b, s, t) (for the next Newton run from (s, t)).
void surface_frame(const BezierPatch& b, double s, double t, Vec3& point, Vec3& normal,
                   SurfacePoint* at = nullptr);
// The same from sp, the patch already evaluated at (s, t).
void surface_frame(const BezierPatch& b, double s, double t, const SurfacePoint& sp, Vec3& point,
                   Vec3& normal);

} // namespace seamless
