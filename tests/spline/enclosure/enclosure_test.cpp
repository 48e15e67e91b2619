// SPDX-License-Identifier: MIT
#include <seamless/spline/enclosure/enclosure.h>

#include "spline/patch_samples.h"
#include "test_util.h"

#include <seamless/model/model.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace seamless;

namespace {

// lo <= v <= hi up to what the long double reference itself may be off by.
bool holds(Interval x, long double v) {
    const long double slack = 1e-16L * (1 + std::fabs(v));
    return x.lo() <= v + slack && x.hi() >= v - slack;
}

// Every enclosure over the box contains the values at `samples` random points
// of the box (corners included). Returns the number of samples checked.
int check_box(const BezierPatch& b, const PatchForms& f, ParamBox box, std::mt19937_64& rng,
              int samples) {
    const PatchEnclosure e = enclose(f, box);
    std::uniform_real_distribution<double> u(0, 1);
    for (int n = 0; n < samples; ++n) {
        double s, t;
        if (n < 4) {
            s = n & 1 ? box.s.hi() : box.s.lo();
            t = n & 2 ? box.t.hi() : box.t.lo();
        } else {
            s = std::clamp(box.s.lo() + u(rng) * (box.s.hi() - box.s.lo()), box.s.lo(), box.s.hi());
            t = std::clamp(box.t.lo() + u(rng) * (box.t.hi() - box.t.lo()), box.t.lo(), box.t.hi());
        }
        const test::RefPoint r = test::reference(b, s, t);
        // Every sample is checked; Catch's assertion machinery (the INFO
        // message is built eagerly) runs only for a sample that fails, which
        // keeps 70,000 samples per patch within seconds.
        bool all = true;
        for (int c = 0; c < 3; ++c)
            all = all && holds(e.point[c], r.point[c]) && holds(e.ds[c], r.ds[c]) &&
                  holds(e.dt[c], r.dt[c]) && holds(e.normal[c], r.normal[c]);
        if (all) continue;
        for (int c = 0; c < 3; ++c) {
            INFO("p " << b.p << " q " << b.q << " rational " << f.rational << " box " << box.s
                      << " x " << box.t << " at " << s << ", " << t << " coord " << c);
            REQUIRE(holds(e.point[c], r.point[c]));
            REQUIRE(holds(e.ds[c], r.ds[c]));
            REQUIRE(holds(e.dt[c], r.dt[c]));
            REQUIRE(holds(e.normal[c], r.normal[c]));
        }
    }
    return samples;
}

// Boxes of every kind: whole patch, touching the border, thin, 1e-12 wide, random.
std::vector<ParamBox> test_boxes(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    const double a = u(rng), c = u(rng), w = 0.3 * u(rng);
    std::vector<ParamBox> boxes = {
        {{0, 1}, {0, 1}},
        {{0, 0.25}, {0.5, 1}},                                    // touching two borders
        {{1 - 1e-9, 1}, {0, 1}},                                  // thin along the border
        {{a, a}, {0, 1}},                                         // a thin iso-line
        {{a * 0.5, a * 0.5 + 1e-12}, {c * 0.5, c * 0.5 + 1e-12}}, // width 1e-12
        {{0, 1e-12}, {1 - 1e-12, 1}},                             // width 1e-12 in a corner
        {{std::min(a, 1 - w), std::min(a, 1 - w) + w},
         {std::min(c, 1 - w), std::min(c, 1 - w) + w}},
    };
    return boxes;
}

// Width of the sampled range of coordinate c over the box (grid with corners).
double sampled_width(const BezierPatch& b, ParamBox box, int c) {
    long double lo = 1e300L, hi = -1e300L;
    const int n = 100;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            double s = box.s.lo() + (box.s.hi() - box.s.lo()) * i / n;
            double t = box.t.lo() + (box.t.hi() - box.t.lo()) * j / n;
            long double v = test::reference(b, s, t).point[c];
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    return double(hi - lo);
}

// Least-squares slope of log(overestimation) over log(r).
double overestimation_slope(const BezierPatch& b, const PatchForms& f, double s0, double t0,
                            int c) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (int k = 3; k <= 11; ++k) {
        const double r = std::ldexp(1.0, -k);
        const ParamBox box{{s0 - r, s0 + r}, {t0 - r, t0 + r}};
        const double over = enclose_point(f, box)[c].width() - sampled_width(b, box, c);
        REQUIRE(over >= -1e-15); // never below the range
        const double x = std::log(r), y = std::log(std::max(over, 1e-300));
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        ++n;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

} // namespace

TEST_CASE("enclosures of teapot patches contain sampled values", "[enclosure][heavy]") {
    std::mt19937_64 rng(31);
    const auto patches = bezier_patches(load_model(test::model_path("teapot.json")));
    long long checked = 0;
    for (const auto& b : patches) {
        const PatchForms f = patch_forms(b);
        for (const ParamBox& box : test_boxes(rng)) checked += check_box(b, f, box, rng, 10000);
    }
    CHECK(patches.size() == 32);
    CHECK(checked == 32 * 7 * 10000);
}

TEST_CASE("enclosures of random patches of degree 1 to 5 contain sampled values",
          "[enclosure][heavy]") {
    std::mt19937_64 rng(32);
    for (int p = 1; p <= 5; ++p)
        for (int q = 1; q <= 5; ++q)
            for (bool rational : {false, true}) {
                const BezierPatch b = test::random_patch(rng, p, q, rational);
                const PatchForms f = patch_forms(b);
                REQUIRE(f.rational == rational);
                const auto boxes = test_boxes(rng);
                for (size_t i = 0; i < boxes.size(); ++i) check_box(b, f, boxes[i], rng, 10000);
            }
}

TEST_CASE("enclosures are tight for tiny boxes", "[enclosure]") {
    std::mt19937_64 rng(33);
    for (bool rational : {false, true}) {
        const BezierPatch b = test::random_patch(rng, 3, 3, rational);
        const PatchForms f = patch_forms(b);
        const ParamBox box{{0.3, 0.3 + 1e-12}, {0.6, 0.6 + 1e-12}};
        const PatchEnclosure e = enclose(f, box);
        for (int c = 0; c < 3; ++c) {
            CHECK(e.point[c].width() < 1e-10);
            CHECK(e.ds[c].width() < 1e-9);
        }
    }
}

TEST_CASE("whole-patch point enclosure is inside the control point hull", "[enclosure]") {
    std::mt19937_64 rng(34);
    for (bool rational : {false, true}) {
        const BezierPatch b = test::random_patch(rng, 4, 2, rational);
        const PatchForms f = patch_forms(b);
        const IVec3 P = enclose_point(f, ParamBox{});
        for (int c = 0; c < 3; ++c) CHECK(f.control_hull[c].contains(P[c]));
    }
}

TEST_CASE("Lemma 2: range of a polynomial with interval coefficients over u >= 0", "[enclosure]") {
    // p(u) = [1,2] - [3,3] u + [1,1] u^2 over [0, 2]: range [min 1-3u+u^2, max 2-3u+u^2]
    // = [-1.25, 2]; interval Horner gives [-5, 2].
    const Interval c[3] = {Interval(1, 2), Interval(-3.0), Interval(1.0)};
    const Interval u(0, 2);
    const Interval r = polynomial_range(c, 2, u);
    const Interval horner = (c[2] * u + c[1]) * u + c[0];
    CHECK(r.contains(Interval(-1.25, 2)));
    CHECK(horner.contains(r));
    CHECK(r.width() < horner.width());
    // Monotone on the box: the range is the hull of the end values, up to rounding.
    const Interval m = polynomial_range(c, 2, Interval(0, 1));
    CHECK(m.contains(Interval(-1, 2)));
    CHECK(m.width() < 3 + 1e-12);
    // Random polynomials: contains sampled values.
    std::mt19937_64 rng(36);
    std::uniform_real_distribution<double> g(-1, 1), v(0, 1);
    for (int n = 0; n < 2000; ++n) {
        Interval cc[6];
        for (Interval& x : cc) x = Interval::hull(g(rng), g(rng));
        double a = v(rng), b = v(rng);
        const Interval ur = Interval::hull(a, b);
        const Interval rr = polynomial_range(cc, 5, ur);
        const double x = ur.lo() + v(rng) * (ur.hi() - ur.lo());
        long double lo = 0, hi = 0;
        for (int i = 5; i >= 0; --i) {
            lo = lo * x + cc[i].lo();
            hi = hi * x + cc[i].hi();
        }
        REQUIRE(rr.lo() <= lo + 1e-15L);
        REQUIRE(rr.hi() >= hi - 1e-15L);
    }
}

TEST_CASE("mean value form: the overestimation shrinks quadratically (Proposition 1)",
          "[enclosure][heavy]") {
    std::mt19937_64 rng(35);
    for (bool rational : {false, true})
        for (int trial = 0; trial < 3; ++trial) {
            const BezierPatch b = test::random_patch(rng, 3, 3, rational);
            const PatchForms f = patch_forms(b);
            for (int c = 0; c < 3; ++c) {
                const double slope = overestimation_slope(b, f, 0.4, 0.55, c);
                INFO("rational " << rational << " coord " << c << " slope " << slope);
                CHECK(slope >= 1.8);
            }
        }
}

TEST_CASE("point enclosures near the underflow threshold hold the exact value",
          "[enclosure][underflow]") {
    // Coefficients whose products and sums are subnormal doubles: the error
    // of each rounding is then absolute, not relative, and only the allowance
    // for gradual underflow (underflow_allowance of interval.h) and the final
    // outward ulps cover it.
    // long double keeps these values normal (15-bit exponent), so its Horner
    // sum is exact to far below the doubles' absolute error here.
    const double tiny = std::numeric_limits<double>::denorm_min();
    std::uint64_t seed = 12345;
    auto next = [&seed]() {
        seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(seed >> 11) * 0x1p-53;
    };
    int checked = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const int n = 1 + trial % 9;
        Interval c[PowerForm::kMaxOrder];
        double cd[PowerForm::kMaxOrder];
        for (int i = 0; i <= n; ++i) {
            cd[i] = (next() - 0.5) * 4096 * tiny * (1 + trial % 7); // a few thousand ulps of 0
            c[i] = Interval(cd[i]);
        }
        const double x = next();
        const Interval r = polynomial_range(c, n, Interval(x));
        long double v = cd[n];
        for (int i = n - 1; i >= 0; --i) v = v * x + cd[i];
        REQUIRE(r.lo() <= v);
        REQUIRE(r.hi() >= v);
        ++checked;
    }
    CHECK(checked == 2000);
    CHECK(underflow_allowance(40) >= 40 * std::numeric_limits<double>::denorm_min());
    CHECK(std::isnormal(underflow_allowance(1)));
}
