// SPDX-License-Identifier: MIT
// STEP and IGES in (lib/model/step_iges/): every bundled CAD file converts,
// the surfaces agree with the JSON conversions made outside the project,
// trimmed faces are refused by name unless skipped or taken whole, and bad
// files give one InputError naming the file.
#include "test_util.h"

#include <seamless/base/error.h>
#include <seamless/model/model.h>
#include <seamless/model/step_iges.h>
#include <seamless/spline/bspline_surface.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

using namespace seamless;

namespace {

std::filesystem::path cad(const std::string& name) {
    return test::model_path("cad/" + name);
}

ModelLoadOptions skipping_trimmed() {
    ModelLoadOptions o;
    o.trimmed = TrimmedFaces::skip;
    return o;
}

// Largest distance between the two surfaces at a grid of parameters over
// their (equal) domains.
double sampled_distance(const BSplineSurface& a, const BSplineSurface& b, int n = 13) {
    double worst = 0;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            const double u = a.u_min() + (a.u_max() - a.u_min()) * i / n;
            const double v = a.v_min() + (a.v_max() - a.v_min()) * j / n;
            worst = std::max(worst, distance(evaluate(a, u, v).point, evaluate(b, u, v).point));
        }
    return worst;
}

std::string load_error(const std::filesystem::path& p, const ModelLoadOptions& o = {}) {
    try {
        load_model(p, o);
    } catch (const InputError& e) {
        CHECK(e.file() == p.string());
        return e.what();
    }
    return "";
}

} // namespace

TEST_CASE("STEP and IGES extensions select the OpenCASCADE reader", "[model][cad]") {
    for (const char* e : {".step", ".stp", ".iges", ".igs"}) CHECK(is_step_iges_extension(e));
    for (const char* e : {".json", ".bpt", ".st", ".ig", ".STEP"})
        CHECK_FALSE(is_step_iges_extension(e));
}

TEST_CASE("every bundled CAD file converts exactly, with the surface count of its README",
          "[model][cad]") {
    // Counts from data/models/cad/README.md (tire: 47 surfaces, 2 of them trimmed).
    const std::map<std::string, size_t> surfaces = {
        {"torus.igs", 1},  {"rounded_cube.iges", 6},     {"sunglasses_lens.igs", 9},
        {"tire.iges", 45}, {"bug28366_fuselage.stp", 8}, {"splinecage.stp", 4}};
    for (const auto& [name, count] : surfaces) {
        INFO(name);
        const Model m = load_model(cad(name), skipping_trimmed());
        CHECK(m.source == cad(name).string());
        REQUIRE(m.surfaces.size() == count);
        REQUIRE(m.origins.size() == count);
        for (size_t k = 0; k < count; ++k) {
            CHECK(m.origins[k].exact);
            CHECK(m.origins[k].approximation_error == 0);
            CHECK(m.origins[k].entity == m.surfaces[k].name);
            CHECK_FALSE(m.surfaces[k].name.empty());
            CHECK_NOTHROW(validate_surface(m.surfaces[k], name, m.surfaces[k].name));
        }
        // Only the tire has something to warn about: the skipped trimmed faces.
        CHECK(m.warnings.size() == (name == "tire.iges" ? 1u : 0u));
        // The JSON written for it reads back bit for bit.
        const Model back = parse_model_json(to_json(m), "back.json");
        REQUIRE(back.surfaces.size() == count);
        for (size_t k = 0; k < count; ++k) {
            CHECK(back.surfaces[k].points == m.surfaces[k].points);
            CHECK(back.surfaces[k].weights == m.surfaces[k].weights);
            CHECK(back.surfaces[k].knots_u == m.surfaces[k].knots_u);
            CHECK(back.surfaces[k].knots_v == m.surfaces[k].knots_v);
        }
    }
}

TEST_CASE("converted surfaces agree with the JSON conversions made outside the project",
          "[model][cad]") {
    for (const char* name :
         {"torus.igs", "rounded_cube.iges", "sunglasses_lens.igs", "bug28366_fuselage.stp"}) {
        INFO(name);
        const Model m = load_model(cad(name));
        const Model ref = load_model(cad(std::filesystem::path(name).stem().string() + ".json"));
        REQUIRE(m.surfaces.size() == ref.surfaces.size());
        const double tol = 1e-13 * d_max(ref);
        for (size_t k = 0; k < m.surfaces.size(); ++k) {
            const BSplineSurface &a = m.surfaces[k], &b = ref.surfaces[k];
            INFO(b.name);
            CHECK(a.name == b.name);
            CHECK(a.degree_u == b.degree_u);
            CHECK(a.degree_v == b.degree_v);
            CHECK(a.knots_u == b.knots_u); // torus.igs: periodic in OpenCASCADE, clamped here
            CHECK(a.knots_v == b.knots_v);
            REQUIRE(a.u_min() == b.u_min());
            REQUIRE(a.u_max() == b.u_max());
            REQUIRE(a.v_min() == b.v_min());
            REQUIRE(a.v_max() == b.v_max());
            CHECK(sampled_distance(a, b) <= tol);
        }
        // Lengths stay in the file's units (OpenCASCADE would convert them to mm).
        CHECK(d_max(m) == d_max(ref));
    }
}

TEST_CASE("the tire's 45 surfaces are rational and splinecage's are degree (1, 3)",
          "[model][cad]") {
    const Model tire = load_model(cad("tire.iges"), skipping_trimmed());
    CHECK(std::count_if(tire.surfaces.begin(), tire.surfaces.end(),
                        [](const BSplineSurface& s) { return s.rational(); }) == 45);
    for (const BSplineSurface& s : tire.surfaces)
        for (double w : s.weights) {
            CHECK(w >= 0.5 - 1e-12);
            CHECK(w <= 1.0 + 1e-12);
        }
    const Model cage = load_model(cad("splinecage.stp"));
    for (const BSplineSurface& s : cage.surfaces) {
        CHECK(s.degree_u + s.degree_v == 4);
        CHECK(std::min(s.degree_u, s.degree_v) == 1);
        CHECK_FALSE(s.rational());
    }
}

TEST_CASE("the fuselage's bare surfaces keep the file's feet: nose at z=-3, tail at x=206.5",
          "[model][cad]") {
    const Model m = load_model(cad("bug28366_fuselage.stp"));
    const Box3 box = control_box(m);
    CHECK(box.hi.x == 206.5);
    int at_nose = 0;
    for (const BSplineSurface& s : m.surfaces)
        for (const Vec3& p : s.points) at_nose += p == Vec3{0, 0, -3};
    CHECK(at_nose > 0);
}

TEST_CASE("trimmed faces: refused by name, skipped, or taken whole", "[model][cad]") {
    ModelLoadOptions refusing;
    refusing.trimmed = TrimmedFaces::refuse;
    const std::string err = load_error(cad("tire.iges"), refusing);
    CHECK_THAT(err, Catch::Contains("tire.iges: 2 trimmed faces ("));
    CHECK(err.find('\n') == std::string::npos);

    const Model skipped = load_model(cad("tire.iges"), skipping_trimmed());
    ModelLoadOptions whole_opt;
    whole_opt.trimmed = TrimmedFaces::whole_surface;
    const Model whole = load_model(cad("tire.iges"), whole_opt);
    REQUIRE(whole.surfaces.size() == skipped.surfaces.size() + 2);
    REQUIRE(whole.warnings.size() == 1);
    REQUIRE(skipped.warnings.size() == 1);
    // The two surfaces only --untrimmed adds are the ones the error and the
    // warnings name.
    int named = 0;
    for (const BSplineSurface& s : whole.surfaces) {
        const bool kept = std::any_of(skipped.surfaces.begin(), skipped.surfaces.end(),
                                      [&](const BSplineSurface& t) { return t.name == s.name; });
        if (kept) continue;
        ++named;
        INFO(s.name);
        CHECK_THAT(err, Catch::Contains(s.name));
        CHECK_THAT(skipped.warnings[0], Catch::Contains(s.name));
        CHECK_THAT(whole.warnings[0], Catch::Contains(s.name));
    }
    CHECK(named == 2);
}

TEST_CASE("bad STEP/IGES files: one InputError naming the file", "[model][cad][errors]") {
    auto dir = test::scratch_dir("step-iges-errors");
    struct Case {
        std::string name, text, expect;
    };
    std::string truncated_step;
    {
        std::ifstream in(cad("splinecage.stp"), std::ios::binary);
        truncated_step.resize(5000);
        in.read(truncated_step.data(), 5000);
    }
    const std::vector<Case> cases = {
        {"words.step", "hello world\n", "not a readable STEP file"},
        {"words.igs", "hello world\n", "not a readable IGES file"},
        {"empty.iges", "", "not a readable IGES file"},
        {"empty.stp", "", "not a readable STEP file"},
        {"truncated.stp", truncated_step, "not a readable STEP file"},
        {"nodata.step", "ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\nENDSEC;\nEND-ISO-10303-21;\n",
         "not a readable STEP file"},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        test::write_file(dir / c.name, c.text);
        const std::string err = load_error(dir / c.name);
        CHECK_THAT(err,
                   Catch::StartsWith((dir / c.name).string() + ": ") && Catch::Contains(c.expect));
        CHECK(err.find('\n') == std::string::npos);
    }
    CHECK_THAT(load_error(dir / "missing.step"), Catch::Contains("cannot open file"));
}

// Issue 12, found by fuzz_step_iges: one misspelt entity name
// (CA0RTESIAN_POINT) left a null reference that OpenCASCADE 7.6's transfer
// dereferenced (SIGSEGV, the CLI exited 139). The reproducer is also in
// tests/fuzz/corpus/step_iges/misspelt-point.step.
TEST_CASE("a STEP file whose geometry refers to an unreadable entity is refused, not a crash",
          "[model][cad][errors]") {
    std::string text;
    {
        std::ifstream in(cad("generated/torus.step"), std::ios::binary);
        std::stringstream ss;
        ss << in.rdbuf();
        text = ss.str();
    }
    const std::string point = "#54 = CARTESIAN_POINT(";
    const size_t at = text.find(point);
    REQUIRE(at != std::string::npos);
    text.replace(at, point.size(), "#54 = CA0RTESIAN_POINT(");
    const auto file = test::scratch_dir("step-iges-misspelt") / "misspelt-point.step";
    test::write_file(file, text);
    const std::string err = load_error(file);
    CHECK_THAT(err, Catch::StartsWith(file.string() + ": not a readable STEP file") &&
                        Catch::Contains("entity #53"));
    CHECK(err.find('\n') == std::string::npos);
}

namespace {

std::filesystem::path generated(const std::string& name) {
    return cad("generated/" + name);
}

// Largest |f(point)| over a grid of parameters of `s`.
template <class F> double worst_on_grid(const BSplineSurface& s, F f, int n = 24) {
    double worst = 0;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            const double u = s.u_min() + (s.u_max() - s.u_min()) * i / n;
            const double v = s.v_min() + (s.v_max() - s.v_min()) * j / n;
            worst = std::max(worst, std::abs(f(evaluate(s, u, v).point)));
        }
    return worst;
}

} // namespace

TEST_CASE("planes, a sphere, a torus and a revolved B-spline curve convert exactly",
          "[model][cad]") {
    // generated/make_analytic.cpp: box (1,2,3) + (2,3,4); sphere r=2 about
    // (1,0,0); torus R=3, r=1 about z; a cubic profile revolved half a turn about z.
    const Model box = load_model(generated("box.step"));
    REQUIRE(box.surfaces.size() == 6);
    for (size_t k = 0; k < 6; ++k) {
        CHECK(box.origins[k].kind == "plane");
        CHECK(box.origins[k].exact);
        const BSplineSurface& s = box.surfaces[k];
        CHECK(s.degree_u == 1);
        CHECK(s.degree_v == 1);
        for (const Vec3& p : s.points) {
            CHECK((p.x == 1 || p.x == 3));
            CHECK((p.y == 2 || p.y == 5));
            CHECK((p.z == 3 || p.z == 7));
        }
    }
    const Model sphere = load_model(generated("sphere.step"));
    REQUIRE(sphere.surfaces.size() == 1);
    CHECK(sphere.origins[0].kind == "sphere");
    CHECK(sphere.origins[0].exact);
    CHECK(sphere.surfaces[0].rational());
    CHECK(worst_on_grid(sphere.surfaces[0], [](Vec3 p) {
              return distance(p, Vec3{1, 0, 0}) - 2;
          }) <= 1e-13);
    const Model torus = load_model(generated("torus.step"));
    REQUIRE(torus.surfaces.size() == 1);
    CHECK(torus.origins[0].kind == "torus");
    CHECK(torus.origins[0].exact);
    CHECK(worst_on_grid(torus.surfaces[0], [](Vec3 p) {
              const double rho = std::hypot(p.x, p.y) - 3;
              return rho * rho + p.z * p.z - 1;
          }) <= 1e-13);
    const Model revolved = load_model(generated("revolved.step"));
    REQUIRE(revolved.surfaces.size() == 1);
    CHECK(revolved.origins[0].kind == "surface of revolution");
    CHECK(revolved.origins[0].exact);
    // Half a turn from the xz plane through +y.
    CHECK(worst_on_grid(revolved.surfaces[0], [](Vec3 p) { return std::min(p.y, 0.0); }) <= 1e-12);
}

TEST_CASE("a cylinder's side is whole, its disc caps are trimmed", "[model][cad]") {
    ModelLoadOptions refusing;
    refusing.trimmed = TrimmedFaces::refuse;
    CHECK_THAT(load_error(generated("cylinder.step"), refusing),
               Catch::Contains("2 trimmed faces"));
    const Model side = load_model(generated("cylinder.step"), skipping_trimmed());
    REQUIRE(side.surfaces.size() == 1);
    CHECK(side.origins[0].kind == "cylinder");
    CHECK(side.origins[0].exact);
    CHECK(worst_on_grid(side.surfaces[0], [](Vec3 p) { return std::hypot(p.x, p.y) - 1; }) <=
          1e-13);
    const Box3 b = control_box(side);
    CHECK(b.lo.z == Approx(0).margin(1e-15));
    CHECK(b.hi.z == Approx(2));
    ModelLoadOptions whole;
    whole.trimmed = TrimmedFaces::whole_surface;
    const Model all = load_model(generated("cylinder.step"), whole);
    REQUIRE(all.surfaces.size() == 3);
    CHECK(std::count_if(all.origins.begin(), all.origins.end(),
                        [](const SurfaceOrigin& o) { return o.kind == "plane"; }) == 2);
}

TEST_CASE("surfaces without an exact form of degree <= 9 are approximated, the error reported",
          "[model][cad]") {
    // An offset (by 0.5) of the plane z = 0 written as a bicubic B-spline.
    const Model offset = load_model(generated("offset.step"));
    REQUIRE(offset.surfaces.size() == 1);
    const SurfaceOrigin& o = offset.origins[0];
    CHECK(o.kind == "offset B-spline");
    CHECK_FALSE(o.exact);
    CHECK(o.approximation_error <= 1e-7 * std::sqrt(5.0));
    CHECK(worst_on_grid(offset.surfaces[0], [](Vec3 p) { return p.z - 0.5; }) <=
          o.approximation_error + 1e-14);
    REQUIRE(offset.warnings.size() == 1);
    CHECK_THAT(offset.warnings[0], Catch::Contains("approximated 1 surface") &&
                                       Catch::Contains(offset.surfaces[0].name));
    // z = x y as a degree-11 Bezier patch.
    const Model high = load_model(generated("degree11.igs"));
    REQUIRE(high.surfaces.size() == 1);
    const BSplineSurface& s = high.surfaces[0];
    CHECK_FALSE(high.origins[0].exact);
    CHECK(s.degree_u <= kMaxDegree);
    CHECK(s.degree_v <= kMaxDegree);
    CHECK(high.origins[0].approximation_error <= 1e-7 * std::sqrt(3.0));
    CHECK(worst_on_grid(s, [](Vec3 p) { return p.z - p.x * p.y; }) <=
          2 * high.origins[0].approximation_error + 1e-14);
    REQUIRE(high.warnings.size() == 1);
}
