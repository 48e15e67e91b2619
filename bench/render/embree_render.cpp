// SPDX-License-Identifier: MIT
// What a user would pick instead of TRAY: the triangles of the library's
// crack-free tessellation (the same as TRAY's) traced with Embree 3, one
// primary ray per pixel centre and one shadow ray per light, shaded with the
// same shade<double>() and interpolated exact corner normals as TRAY. No
// reflected or refracted rays (the paper's scenes' mirrors and glass show
// their local shading only). Benchmark only: nothing in seamless uses it.
//
//   bench_render_embree SCENE [--size WxH] [--levels L] [--threads N] [-o OUT.png]
// prints one JSON line: seconds (precalculation included), precalc_seconds.
#include <seamless/base/error.h>
#include <seamless/base/parallel/huge_pages.h>
#include <seamless/render/scene/camera.h>
#include <seamless/render/scene/image.h>
#include <seamless/render/scene/render_loop.h>
#include <seamless/render/scene/scene.h>
#include <seamless/render/shading/shading.h>
#include <seamless/render/tray/trace.h>

#include <embree3/rtcore.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace seamless;

namespace {

// Shadow rays ignore the triangles of the patch they leave (SHADE step 1, as TRAY).
struct ShadowContext {
    RTCIntersectContext context;
    const int* triangle_patch;
    int skip_patch;
};

void skip_own_patch(const RTCFilterFunctionNArguments* args) {
    const auto* c = reinterpret_cast<const ShadowContext*>(args->context);
    const unsigned prim = RTCHitN_primID(args->hit, args->N, 0);
    if (c->triangle_patch[prim] == c->skip_patch) args->valid[0] = 0;
}

int usage(const char* argv0, int status) {
    std::fprintf(status ? stderr : stdout,
                 "usage: %s SCENE [--size WxH] [--levels L] [--threads N] [-o OUT.png]\n"
                 "Traces SCENE's tessellation with Embree 3, one primary ray per pixel and one\n"
                 "shadow ray per light (TRAY's shading, no secondary rays); prints JSON timings.\n",
                 argv0);
    return status;
}

int run(int argc, char** argv) {
    if (argc < 2) return usage(argv[0], 2);
    for (int i = 1; i < argc; ++i)
        if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h")
            return usage(argv[0], 0);
    keep_freed_memory(); // as `seamless render` does (huge_pages.h)
    const Scene scene = load_scene(argv[1]);
    int W = scene.camera.width, H = scene.camera.height, L = scene.levels, threads = 0;
    std::string out;
    for (int i = 2; i < argc; i += 2) {
        const std::string a = argv[i];
        if (i + 1 >= argc) {
            std::fprintf(stderr, "%s: option %s needs a value\n", argv[0], a.c_str());
            return 2;
        }
        bool ok = true;
        if (a == "--size")
            ok = std::sscanf(argv[i + 1], "%dx%d", &W, &H) == 2 && W > 0 && H > 0;
        else if (a == "--levels")
            ok = (L = std::atoi(argv[i + 1])) >= 2;
        else if (a == "--threads")
            ok = (threads = std::atoi(argv[i + 1])) >= 0;
        else if (a == "-o")
            out = argv[i + 1];
        else
            return usage(argv[0], 2);
        if (!ok) {
            std::fprintf(stderr, "%s: bad value '%s' for %s\n", argv[0], argv[i + 1], a.c_str());
            return 2;
        }
    }
    const auto t0 = std::chrono::steady_clock::now();
    Camera cam = scene.camera;
    cam.width = W;
    cam.height = H;
    const CameraFrame frame(cam);
    const TriangleScene ts = build_triangle_scene(scene, threads);
    const TriangleMesh& mesh = ts.tess.mesh;

    RTCDevice device =
        rtcNewDevice(threads > 0 ? ("threads=" + std::to_string(threads)).c_str() : nullptr);
    RTCScene rs = rtcNewScene(device);
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.positions.size()));
    for (size_t k = 0; k < mesh.positions.size(); ++k)
        for (int c = 0; c < 3; ++c) v[3 * k + c] = static_cast<float>(mesh.positions[k][c]);
    auto* idx = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                mesh.triangles.size()));
    for (size_t f = 0; f < mesh.triangles.size(); ++f)
        for (int c = 0; c < 3; ++c) idx[3 * f + c] = static_cast<unsigned>(mesh.triangles[f][c]);
    rtcSetGeometryOccludedFilterFunction(g, skip_own_patch);
    rtcCommitGeometry(g);
    rtcAttachGeometry(rs, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(rs);
    const double precalc =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    Image image(W, H, L);
    for_each_item(H, threads, [&](int y) {
        Scene lighting; // per row: the lights that reach the hit point
        for (int x = 0; x < W; ++x) {
            const Vec3 d = frame.ray_direction(frame.screen_a(x + 0.5), frame.screen_b(y + 0.5));
            RTCIntersectContext ctx;
            rtcInitIntersectContext(&ctx);
            RTCRayHit rh{};
            rh.ray.org_x = static_cast<float>(frame.eye.x);
            rh.ray.org_y = static_cast<float>(frame.eye.y);
            rh.ray.org_z = static_cast<float>(frame.eye.z);
            rh.ray.dir_x = static_cast<float>(d.x);
            rh.ray.dir_y = static_cast<float>(d.y);
            rh.ray.dir_z = static_cast<float>(d.z);
            rh.ray.tnear = 0;
            rh.ray.tfar = std::numeric_limits<float>::infinity();
            rh.ray.mask = ~0u;
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(rs, &ctx, &rh);
            std::array<double, 3> I{scene.background.x, scene.background.y, scene.background.z};
            const bool hit = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            if (hit) {
                const int f = static_cast<int>(rh.hit.primID);
                const auto& tri = mesh.triangles[f];
                const auto& cn = mesh.corner_normals[f];
                const double u = rh.hit.u, w = rh.hit.v, b0 = 1 - u - w;
                const Vec3 P = b0 * mesh.positions[tri[0]] + u * mesh.positions[tri[1]] +
                               w * mesh.positions[tri[2]];
                Vec3 N = b0 * cn[0] + u * cn[1] + w * cn[2];
                if (!(dot(N, N) > 0))
                    N = cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                              mesh.positions[tri[2]] - mesh.positions[tri[0]]);
                N = normalize(N);
                const Vec3 view = -normalize(d);
                const Vec3 Nf = dot(N, view) < 0 ? -N : N;
                const Material& m = scene.materials[ts.triangle_material[f]];
                lights_reaching(scene, m, P, Nf, lighting, [&](Vec3 dir, double dist) {
                    ShadowContext sc;
                    rtcInitIntersectContext(&sc.context);
                    sc.triangle_patch = ts.triangle_patch.data();
                    sc.skip_patch = ts.triangle_patch[f];
                    RTCRay r{};
                    r.org_x = static_cast<float>(P.x);
                    r.org_y = static_cast<float>(P.y);
                    r.org_z = static_cast<float>(P.z);
                    r.dir_x = static_cast<float>(dir.x);
                    r.dir_y = static_cast<float>(dir.y);
                    r.dir_z = static_cast<float>(dir.z);
                    r.tnear = static_cast<float>(ts.ray_epsilon);
                    r.tfar = static_cast<float>(dist);
                    r.mask = ~0u;
                    rtcOccluded1(rs, &sc.context, &r);
                    return r.tfar < 0; // Embree sets tfar to -inf when occluded
                });
                I = shade<double>(lighting, m, to_v3(P), to_v3(N), P + view);
                for (double& c : I) c = clamp01(c);
            }
            for (int c = 0; c < 3; ++c)
                image.at(x, y, c) = static_cast<std::uint16_t>(quantise(I[c], L));
            image.surface_at(x, y) = hit;
        }
    });
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rtcReleaseScene(rs);
    rtcReleaseDevice(device);
    if (!out.empty()) write_png(out, image);
    std::printf("{\"method\": \"embree\", \"seconds\": %.6f, \"precalc_seconds\": %.6f, "
                "\"triangles\": %d}\n",
                seconds, precalc, mesh.triangle_count());
    return 0;
}
} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const InputError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 2;
    }
}
