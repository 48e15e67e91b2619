// SPDX-License-Identifier: MIT
// The CLI on the issue 9 example: two bicubic sheets sharing the curve x = 1,
// the second with an extra knot at v = 0.3 along that edge (one Bezier span on
// one side, two on the other). The tessellator stitches that seam geometrically
// (lib/tessellate/seams/edge_graph.h), so `seamless check` passes it. Moved 1e-4
// apart, beyond the default seam tolerance, the sheets stay apart and `check`
// must fail the seam and name it with its location, length and width; with
// `--seam-tolerance 1e-3` they are stitched again and pass.
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

json sheet(const char* name, int i0, bool extra_knot, double dz = 0) {
    // Rows along v (j) per column i; cubic Bezier in v, optionally with the knot
    // t = 0.3 inserted (Boehm: Q_k = (1 - t) P_{k-1} + t P_k for k = 1..3).
    const double t = 0.3;
    json points = json::array();
    for (int i = i0; i < i0 + 4; ++i) {
        std::array<std::array<double, 3>, 4> p;
        for (int j = 0; j < 4; ++j) {
            p[j] = grid(i, j);
            p[j][2] += dz;
        }
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

std::string tessellate(const std::filesystem::path& dir, double dz, const std::string& options) {
    const json model{{"version", 1},
                     {"surfaces", {sheet("left", 0, false), sheet("right", 3, true, dz)}}};
    test::write_file(dir / "sheets.json", model.dump(1));
    const auto mesh = (dir / "sheets.off").string();
    const auto r = test::run_cli("tessellate \"" + (dir / "sheets.json").string() + "\" -o \"" +
                                 mesh + "\" " + options);
    REQUIRE(r.status == 0);
    return mesh;
}

} // namespace

TEST_CASE("check CLI: two sheets, one with an extra knot, stitched by the tessellator, pass",
          "[check][seam][cli][heavy]") {
    const auto dir = test::scratch_dir("check_seam_cli_stitched");
    for (const char* options : {"", "--eps1 0.00002 --eps2 0.0004"}) {
        const auto mesh = tessellate(dir, 0, options);
        const auto r = test::run_cli("check \"" + mesh + "\" --json");
        CHECK(r.status == 0);
        const json j = json::parse(r.out);
        CHECK(j["passed"] == true);
        CHECK(j["seams"]["count"] == 0);
        CHECK(j["t_junctions"]["count"] == 0);
    }
}

TEST_CASE("check CLI: the unstitched seam of two sheets 1e-4 apart fails by name",
          "[check][seam][cli]") {
    const auto dir = test::scratch_dir("check_seam_cli");
    const auto mesh = tessellate(dir, 1e-4, "");
    auto r = test::run_cli("check \"" + mesh + "\" --json");
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
    CHECK(seam["gap"].get<double>() >= 0.9e-4);
    CHECK(seam["gap"].get<double>() < 1e-2);
    CHECK(j["cracks"]["count"] == seam["edges"]);

    r = test::run_cli("check \"" + mesh + "\"");
    CHECK(r.status == 1);
    CHECK(r.out.find("seams (cracks: border edges along border edges): 1") != std::string::npos);
    CHECK(r.out.find("FAIL") != std::string::npos);
}

TEST_CASE("check CLI: the sheets 1e-4 apart, stitched with --seam-tolerance 1e-3, pass",
          "[check][seam][cli]") {
    const auto dir = test::scratch_dir("check_seam_cli_tolerance");
    const auto mesh = tessellate(dir, 1e-4, "--seam-tolerance 1e-3");
    const auto r = test::run_cli("check \"" + mesh + "\" --json");
    CHECK(r.status == 0);
    const json j = json::parse(r.out);
    CHECK(j["passed"] == true);
    CHECK(j["seams"]["count"] == 0);
}
