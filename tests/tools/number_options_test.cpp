// SPDX-License-Identifier: MIT
// Numeric options (tools/number_options.h) and usage errors: one line naming
// the option and the bound, exit 2, no output file.
#include "test_util.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace seamless;

namespace {

void check_refused(const std::string& args, const std::string& option,
                   const std::filesystem::path& out) {
    INFO(args);
    auto r = test::run_cli(args);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::StartsWith("error: " + option + ": expected a finite number"));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.err.size() < 200); // no range printed up to DBL_MAX
    CHECK_FALSE(std::filesystem::exists(out));
}

} // namespace

TEST_CASE("negative, NaN and infinite lengths are refused in one line", "[cli]") {
    auto dir = test::scratch_dir("cli-number-options");
    const auto out = dir / "t.off";
    const std::string tess = "tessellate \"" + test::model_path("teapot.json").string() +
                             "\" -o \"" + out.string() + "\" ";
    for (const char* v : {"-1", "0", "nan", "inf", "-inf"})
        check_refused(tess + "--tolerance " + v, "--tolerance", out);
    for (const char* v : {"-1", "nan"}) {
        check_refused(tess + "--eps1 " + v, "--eps1", out);
        check_refused(tess + "--seam-tolerance " + v, "--seam-tolerance", out);
    }
    check_refused("check \"" + out.string() + "\" --gap nan", "--gap", out);
    check_refused("sweep \"" + test::model_path("teapot.json").string() + "\" --first-decade inf",
                  "--first-decade", out);
}

TEST_CASE("zero stays a valid seam tolerance; usage errors are one line", "[cli]") {
    auto dir = test::scratch_dir("cli-number-options-ok");
    const auto out = dir / "b.off";
    auto ok = test::run_cli("tessellate \"" + test::model_path("bilinear.json").string() +
                            "\" -o \"" + out.string() + "\" --seam-tolerance 0");
    CHECK(ok.status == 0);
    CHECK(std::filesystem::exists(out));
    auto bogus = test::run_cli("tessellate --bogus");
    CHECK(bogus.status == 2);
    CHECK_THAT(bogus.err, Catch::StartsWith("error: ") && Catch::Contains("--help"));
    CHECK(std::count(bogus.err.begin(), bogus.err.end(), '\n') == 1);
}
