// SPDX-License-Identifier: MIT
// SHADE for one ray (trace.h, paper section 7) over the triangles of the
// tessellation: shadows, a mirror, refraction through a plane-parallel plate
// as Snell's law predicts, the recursion limit, lights that are off; TRAY on
// the scenes of section 8 (data/scenes): sequential == parallel, all load and render.
#include "render/render_compare.h"
#include "test_util.h"

#include <seamless/render/render.h>
#include <seamless/render/scene/camera.h>
#include <seamless/render/tray/trace.h>

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace seamless;
using nlohmann::json;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

json vec(Vec3 p) {
    return {p.x, p.y, p.z};
}

// Bilinear patch with normal (p10 - p00) x (p01 - p00), as data/scenes/generate.py's quad().
json quad(const std::string& name, Vec3 p00, Vec3 p10, Vec3 p01, Vec3 p11) {
    return {{"name", name},
            {"degree", {1, 1}},
            {"size", {2, 2}},
            {"knots_u", {0, 0, 1, 1}},
            {"knots_v", {0, 0, 1, 1}},
            {"control_points", {vec(p00), vec(p01), vec(p10), vec(p11)}}};
}

// Horizontal quad [x0,x1] x [y0,y1] at height z, normal `up` (+z) or -z.
json horizontal(const std::string& name, double x0, double x1, double y0, double y1, double z,
                bool up = true) {
    return up ? quad(name, {x0, y0, z}, {x1, y0, z}, {x0, y1, z}, {x1, y1, z})
              : quad(name, {x0, y0, z}, {x0, y1, z}, {x1, y0, z}, {x1, y1, z});
}

json material(Vec3 color, double diffuse, double specular, double reflect = 0, double transmit = 0,
              double ior = 1.5) {
    return {{"color", vec(color)}, {"diffuse", diffuse}, {"specular", specular},
            {"shininess", 20},     {"reflect", reflect}, {"transmit", transmit},
            {"ior", ior}};
}

struct ObjectSpec {
    std::string name;
    // A vector, not a json: `json{x}` of one json x is x itself under clang
    // and [x] under gcc (CWG 2137), so a braced list of one surface would be
    // written as an object by one compiler.
    std::vector<json> surfaces;
    std::string material;
};

// A scene of `objects` (one model file each) written to `dir` and loaded.
Scene make_scene(const std::filesystem::path& dir, const std::vector<ObjectSpec>& objects,
                 const json& materials, const json& lights, double ambient, Vec3 eye, Vec3 look_at,
                 int max_depth = 2) {
    json objs = json::array();
    for (const ObjectSpec& o : objects) {
        test::write_file(dir / (o.name + ".json"),
                         json{{"version", 1}, {"surfaces", json(o.surfaces)}}.dump());
        objs.push_back({{"model", o.name + ".json"}, {"material", o.material}});
    }
    const json s = {{"version", 1},
                    {"camera",
                     {{"eye", vec(eye)},
                      {"look_at", vec(look_at)},
                      {"up", {0, 0, 1}},
                      {"fov_deg", 40},
                      {"width", 64},
                      {"height", 48}}},
                    {"levels", 16},
                    {"background", {0.0, 0.0, 0.0}},
                    {"ambient", ambient},
                    {"lights", lights},
                    {"materials", materials},
                    {"objects", objs},
                    {"max_depth", max_depth}};
    test::write_file(dir / "scene.json", s.dump());
    return load_scene(dir / "scene.json");
}

json light(Vec3 p, Vec3 c = {1, 1, 1}) {
    return {{"position", vec(p)}, {"color", vec(c)}};
}

// A floor z = 0 over [-2,2]^2 and a horizontal blocker [-0.3,0.3]^2 at z = 1.
Scene shadow_scene(const std::string& tag, const json& lights) {
    return make_scene(test::scratch_dir(tag),
                      {{"floor", {horizontal("floor", -2, 2, -2, 2, 0)}, "grey"},
                       {"blocker", {horizontal("blocker", -0.3, 0.3, -0.3, 0.3, 1)}, "grey"}},
                      {{"grey", material({0.8, 0.8, 0.8}, 0.8, 0.2)}}, lights, 0.1, {0, -4, 0.5},
                      {0, 0, 0});
}

// Shades the first surface point seen along origin + t dir.
std::array<double, 3> shade_along(const Scene& scene, const TriangleScene& ts, Vec3 origin,
                                  Vec3 dir, long long* tests = nullptr) {
    TraceHit h;
    REQUIRE(nearest_hit(ts, {origin, dir, 0, kInf, -1}, h));
    return shade_ray(scene, ts, {h.point, h.normal, h.material, h.patch, -normalize(dir)}, 0,
                     tests);
}

// Pixel (column, row) of the world point p in a render of `scene` at W x H.
std::array<int, 2> pixel_of(const Scene& scene, int W, int H, Vec3 p) {
    Camera cam = scene.camera;
    cam.width = W;
    cam.height = H;
    const CameraFrame f(cam);
    const Vec3 c = f.to_camera(p);
    const double a = c.x / c.z, b = c.y / c.z;
    return {static_cast<int>(std::floor((a / (f.tan_half * f.aspect) + 1) * W / 2)),
            static_cast<int>(std::floor((b / f.tan_half + 1) * H / 2))};
}

int brightness(const Image& im, std::array<int, 2> px) {
    return im.at(px[0], px[1], 0) + im.at(px[0], px[1], 1) + im.at(px[0], px[1], 2);
}

} // namespace

TEST_CASE("A blocker between light and floor casts a shadow", "[trace]") {
    const Scene scene = shadow_scene("trace-shadow", json::array({light({0, 0, 3})}));
    const TriangleScene ts = build_triangle_scene(scene);
    const Vec3 eye = scene.camera.eye;
    const Vec3 under{0, 0, 0}, outside{1.2, 0.3, 0};
    const auto Iu = shade_along(scene, ts, eye, under - eye);
    const auto Io = shade_along(scene, ts, eye, outside - eye);
    // In the shadow only the ambient term is left.
    for (int c = 0; c < 3; ++c) {
        CHECK(Iu[c] == Approx(0.1 * 0.8));
        CHECK(Io[c] > Iu[c] + 0.3);
    }
    // The same in a TRAY image.
    RenderOptions o;
    o.method = RenderMethod::tray;
    o.width = 64;
    o.height = 48;
    const Image im = render(scene, o);
    CHECK(brightness(im, pixel_of(scene, 64, 48, under)) + 10 <
          brightness(im, pixel_of(scene, 64, 48, outside)));
}

TEST_CASE("A light that is off casts no shadow and costs no shadow test", "[trace]") {
    const Scene one = shadow_scene("trace-one-light", json::array({light({0, 0, 3})}));
    const Scene two = shadow_scene("trace-light-off",
                                   json::array({light({0, 0, 3}), light({0.2, 0, 3}, {0, 0, 0})}));
    const Scene off = shadow_scene("trace-all-off", json::array({light({0, 0, 3}, {0, 0, 0})}));
    const TriangleScene ts = build_triangle_scene(one);
    const Vec3 eye = one.camera.eye;
    for (Vec3 p : {Vec3{0, 0, 0}, Vec3{1.2, 0.3, 0}}) {
        long long n1 = 0, n2 = 0, n0 = 0;
        CHECK(shade_along(one, ts, eye, p - eye, &n1) == shade_along(two, ts, eye, p - eye, &n2));
        CHECK(n1 == n2);
        if (p.x == 0) CHECK(n1 > 0); // the light that is on costs a shadow test
        const auto I0 = shade_along(off, ts, eye, p - eye, &n0);
        CHECK(n0 == 0); // no light on: no shadow test at all
        CHECK(I0[0] == Approx(0.1 * 0.8));
    }
}

TEST_CASE("A mirror shows the object at the mirrored position", "[trace]") {
    // Mirror in the plane y = 1; a red target centred at Q = (0.5, -1, 0) in the
    // plane y = -1, between the eye and the mirror but off the line of sight.
    const Vec3 eye{0, -3, 0}, Q{0.5, -1, 0};
    const double r = 0.05;
    auto make = [&](int max_depth) {
        return make_scene(
            test::scratch_dir("trace-mirror-" + std::to_string(max_depth)),
            {{"mirror", {quad("mirror", {-1, 1, -1}, {1, 1, -1}, {-1, 1, 1}, {1, 1, 1})}, "mirror"},
             {"target",
              {quad("target", {Q.x - r, Q.y, Q.z - r}, {Q.x - r, Q.y, Q.z + r},
                    {Q.x + r, Q.y, Q.z - r}, {Q.x + r, Q.y, Q.z + r})},
              "red"}},
            {{"mirror", material({0, 0, 0}, 0, 0, 1)}, {"red", material({0.9, 0.1, 0.2}, 0, 0)}},
            json::array(), 1.0, eye, {0, 1, 0}, max_depth);
    };
    const Scene scene = make(2);
    const TriangleScene ts = build_triangle_scene(scene);
    const Vec3 Qm{Q.x, 2 * 1 - Q.y, Q.z}; // Q mirrored in y = 1
    TraceHit m;
    REQUIRE(nearest_hit(ts, {eye, Qm - eye, 0, kInf, -1}, m));
    CHECK(m.point.y == Approx(1));
    CHECK(scene.materials[m.material].name == "mirror");
    // The reflected ray, traced on with the mirror's patch marked, meets Q.
    const Vec3 d = normalize(Qm - eye);
    const Vec3 R = d - 2 * dot(d, m.normal) * m.normal;
    TraceHit t;
    REQUIRE(nearest_hit(ts, {m.point, R, ts.ray_epsilon, kInf, m.patch}, t));
    CHECK(scene.materials[t.material].name == "red");
    CHECK(distance(t.point, Q) < 1e-9);
    // SHADE sees the target's colour in the mirror, and the background beside it.
    const auto I = shade_ray(scene, ts, {m.point, m.normal, m.material, m.patch, -d}, 0);
    CHECK(I[0] == Approx(0.9));
    CHECK(I[1] == Approx(0.1));
    CHECK(I[2] == Approx(0.2));
    const auto Ib = shade_along(scene, ts, eye, Qm + Vec3{3 * r, 0, 0} - eye);
    CHECK(Ib == std::array<double, 3>{0, 0, 0});

    SECTION("max_depth 0 disables reflection") {
        const Scene flat = make(0);
        const auto I0 = shade_ray(flat, ts, {m.point, m.normal, m.material, m.patch, -d}, 0);
        CHECK(I0 == std::array<double, 3>{0, 0, 0});
    }
}

TEST_CASE("A plane-parallel glass plate displaces a ray as Snell's law predicts", "[trace]") {
    // Plate 0 <= z <= h (ior 1.5, fully transmitting, all faces bilinear with
    // outward normals); below it at z = -1 a floor that is red for x < xe and
    // blue for x > xe. A ray at angle theta from the vertical lands at
    // x0 + h tan(theta_t) + 1 tan(theta), sin(theta_t) = sin(theta) / 1.5.
    const double h = 0.5, ior = 1.5, theta = 0.6;
    const double theta_t = std::asin(std::sin(theta) / ior);
    const double xe = 0.3;
    const double L = 3;
    json plate = json::array({horizontal("top", -L, L, -L, L, h, true),
                              horizontal("bottom", -L, L, -L, L, 0, false),
                              quad("-x", {-L, -L, 0}, {-L, -L, h}, {-L, L, 0}, {-L, L, h}),
                              quad("+x", {L, -L, 0}, {L, L, 0}, {L, -L, h}, {L, L, h}),
                              quad("-y", {-L, -L, 0}, {L, -L, 0}, {-L, -L, h}, {L, -L, h}),
                              quad("+y", {-L, L, 0}, {-L, L, h}, {L, L, 0}, {L, L, h})});
    const Scene scene = make_scene(test::scratch_dir("trace-plate"),
                                   {{"plate", plate, "glass"},
                                    {"red", {horizontal("red", -2 * L, xe, -L, L, -1)}, "red"},
                                    {"blue", {horizontal("blue", xe, 2 * L, -L, L, -1)}, "blue"}},
                                   {{"glass", material({0, 0, 0}, 0, 0, 0, 1, ior)},
                                    {"red", material({1, 0, 0}, 0, 0)},
                                    {"blue", material({0, 0, 1}, 0, 0)}},
                                   json::array(), 1.0, {0, -4, 2}, {0, 0, 0});
    const TriangleScene ts = build_triangle_scene(scene);
    const Vec3 dir{std::sin(theta), 0, -std::cos(theta)};
    const double zo = 2; // origin height
    const double land = (zo - h) * std::tan(theta) + h * std::tan(theta_t) + std::tan(theta);
    for (double delta : {-1e-6, 1e-6}) {
        // Origin x chosen so the predicted landing point is xe + delta.
        const Vec3 o{xe + delta - land, 0.1, zo};
        const auto I = shade_along(scene, ts, o, dir);
        INFO("delta " << delta);
        CHECK(I == (delta < 0 ? std::array<double, 3>{1, 0, 0} : std::array<double, 3>{0, 0, 1}));
    }
    // Without refraction (ior 1) the ray would land 0.1 further, on the blue side.
    const double straight = (zo + 1) * std::tan(theta);
    CHECK(straight - land > 0.1);
    Scene same = scene;
    for (Material& m : same.materials)
        if (m.name == "glass") m.ior = 1;
    const auto I1 = shade_along(same, ts, {xe - 1e-6 - land, 0.1, zo}, dir);
    CHECK(I1 == std::array<double, 3>{0, 0, 1});
}

TEST_CASE("TRAY with SHADE gives the same image sequentially and in parallel on SCENE 1",
          "[trace]") {
    const Scene scene = load_scene(test::data_dir() / "scenes" / "scene1.json");
    test::check_threads_agree(scene, RenderMethod::tray, 80, 60);
}

TEST_CASE("The scenes of section 8 load and render with TRAY", "[trace][heavy]") {
    struct Expect {
        const char* file;
        size_t objects, lights_on;
    };
    long long sum2 = 0, sum2a = 0;
    for (const Expect& e : {Expect{"scene1.json", 9, 1}, Expect{"scene2.json", 15, 2},
                            Expect{"scene2a.json", 15, 1}, Expect{"scene3.json", 21, 2}}) {
        INFO(e.file);
        const Scene scene = load_scene(test::data_dir() / "scenes" / e.file);
        CHECK(scene.objects.size() == e.objects);
        CHECK(static_cast<size_t>(std::count_if(scene.lights.begin(), scene.lights.end(),
                                                [](const Light& l) { return l.on(); })) ==
              e.lights_on);
        CHECK(scene.max_depth == 2);
        CHECK(scene.levels == 16);
        CHECK(scene.camera.width == 640);
        CHECK(scene.camera.height == 480);
        RenderOptions o;
        o.method = RenderMethod::tray;
        o.width = 64;
        o.height = 48;
        RenderStats st;
        const Image im = render(scene, o, &st);
        CHECK(st.patches >= 50);
        CHECK(st.patches <= 200);
        const long long surface = std::count(im.surface.begin(), im.surface.end(), 1);
        CHECK(surface > 64 * 48 / 2);
        long long sum = 0;
        for (auto v : im.level) sum += v;
        if (std::string(e.file) == "scene2.json") sum2 = sum;
        if (std::string(e.file) == "scene2a.json") sum2a = sum;
    }
    // SCENE 2a: one light off, a darker picture.
    CHECK(sum2a < sum2);
}
