// SPDX-License-Identifier: MIT
// Measured deviation between exact surfaces and their tessellation.
#include <seamless/mesh/deviation/deviation.h>

#include <seamless/mesh/deviation/deviation_accumulator.h>
#include <seamless/mesh/deviation/mesh_distance.h>
#include <seamless/mesh/deviation/spline_projection.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace seamless {
namespace {

using Accumulator = DeviationAccumulator;

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
    const int n = std::max(2, options.patch_grid);
    std::vector<Sample> grid;
    grid.reserve(patches.size() * n * n + samples.size());
    for (int p = 0; p < static_cast<int>(patches.size()); ++p)
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                grid.push_back({p, double(i) / (n - 1), double(j) / (n - 1)});
    grid.insert(grid.end(), samples.begin(), samples.end());
    const MeshDistance to_mesh(mesh);
    if (!to_mesh.empty()) {
        const long long count = static_cast<long long>(grid.size());
        std::vector<Accumulator> acc((count + kChunk - 1) / kChunk);
        for_chunks(count, kChunk, threads, [&](long long b, long long e, long long c) {
            for (long long i = b; i < e; ++i) {
                const Sample& q = grid[i];
                const Vec3 p = evaluate(patches[q.patch], q.s, q.t).point;
                acc[c].add(to_mesh(p));
            }
        });
        out.surface_to_mesh = combine(acc);
    }

    // Mesh -> surface: barycentric samples of each triangle, on its source surface.
    const bool has_uv = mesh.corner_uvs.size() == mesh.triangles.size() &&
                        mesh.triangle_surface.size() == mesh.triangles.size();
    const std::vector<std::array<double, 3>> bary = barycentric_points(options.triangle_level);
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
                proj[c].add(std::min(
                    d_same, project_to_surface(surf, x, u, v, options.newton_iterations).distance));
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
