// SPDX-License-Identifier: MIT
// The STEP/IGES reader's limits on the command line (--reader-time-limit,
// --reader-memory-limit; tools/model_options.h): every command that reads
// models takes them, a read past the time limit ends with exit 2 and one line
// naming the file and the limit, so does one past the memory limit, and bad
// values are refused in one line.
#include "test_util.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>

using namespace seamless;

// One line: the error, nothing before it.
static bool one_line(const std::string& s) {
    return std::count(s.begin(), s.end(), '\n') == 1;
}

TEST_CASE("A corpus file read past --reader-time-limit ends with exit 2 and one line naming it",
          "[cli][cad][heavy]") {
    const auto dir = test::scratch_dir("cli-reader-time-limit");
    const auto f = test::shared_dir() / "models" / "cad-corpus" / "ksu_dip_8_300.step";
    REQUIRE(std::filesystem::exists(f));
    const auto scene = dir / "scene.json";
    test::write_file(scene, R"({"version": 1, "camera": {"eye": [0, -50, 10], "look_at": [0, 0, 0]},
        "objects": [{"model": )" +
                                test::quoted(f) + "}]}");
    const auto out = dir / "out";
    const std::string limit = " --reader-time-limit 0.001";
    for (const std::string& cmd :
         {"info " + test::quoted(f),
          "tessellate " + test::quoted(f) + " -o " + test::quoted(out.string() + ".glb"),
          "convert " + test::quoted(f) + " -o " + test::quoted(out.string() + ".json"),
          "render " + test::quoted(scene) + " -o " + test::quoted(out.string() + ".png") +
              " --method tray",
          "sweep " + test::quoted(f) + " --decades 0"}) {
        INFO(cmd);
        const auto r = test::run_cli(cmd + limit);
        CHECK(r.status == 2);
        CHECK(one_line(r.err));
        CHECK_THAT(r.err,
                   Catch::StartsWith("error: " + f.string() + ": ") &&
                       Catch::Contains("took longer than the time limit of 0.001 s reading it"));
    }
    for (const char* ext : {".glb", ".json", ".png"})
        CHECK_FALSE(std::filesystem::exists(out.string() + ext));
}

TEST_CASE("A read past a small --reader-memory-limit ends with exit 2 and one line naming the "
          "file and the limit",
          "[cli][cad][heavy][native-allocator]") {
    // OpenCASCADE's STEP reader would call 11752 unreadable under 64 MiB.
    const auto f = test::shared_dir() / "models" / "cad-corpus" / "pyocc_11752.stp";
    REQUIRE(std::filesystem::exists(f));
    const auto r = test::run_cli("info " + test::quoted(f) + " --reader-memory-limit 64M");
    CHECK(r.status == 2);
    CHECK(one_line(r.err));
    CHECK(r.err == "error: " + f.string() +
                       ": OpenCASCADE ran out of memory reading it (the reader's limit is 64 MiB, "
                       "ModelLoadOptions::reader_memory_limit)\n");
}

TEST_CASE("Bad reader limits are refused in one line naming the option; good ones are taken",
          "[cli][heavy]") {
    const std::string model = test::quoted(test::model_path("bilinear.json"));
    for (const char* v : {"-1", "nan", "inf", "1e999", "ten"}) {
        INFO(v);
        const auto r = test::run_cli("info " + model + " --reader-time-limit " + v);
        CHECK(r.status == 2);
        CHECK(one_line(r.err));
        CHECK_THAT(r.err,
                   Catch::StartsWith("error: --reader-time-limit: expected a finite number"));
    }
    for (const char* v :
         {"-1", "1.5G", "4GB", "12Q", "G", "99999999999G", "99999999999999999999"}) {
        INFO(v);
        const auto r = test::run_cli("info " + model + " --reader-memory-limit " + v);
        CHECK(r.status == 2);
        CHECK(one_line(r.err));
        CHECK_THAT(r.err, Catch::StartsWith("error: --reader-memory-limit: expected bytes"));
    }
    // A JSON model does not start the reader; the values are accepted.
    for (const char* v : {"0", "4096", "512k", "64M", "4G", "1T"}) {
        INFO(v);
        CHECK(test::run_cli("info " + model + " --reader-memory-limit " + v).status == 0);
    }
    CHECK(test::run_cli("info " + model + " --reader-time-limit 0").status == 0);
}
