// SPDX-License-Identifier: MIT
// The seamless program on STEP and IGES: info, convert and tessellate take
// them, --skip-trimmed and --untrimmed act and warn, bad files give one line
// and exit 2 without output files.
#include "test_util.h"

#include <seamless/model/model.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>

using namespace seamless;

namespace {

std::filesystem::path cad(const std::string& name) {
    return test::model_path("cad/" + name);
}
int lines(const std::string& s) {
    return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

} // namespace

TEST_CASE("seamless convert --help, and the CAD flags on info, tessellate, convert", "[cli][cad]") {
    for (const char* cmd : {"convert", "info", "tessellate"}) {
        INFO(cmd);
        auto r = test::run_cli(std::string(cmd) + " --help");
        CHECK(r.status == 0);
        CHECK_THAT(r.out, Catch::Contains("--skip-trimmed") && Catch::Contains("--untrimmed"));
    }
    CHECK_THAT(test::run_cli("--help").out, Catch::Contains("convert"));
}

TEST_CASE("seamless info on STEP and IGES: surfaces, exactness, nothing else on stdout",
          "[cli][cad]") {
    auto r = test::run_cli("info " + test::quoted(cad("bug28366_fuselage.stp")));
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    CHECK_THAT(r.out, Catch::Contains("8 surfaces") && Catch::Contains("#55: degree 3x3") &&
                          Catch::Contains("from B-spline (exact)"));
    auto j = test::run_cli("info --json " + test::quoted(cad("torus.igs")));
    CHECK(j.status == 0);
    CHECK_THAT(j.out, Catch::Contains("\"entity\": \"DE3\"") &&
                          Catch::Contains("\"approximation_error\": 0.0"));
}

TEST_CASE("seamless convert writes a JSON model equal to the reader's model", "[cli][cad]") {
    auto dir = test::scratch_dir("cli-convert");
    for (const char* name : {"splinecage.stp", "rounded_cube.iges"}) {
        INFO(name);
        const auto out = dir / (std::string(name) + ".json");
        auto r = test::run_cli("convert " + test::quoted(cad(name)) + " -o " + test::quoted(out));
        CHECK(r.status == 0);
        CHECK(r.err.empty());
        CHECK_THAT(r.out, Catch::Contains("exact, 0 approximated"));
        const Model direct = load_model(cad(name));
        const Model written = load_model(out);
        REQUIRE(written.surfaces.size() == direct.surfaces.size());
        for (size_t k = 0; k < direct.surfaces.size(); ++k) {
            CHECK(written.surfaces[k].name == direct.surfaces[k].name);
            CHECK(written.surfaces[k].points == direct.surfaces[k].points);
            CHECK(written.surfaces[k].knots_u == direct.surfaces[k].knots_u);
            CHECK(written.surfaces[k].knots_v == direct.surfaces[k].knots_v);
        }
    }
    // Unknown output extension: refused before reading the model.
    auto bad = test::run_cli("convert " + test::quoted(cad("torus.igs")) + " -o " +
                             test::quoted(dir / "out.obj"));
    CHECK(bad.status == 2);
    CHECK(lines(bad.err) == 1);
    CHECK_FALSE(std::filesystem::exists(dir / "out.obj"));
}

TEST_CASE("tire.iges: read as a B-rep, --skip-trimmed and --untrimmed warn", "[cli][cad]") {
    auto dir = test::scratch_dir("cli-trimmed");
    const auto out = dir / "tire.json";
    // By default its two trimmed faces make it a B-rep: a version-2 JSON model.
    auto brep =
        test::run_cli("convert " + test::quoted(cad("tire.iges")) + " -o " + test::quoted(out));
    CHECK(brep.status == 0);
    CHECK_THAT(brep.out, Catch::Contains("47 B-rep faces"));
    const Model read_back = load_model(out);
    CHECK(read_back.brep.faces.size() == 47);
    CHECK(read_back.surfaces.size() == 47);

    auto skipped = test::run_cli("convert --skip-trimmed " + test::quoted(cad("tire.iges")) +
                                 " -o " + test::quoted(out));
    CHECK(skipped.status == 0);
    CHECK(lines(skipped.err) == 1);
    CHECK_THAT(skipped.err,
               Catch::StartsWith("warning: ") && Catch::Contains("skipped 2 trimmed faces"));
    CHECK(load_model(out).surfaces.size() == 45);

    auto whole = test::run_cli("info --untrimmed " + test::quoted(cad("tire.iges")));
    CHECK(whole.status == 0);
    CHECK_THAT(whole.err, Catch::StartsWith("warning: ") &&
                              Catch::Contains("whole surfaces of 2 trimmed faces"));
    CHECK_THAT(whole.out, Catch::Contains("47 surfaces"));

    auto both = test::run_cli("info --skip-trimmed --untrimmed " + test::quoted(cad("tire.iges")));
    CHECK(both.status == 2);

    const auto mesh = dir / "tire.off";
    auto tess = test::run_cli("tessellate --skip-trimmed " + test::quoted(cad("tire.iges")) +
                              " -o " + test::quoted(mesh));
    CHECK(tess.status == 0);
    CHECK_THAT(tess.out, Catch::Contains("45 surfaces"));
    CHECK(std::filesystem::exists(mesh));
}

TEST_CASE("bad STEP/IGES files: one line naming the file, exit 2, no output",
          "[cli][cad][errors]") {
    auto dir = test::scratch_dir("cli-cad-errors");
    test::write_file(dir / "words.step", "hello world\n");
    test::write_file(dir / "words.igs", "hello world\n");
    test::write_file(dir / "empty.stp", "");
    for (const char* name : {"words.step", "words.igs", "empty.stp", "missing.iges"}) {
        INFO(name);
        const std::vector<std::string> cmds = {
            "info ", "convert -o " + test::quoted(dir / "out.json") + " ",
            "tessellate -o " + test::quoted(dir / "out.off") + " "};
        for (const std::string& cmd : cmds) {
            auto r = test::run_cli(cmd + test::quoted(dir / name));
            CHECK(r.status == 2);
            CHECK(r.out.empty());
            CHECK(lines(r.err) == 1);
            CHECK_THAT(r.err, Catch::StartsWith("error: " + (dir / name).string() + ": "));
        }
        CHECK_FALSE(std::filesystem::exists(dir / "out.json"));
        CHECK_FALSE(std::filesystem::exists(dir / "out.off"));
    }
}

// The tire's surfaces meet along four curves only within 1.2e-3 (the file's
// tolerance; the tread and the shoulders are separate surfaces): by default
// those seams stay apart and `check` names them with their width; with
// --seam-tolerance 2e-3 they are stitched and the mesh passes `check`, its 12
// surfaces that face the other way in the file flipped to agree.
TEST_CASE("tire.iges: seams within 1.2e-3 reported by check, stitched by --seam-tolerance",
          "[cli][cad]") {
    const auto dir = test::scratch_dir("cli_cad_tire_seams");
    const auto mesh = dir / "tire.off";
    auto r = test::run_cli("tessellate --skip-trimmed " + test::quoted(cad("tire.iges")) + " -o " +
                           test::quoted(mesh));
    REQUIRE(r.status == 0);
    r = test::run_cli("check --json " + test::quoted(mesh));
    CHECK(r.status == 1);
    auto j = nlohmann::json::parse(r.out);
    CHECK(j["seams"]["count"] == 4);
    CHECK(j["inconsistent_orientation"]["count"] == 0);
    for (const auto& seam : j["seams"]["listed"]) {
        CHECK(seam["gap"].get<double>() > 1e-3);
        CHECK(seam["gap"].get<double>() < 2e-3);
    }
    // (100x finer tolerances: tests/tessellate/cad_tessellation_test.cpp.)
    r = test::run_cli("tessellate --skip-trimmed --seam-tolerance 2e-3 " +
                      test::quoted(cad("tire.iges")) + " -o " + test::quoted(mesh));
    REQUIRE(r.status == 0);
    r = test::run_cli("check --json " + test::quoted(mesh));
    CHECK(r.status == 0);
    j = nlohmann::json::parse(r.out);
    CHECK(j["passed"] == true);
    CHECK(j["seams"]["count"] == 0);
    CHECK(j["t_junctions"]["count"] == 0);
}
