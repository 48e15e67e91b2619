// SPDX-License-Identifier: MIT
// The CLI on the issue 9 example: two bicubic sheets sharing the curve x = 1
// exactly, the second with an extra knot at v = 0.3 along that edge (one Bezier
// span on one side, two on the other). `seamless tessellate` leaves that seam
// unstitched on this branch (vertices of one side inside edges of the other),
// so `seamless check` must fail it and name the seam. The seams branch (issue 9,
// section 1: geometric seam matching in lib/tessellate) makes this tessellation
// pass; then this test's expectation turns around.
#include "test_util.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>

using namespace seamless;
using nlohmann::json;

namespace {

// Control points of both sheets on one 7 x 4 grid: x = i / 3 (i = 0..6),
// y = j / 3, z curved in both directions. Sheet A takes columns 0..3, sheet B
// 3..6: the column at x = 1 is their shared boundary curve.
std::array<double, 3> grid(int i, int j) {
    const double x = i / 3.0, y = j / 3.0;
    return {x, y, 0.25 * std::sin(1.3 * x + 0.4) * std::cos(2.1 * y - 0.3)};
}

json sheet(const char* name, int i0, bool extra_knot, double t = 0.3) {
    // Rows along v (j) per column i; cubic Bezier in v, optionally with the knot
    // t inserted (Boehm: Q_k = (1 - t) P_{k-1} + t P_k for k = 1..3).
    json points = json::array();
    for (int i = i0; i < i0 + 4; ++i) {
        std::array<std::array<double, 3>, 4> p;
        for (int j = 0; j < 4; ++j) p[j] = grid(i, j);
        std::vector<std::array<double, 3>> row{p[0]};
        if (extra_knot)
            for (int k = 1; k <= 3; ++k) {
                std::array<double, 3> q;
                for (int c = 0; c < 3; ++c) q[c] = (1 - t) * p[k - 1][c] + t * p[k][c];
                row.push_back(q);
            }
        else
            row.insert(row.end(), p.begin() + 1, p.begin() + 3);
        row.push_back(p[3]);
        for (const auto& q : row) points.push_back(q);
    }
    const int nv = extra_knot ? 5 : 4;
    json knots_v = extra_knot ? json{0, 0, 0, 0, t, 1, 1, 1, 1} : json{0, 0, 0, 0, 1, 1, 1, 1};
    return {{"name", name},       {"degree", {3, 3}},
            {"size", {4, nv}},    {"knots_u", {0, 0, 0, 0, 1, 1, 1, 1}},
            {"knots_v", knots_v}, {"control_points", points}};
}

} // namespace

TEST_CASE("check CLI: the unstitched seam of two sheets, one with an extra knot, fails by name",
          "[check][seam][cli]") {
    const auto dir = test::scratch_dir("check_seam_cli");
    const json model{{"version", 1},
                     {"surfaces", {sheet("left", 0, false), sheet("right", 3, true)}}};
    test::write_file(dir / "sheets.json", model.dump(1));
    const auto mesh = (dir / "sheets.off").string();
    auto r =
        test::run_cli("tessellate \"" + (dir / "sheets.json").string() + "\" -o \"" + mesh + "\"");
    REQUIRE(r.status == 0);

    r = test::run_cli("check \"" + mesh + "\" --json");
    CHECK(r.status == 1);
    const json j = json::parse(r.out);
    CHECK(j["passed"] == false);
    REQUIRE(j["seams"]["count"] == 1);
    const json& seam = j["seams"]["listed"][0];
    // The seam runs along the shared curve x = 1, from y = 0 to y = 1.
    CHECK(std::abs(seam["location"][0].get<double>() - 1) < 1e-9);
    CHECK(std::abs(seam["from"][0].get<double>() - 1) < 1e-9);
    CHECK(std::abs(seam["to"][0].get<double>() - 1) < 1e-9);
    const double y0 = seam["from"][1], y1 = seam["to"][1];
    CHECK(std::min(y0, y1) == 0);
    CHECK(std::max(y0, y1) == 1);
    // Its length is that of the curve x = 1 (at least its chord 1 in y).
    CHECK(seam["length"].get<double>() >= 1);
    CHECK(seam["length"].get<double>() < 1.5);
    CHECK(j["t_junctions"]["count"].get<int>() > 0);
    CHECK(j["cracks"]["count"] == seam["edges"]);

    r = test::run_cli("check \"" + mesh + "\"");
    CHECK(r.status == 1);
    CHECK(r.out.find("seams (cracks: border edges along border edges): 1") != std::string::npos);
    CHECK(r.out.find("FAIL") != std::string::npos);
}

TEST_CASE("check CLI: with the extra knot at 0.5 the seam is partly welded and still fails",
          "[check][seam][cli]") {
    // Issue 9: at 0.5 the sides' vertices coincide where both sides have them
    // (welded, or within 3e-18), and the finer side's others lie inside the
    // coarser side's edges: the seam is cut into runs, each on x = 1.
    const auto dir = test::scratch_dir("check_seam_cli_05");
    const json model{{"version", 1},
                     {"surfaces", {sheet("left", 0, false), sheet("right", 3, true, 0.5)}}};
    test::write_file(dir / "sheets.json", model.dump(1));
    const auto mesh = (dir / "sheets.off").string();
    auto r =
        test::run_cli("tessellate \"" + (dir / "sheets.json").string() + "\" -o \"" + mesh + "\"");
    REQUIRE(r.status == 0);
    r = test::run_cli("check \"" + mesh + "\" --json");
    CHECK(r.status == 1);
    const json j = json::parse(r.out);
    REQUIRE(j["seams"]["count"].get<int>() >= 1);
    double length = 0;
    for (const json& seam : j["seams"]["listed"]) {
        CHECK(std::abs(seam["location"][0].get<double>() - 1) < 1e-9);
        length += seam["length"].get<double>();
    }
    CHECK(length > 0);
    CHECK(length < 1.5);
}
