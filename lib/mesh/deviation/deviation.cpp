// SPDX-License-Identifier: MIT
// Measured deviation between exact surfaces and their tessellation. CGAL only
// here: an AABB tree of the triangles for the closest-point queries.
#include <seamless/mesh/deviation/deviation.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace seamless {
namespace {

using K = CGAL::Simple_cartesian<double>;
using Triangle = K::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<K, std::vector<Triangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

// Running max and sum of squares of one chunk of samples.
struct Accumulator {
    double max = 0, sum_sq = 0;
    long long count = 0;
    void add(double d) {
        max = std::max(max, d);
        sum_sq += d * d;
        ++count;
    }
};

DeviationStats combine(const std::vector<Accumulator>& chunks) {
    // Fixed chunks combined in order: the same sums whatever the thread count.
    Accumulator a;
    for (const Accumulator& c : chunks) {
        a.max = std::max(a.max, c.max);
        a.sum_sq += c.sum_sq;
        a.count += c.count;
    }
    DeviationStats s;
    s.max = a.max;
    s.samples = a.count;
    s.rms = a.count > 0 ? std::sqrt(a.sum_sq / static_cast<double>(a.count)) : 0.0;
    return s;
}

// Runs f(begin, end, chunk) over fixed chunks of [0, n) on `threads` threads.
template <class F> void for_chunks(long long n, long long chunk, int threads, F&& f) {
    const long long chunks = (n + chunk - 1) / chunk;
    threads = static_cast<int>(std::min<long long>(threads, chunks));
    auto work = [&](int id) {
        for (long long c = id; c < chunks; c += threads)
            f(c * chunk, std::min(n, (c + 1) * chunk), c);
    };
    if (threads <= 1 || chunks <= 1) {
        work(0);
        return;
    }
    std::vector<std::thread> pool;
    for (int id = 1; id < threads; ++id) pool.emplace_back(work, id);
    work(0);
    for (std::thread& th : pool) th.join();
}

// Local minimum of |S(u,v) - x| over the surface's domain by damped
// Gauss-Newton from (u, v), clamped to the domain; returns the smallest
// distance reached.
double project(const BSplineSurface& b, Vec3 x, double u, double v, int iterations) {
    const double u0 = b.u_min(), u1 = b.u_max(), v0 = b.v_min(), v1 = b.v_max();
    double s = std::clamp(u, u0, u1), t = std::clamp(v, v0, v1);
    SurfacePoint sp = evaluate(b, s, t);
    double best = distance(sp.point, x);
    for (int it = 0; it < iterations && best > 0; ++it) {
        const Vec3 r = sp.point - x;
        // Levenberg regularisation keeps the step finite at poles and folds.
        const double reg = 1e-12 * (dot(sp.du, sp.du) + dot(sp.dv, sp.dv));
        const double a11 = dot(sp.du, sp.du) + reg, a22 = dot(sp.dv, sp.dv) + reg;
        const double a12 = dot(sp.du, sp.dv);
        const double g1 = dot(sp.du, r), g2 = dot(sp.dv, r);
        const double det = a11 * a22 - a12 * a12;
        if (!(det > 0)) break;
        double ds = -(a22 * g1 - a12 * g2) / det, dt = -(a11 * g2 - a12 * g1) / det;
        bool improved = false;
        for (int halving = 0; halving < 6 && !improved; ++halving) {
            const double ns = std::clamp(s + ds, u0, u1), nt = std::clamp(t + dt, v0, v1);
            const SurfacePoint np = evaluate(b, ns, nt);
            const double d = distance(np.point, x);
            if (d < best) {
                improved = true;
                best = d;
                s = ns;
                t = nt;
                sp = np;
            }
            ds *= 0.5;
            dt *= 0.5;
        }
        if (!improved || std::max(std::abs(ds) / (u1 - u0), std::abs(dt) / (v1 - v0)) < 1e-15)
            break;
    }
    return best;
}

struct Sample {
    int patch = 0;
    double s = 0, t = 0;
};

int thread_count(int requested) {
    if (requested > 0) return requested;
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

} // namespace

double Deviation::max() const {
    return std::max(surface_to_mesh.max, mesh_to_surface.max);
}

namespace {

Deviation measure(const Model& model, const std::vector<BezierPatch>& patches,
                  const TriangleMesh& mesh, std::vector<Sample> samples,
                  const DeviationOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const int threads = thread_count(options.threads);
    constexpr long long kChunk = 4096;
    Deviation out;

    // Surface -> mesh: exact sample points, then closest points on the triangles.
    std::vector<Triangle> triangles;
    triangles.reserve(mesh.triangles.size());
    for (const auto& f : mesh.triangles) {
        if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) continue;
        const Vec3 a = mesh.positions[f[0]], b = mesh.positions[f[1]], c = mesh.positions[f[2]];
        triangles.emplace_back(K::Point_3(a.x, a.y, a.z), K::Point_3(b.x, b.y, b.z),
                               K::Point_3(c.x, c.y, c.z));
    }
    const int n = std::max(2, options.patch_grid);
    std::vector<Sample> grid;
    grid.reserve(patches.size() * n * n + samples.size());
    for (int p = 0; p < static_cast<int>(patches.size()); ++p)
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                grid.push_back({p, double(i) / (n - 1), double(j) / (n - 1)});
    grid.insert(grid.end(), samples.begin(), samples.end());
    if (!triangles.empty()) {
        Tree tree(triangles.begin(), triangles.end());
        tree.build();
        tree.accelerate_distance_queries();
        const long long count = static_cast<long long>(grid.size());
        std::vector<Accumulator> acc((count + kChunk - 1) / kChunk);
        for_chunks(count, kChunk, threads, [&](long long b, long long e, long long c) {
            for (long long i = b; i < e; ++i) {
                const Sample& q = grid[i];
                const Vec3 p = evaluate(patches[q.patch], q.s, q.t).point;
                acc[c].add(std::sqrt(tree.squared_distance(K::Point_3(p.x, p.y, p.z))));
            }
        });
        out.surface_to_mesh = combine(acc);
    }

    // Mesh -> surface: barycentric samples of each triangle, on its source surface.
    const bool has_uv = mesh.corner_uvs.size() == mesh.triangles.size() &&
                        mesh.triangle_surface.size() == mesh.triangles.size();
    std::vector<std::array<double, 3>> bary;
    const int level = std::max(1, options.triangle_level);
    for (int i = 0; i <= level; ++i)
        for (int j = 0; i + j <= level; ++j)
            bary.push_back({double(i) / level, double(j) / level, double(level - i - j) / level});
    if (level % 3 != 0) bary.push_back({1.0 / 3, 1.0 / 3, 1.0 / 3});
    const long long count = has_uv ? mesh.triangle_count() : 0;
    const size_t chunks = static_cast<size_t>((count + kChunk - 1) / kChunk);
    std::vector<Accumulator> proj(chunks), same(chunks);
    for_chunks(count, kChunk, threads, [&](long long b, long long e, long long c) {
        for (long long f = b; f < e; ++f) {
            const int si = mesh.triangle_surface[f];
            if (si < 0 || si >= static_cast<int>(model.surfaces.size())) continue;
            const BSplineSurface& surf = model.surfaces[si];
            const auto& tri = mesh.triangles[f];
            if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
            const auto& uv = mesh.corner_uvs[f];
            for (const auto& w : bary) {
                Vec3 x{};
                double u = 0, v = 0;
                for (int m = 0; m < 3; ++m) {
                    x += w[m] * mesh.positions[tri[m]];
                    u += w[m] * uv[m][0];
                    v += w[m] * uv[m][1];
                }
                const double d_same = distance(evaluate(surf, u, v).point, x);
                same[c].add(d_same);
                proj[c].add(std::min(d_same, project(surf, x, u, v, options.newton_iterations)));
            }
        }
    });
    out.mesh_to_surface = combine(proj);
    out.mesh_same_parameter = combine(same);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace

Deviation measure_deviation(const Model& model, const TriangleMesh& mesh,
                            const DeviationOptions& options) {
    return measure(model, bezier_patches(model), mesh, {}, options);
}

Deviation measure_deviation(const Model& model, const Tessellation& t,
                            const DeviationOptions& options) {
    std::vector<Sample> samples;
    const int k = std::max(0, options.subpatch_grid);
    for (const Subpatch& sp : t.subpatches) {
        const double s0 = param_of(sp.rect.s0), s1 = param_of(sp.rect.s1);
        const double t0 = param_of(sp.rect.t0), t1 = param_of(sp.rect.t1);
        for (int i = 0; i < k; ++i)
            for (int j = 0; j < k; ++j)
                samples.push_back(
                    {sp.patch, s0 + (i + 0.5) / k * (s1 - s0), t0 + (j + 0.5) / k * (t1 - t0)});
    }
    return measure(model, bezier_patches(model), t.mesh, std::move(samples), options);
}

} // namespace seamless
