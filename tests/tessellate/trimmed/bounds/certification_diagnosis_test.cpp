// SPDX-License-Identifier: MIT
// By hand: SEAMLESS_DIAGNOSE=model.stp test_tessellate "[.diagnose]" prints
// the triangles with the largest certified bounds (triangle_bound.h) beside
// their sampled parametric distance |S(x) - L(x)|.
#include <tessellate/trimmed/bounds/bound_cases.h>
#include <tessellate/trimmed/brep_cases.h>

#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>
#include <seamless/tessellate/trimmed/bounds/triangle_bound.h>
#include <seamless/tessellate/trimmed/face_surface.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace seamless;

TEST_CASE("trimmed faces: the largest certified triangle bounds of a model", "[.diagnose]") {
    const char* file = std::getenv("SEAMLESS_DIAGNOSE");
    if (!file) return;
    // A hard case by name (brep_cases.h), or a model file.
    Model model;
    for (const test::BRepCase& c : test::all_brep_cases())
        if (c.name == file) model = c.model;
    if (model.brep.faces.empty()) model = load_model(file);
    TessellationOptions o;
    const Tessellation t = tessellate(model, o);
    const TriangleMesh& m = t.mesh;
    struct Row {
        double bound, sampled;
        int tri;
    };
    std::vector<Row> rows;
    for (int f = 0; f < m.triangle_count(); ++f) {
        const FaceSurface face(model.surfaces[m.triangle_surface[f]]);
        const test::MeshTriangleBound t = test::mesh_triangle_bound(model, m, f);
        const std::array<UV, 3>& uv = t.uv;
        const std::array<Vec3, 3>& Q = t.Q;
        double sampled = 0;
        for (int a = 0; a <= 8; ++a)
            for (int b = 0; a + b <= 8; ++b) {
                const double l1 = a / 8.0, l2 = b / 8.0, l0 = 1 - l1 - l2;
                const Vec3 x{l0 * uv[0][0] + l1 * uv[1][0] + l2 * uv[2][0],
                             l0 * uv[0][1] + l1 * uv[1][1] + l2 * uv[2][1], 0};
                sampled = std::max(sampled,
                                   distance(face.at(x).point, l0 * Q[0] + l1 * Q[1] + l2 * Q[2]));
            }
        rows.push_back({t.bound, sampled, f});
    }
    std::sort(rows.begin(), rows.end(),
              [](const Row& a, const Row& b) { return a.bound > b.bound; });
    if (std::getenv("SEAMLESS_DIAGNOSE_SURFACES"))
        for (const BSplineSurface& s : model.surfaces) {
            int tris = 0;
            for (int f = 0; f < m.triangle_count(); ++f)
                tris += &model.surfaces[m.triangle_surface[f]] == &s;
            std::printf("surface deg %d,%d knots %zu,%zu %s triangles %d\n", s.degree_u, s.degree_v,
                        s.knots_u.size(), s.knots_v.size(),
                        s.rational() ? "rational" : "polynomial", tris);
        }
    if (const char* sv = std::getenv("SEAMLESS_DIAGNOSE_SURFACE"))
        for (int f = 0; f < m.triangle_count(); ++f)
            if (m.triangle_surface[f] == std::atoi(sv)) {
                std::printf("tri");
                for (int k = 0; k < 3; ++k)
                    std::printf(" %d (%.17g, %.17g)", m.triangles[f][k], m.corner_uvs[f][k][0],
                                m.corner_uvs[f][k][1]);
                std::printf("\n");
            }
    std::printf("D %g, bound %g, sampled deviation %g\n", t.stats.tolerance,
                t.stats.max_error_bound, t.stats.brep.max_deviation);
    for (size_t r = 0; r < std::min<size_t>(rows.size(), 12); ++r) {
        const int f = rows[r].tri;
        const BSplineSurface& s = model.surfaces[m.triangle_surface[f]];
        std::printf("bound %.4g parametric %.4g surface %d deg %d,%d %s uv", rows[r].bound,
                    rows[r].sampled, m.triangle_surface[f], s.degree_u, s.degree_v,
                    s.rational() ? "rational" : "polynomial");
        for (int k = 0; k < 3; ++k)
            std::printf(" (%.6g, %.6g)", m.corner_uvs[f][k][0], m.corner_uvs[f][k][1]);
        std::printf(" domain [%g,%g]x[%g,%g]\n", s.u_min(), s.u_max(), s.v_min(), s.v_max());
    }
}

// By hand: SEAMLESS_FIGURES="a.stp:b.stp" test_tessellate "[.figures]" prints
// the certified bound beside the sampled deviation and the time of the
// certification pass (docs/results/certified_bound.md).
TEST_CASE("trimmed faces: figures of the certified bound on model files", "[.figures]") {
    const char* files = std::getenv("SEAMLESS_FIGURES");
    if (!files) return;
    std::string list = files;
    for (size_t at = 0; at < list.size();) {
        const size_t end = std::min(list.find(':', at), list.size());
        const std::string file = list.substr(at, end - at);
        at = end + 1;
        const Model model = load_model(file);
        TessellationOptions o;
        o.threads = 1;
        using clock = std::chrono::steady_clock;
        auto seconds = [&](bool certify, Tessellation& t) {
            o.certify = certify;
            double best = 1e30;
            for (int r = 0; r < 3; ++r) {
                const auto t0 = clock::now();
                t = tessellate(model, o);
                best = std::min(best, std::chrono::duration<double>(clock::now() - t0).count());
            }
            return best;
        };
        Tessellation t;
        const double plain = seconds(false, t), with = seconds(true, t);
        const auto& b = t.stats.brep;
        std::printf("| %s | %d | %.3g | %.3g | %.3g | %.3g | %.3g | %.2f | %.2f | %.1f | %.1f |\n",
                    file.substr(file.find_last_of('/') + 1).c_str(), t.stats.triangles,
                    t.stats.tolerance, t.stats.max_error_bound, b.bound_triangles, b.bound_chords,
                    b.max_deviation, t.stats.max_error_bound / b.max_deviation,
                    t.stats.max_error_bound / t.stats.tolerance, plain * 1e3, (with - plain) * 1e3);
    }
}
