// SPDX-License-Identifier: MIT
// Measured deviation between exact surfaces and their tessellation. CGAL only
// here: an AABB tree of the triangles for the closest-point queries.
#include <seamless/mesh/deviation.h>

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

// Local minimum of |S(s,t) - x| over the patch domain by damped Gauss-Newton
// from (s, t), clamped to [0,1]^2; returns the smallest distance reached.
double project(const BezierPatch& b, Vec3 x, double s, double t, int iterations) {
    s = std::clamp(s, 0.0, 1.0);
    t = std::clamp(t, 0.0, 1.0);
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
            const double ns = std::clamp(s + ds, 0.0, 1.0), nt = std::clamp(t + dt, 0.0, 1.0);
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
        if (!improved || std::max(std::abs(ds), std::abs(dt)) < 1e-15) break;
    }
    return best;
}

int thread_count(int requested) {
    if (requested > 0) return requested;
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

} // namespace

double Deviation::max() const {
    return std::max({surface_to_mesh.max, mesh_to_surface.max, mesh_same_parameter.max});
}

Deviation measure_deviation(const Model& model, const Tessellation& t,
                            const DeviationOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<BezierPatch> patches = bezier_patches(model);
    const TriangleMesh& mesh = t.mesh;
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
    struct Sample {
        int patch = 0;
        double s = 0, t = 0;
    };
    std::vector<Sample> samples;
    const int n = std::max(2, options.patch_grid);
    for (int p = 0; p < static_cast<int>(patches.size()); ++p)
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                samples.push_back({p, double(i) / (n - 1), double(j) / (n - 1)});
    const int k = std::max(0, options.subpatch_grid);
    for (const Subpatch& sp : t.subpatches) {
        const double s0 = param_of(sp.rect.s0), s1 = param_of(sp.rect.s1);
        const double t0 = param_of(sp.rect.t0), t1 = param_of(sp.rect.t1);
        for (int i = 0; i < k; ++i)
            for (int j = 0; j < k; ++j)
                samples.push_back(
                    {sp.patch, s0 + (i + 0.5) / k * (s1 - s0), t0 + (j + 0.5) / k * (t1 - t0)});
    }
    if (!triangles.empty()) {
        Tree tree(triangles.begin(), triangles.end());
        tree.build();
        tree.accelerate_distance_queries();
        const long long count = static_cast<long long>(samples.size());
        std::vector<Accumulator> acc((count + kChunk - 1) / kChunk);
        for_chunks(count, kChunk, threads, [&](long long b, long long e, long long c) {
            for (long long i = b; i < e; ++i) {
                const Sample& q = samples[i];
                const Vec3 p = evaluate(patches[q.patch], q.s, q.t).point;
                acc[c].add(std::sqrt(tree.squared_distance(K::Point_3(p.x, p.y, p.z))));
            }
        });
        out.surface_to_mesh = combine(acc);
    }

    // Mesh -> surface: barycentric samples of each triangle, on its Bezier patch.
    std::vector<int> triangle_patch(mesh.triangles.size(), -1);
    for (const Subpatch& sp : t.subpatches)
        for (int f = sp.first_triangle; f < sp.first_triangle + sp.triangle_count; ++f)
            triangle_patch[f] = sp.patch;
    std::vector<std::array<double, 3>> bary;
    const int level = std::max(1, options.triangle_level);
    for (int i = 0; i <= level; ++i)
        for (int j = 0; i + j <= level; ++j)
            bary.push_back({double(i) / level, double(j) / level, double(level - i - j) / level});
    if (level % 3 != 0) bary.push_back({1.0 / 3, 1.0 / 3, 1.0 / 3});
    const long long count = mesh.triangle_count();
    const size_t chunks = static_cast<size_t>((count + kChunk - 1) / kChunk);
    std::vector<Accumulator> proj(chunks), same(chunks);
    for_chunks(count, kChunk, threads, [&](long long b, long long e, long long c) {
        for (long long f = b; f < e; ++f) {
            const int pi = triangle_patch[f];
            if (pi < 0 || mesh.corner_uvs.size() != mesh.triangles.size()) continue;
            const BezierPatch& bp = patches[pi];
            const auto& tri = mesh.triangles[f];
            const auto& uv = mesh.corner_uvs[f];
            for (const auto& w : bary) {
                Vec3 x{};
                double u = 0, v = 0;
                for (int m = 0; m < 3; ++m) {
                    x += w[m] * mesh.positions[tri[m]];
                    u += w[m] * uv[m][0];
                    v += w[m] * uv[m][1];
                }
                const double s = std::clamp((u - bp.u0) / (bp.u1 - bp.u0), 0.0, 1.0);
                const double tt = std::clamp((v - bp.v0) / (bp.v1 - bp.v0), 0.0, 1.0);
                const double d_same = distance(evaluate(bp, s, tt).point, x);
                same[c].add(d_same);
                proj[c].add(std::min(d_same, project(bp, x, s, tt, options.newton_iterations)));
            }
        }
    });
    out.mesh_to_surface = combine(proj);
    out.mesh_same_parameter = combine(same);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

std::vector<SweepRow> sweep_tolerances(const Model& model, const SweepOptions& options) {
    std::vector<SweepRow> rows;
    const double dm = d_max(model);
    const int steps = std::max(1, options.steps_per_decade);
    for (int k = 0; k <= options.decades * steps; ++k) {
        const double factor = std::pow(10.0, options.first_decade - double(k) / steps);
        if (!rows.empty()) {
            // Triangles grow like 1/eps (deviation ~ h^2): predict from the last step.
            double ratio = std::pow(10.0, 1.0 / steps);
            if (rows.size() >= 2 && rows[rows.size() - 2].tess.triangles > 0)
                ratio = std::max(ratio, double(rows.back().tess.triangles) /
                                            rows[rows.size() - 2].tess.triangles);
            if (rows.back().tess.triangles * ratio > double(options.max_triangles)) break;
        }
        TessellationOptions topt;
        topt.eps1 = factor * 0.001 * dm;
        topt.eps2 = factor * 0.02 * dm;
        const Tessellation t = tessellate(model, topt);
        SweepRow row;
        row.factor = factor;
        row.tess = t.stats;
        row.deviation = measure_deviation(model, t, options.deviation);
        rows.push_back(row);
    }
    return rows;
}

} // namespace seamless
