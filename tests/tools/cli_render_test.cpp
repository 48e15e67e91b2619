// SPDX-License-Identifier: MIT
// seamless render's --size (tools/render.cpp): malformed and out-of-range
// sizes refused in one line naming the option, exit 2, no PNG written.
#include "test_util.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace seamless;

TEST_CASE("render --size: bad sizes are one line, exit 2, no image", "[cli]") {
    auto dir = test::scratch_dir("cli-render-size");
    const auto png = dir / "r.png";
    const std::string scene = (test::data_dir() / "scenes" / "teapot.json").string();
    const auto run = [&](const std::string& size) {
        return test::run_cli("render \"" + scene + "\" -o \"" + png.string() + "\" --size " + size);
    };
    for (const char* size : {"0x10", "16385x2", "100000x100000", "99999999999999999999x2"}) {
        INFO(size);
        auto r = run(size);
        CHECK(r.status == 2);
        CHECK(r.err == "error: --size: width and height must be in 1..16384\n");
        CHECK_FALSE(std::filesystem::exists(png));
    }
    for (const char* size : {"640x480x", "10x-3", "x"}) {
        INFO(size);
        auto r = run(size);
        CHECK(r.status == 2);
        CHECK_THAT(r.err, Catch::StartsWith("error: --size: expected WxH"));
        CHECK_FALSE(std::filesystem::exists(png));
    }
    auto ok = run("4x3");
    CHECK(ok.status == 0);
    CHECK(std::filesystem::exists(png));
}
