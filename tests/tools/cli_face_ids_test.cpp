// SPDX-License-Identifier: MIT
// seamless tessellate writes face ids to OBJ and PLY, and seamless check on
// such a file names the faces and parts its defects lie on.
#include "test_util.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

using namespace seamless;

namespace {

std::string read_text(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The text with its n-th line of `tokens` tokens starting with `prefix`
// replaced by edit(line).
template <class Edit>
std::string edit_line(const std::string& text, const std::string& prefix, int tokens, int n,
                      Edit edit) {
    std::istringstream in(text);
    std::string line, out;
    int seen = 0;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        int count = 0;
        for (std::string w; words >> w;) ++count;
        if (line.rfind(prefix, 0) == 0 && count == tokens && seen++ == n) line = edit(line);
        out += line + "\n";
    }
    return out;
}

} // namespace

TEST_CASE("check names the faces of a broken OBJ and PLY written with face ids",
          "[cli][face_ids][heavy]") {
    const auto dir = test::scratch_dir("cli_face_ids");
    const auto model = test::model_path("cad/b123d_M6-1x12-countersunk-screw.step");
    for (const char* ext : {".obj", ".ply"}) {
        INFO(ext);
        const auto out = dir / (std::string("cage") + ext);
        const auto r = test::run_cli("tessellate " + test::quoted(model) + " -o " +
                                     test::quoted(out) + " --tolerance 0.02");
        REQUIRE(r.status == 0);
        const std::string text = read_text(out);
        std::string broken;
        if (std::string(ext) == ".obj") {
            CHECK_THAT(text, Catch::Contains("\no b123d_M6-1x12-countersunk-screw\ng face_0\n"));
            broken = edit_line(text, "f ", 4, 10, [](const std::string&) { return "# dropped"; });
        } else {
            CHECK_THAT(text, Catch::Contains("property int part_id\nproperty int face_id\n"
                                             "property int solid_id\n"));
            // Turn the first triangle: "3 a b c part face solid" -> "3 a c b part face solid".
            broken = edit_line(text, "3 ", 7, 0, [](const std::string& l) {
                std::istringstream s(l);
                std::string n, a, b, c, rest;
                s >> n >> a >> b >> c;
                std::getline(s, rest);
                return n + " " + a + " " + c + " " + b + rest;
            });
        }
        const auto bad = dir / (std::string("broken") + ext);
        test::write_file(bad, broken);
        // A dropped triangle leaves a hole: a defect with --closed.
        const auto check = test::run_cli("check --closed " + test::quoted(bad));
        CHECK(check.status == 1);
        CHECK_THAT(check.out, Catch::Contains(" on face ") &&
                                  Catch::Contains("of part 0 (b123d_M6-1x12-countersunk-screw)") &&
                                  Catch::Contains("faces with defects or border loops: "));
        const auto json = test::run_cli("check --closed --json " + test::quoted(bad));
        const auto j = nlohmann::json::parse(json.out);
        REQUIRE(j.contains("defect_faces"));
        CHECK(j["defect_faces"].size() >= 1);
        CHECK(j["defect_faces"][0]["part"] == 0);
        // The unbroken file passes as before and names nothing.
        const auto good = test::run_cli("check " + test::quoted(out));
        CHECK_THAT(good.out, !Catch::Contains("faces with defects"));
    }
}
