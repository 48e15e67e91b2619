// SPDX-License-Identifier: MIT
// Regressions of issue 12 in the text mesh readers: PLY numbers converted to
// integers before their range was checked (3), OBJ and ASCII STL files of
// garbage or nothing that passed as clean empty meshes (14), and a folder
// given as a mesh (15).
#include "test_util.h"

#include <seamless/base/error.h>
#include <seamless/mesh/io/mesh_io.h>

#include <catch2/catch.hpp>

using namespace seamless;

namespace {

// The message read_mesh gives for `text` stored as `name`, or "" if it reads.
std::string error_for(const std::filesystem::path& dir, const std::string& name,
                      const std::string& text) {
    test::write_file(dir / name, text);
    try {
        read_mesh(dir / name);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST_CASE("PLY list count nan and index 1e300 are refused before converting to integers",
          "[ply][hostile]") {
    const auto dir = test::scratch_dir("ply-float-to-int");
    // The 72-byte reproducer of the probe.
    CHECK_THAT(error_for(dir, "nan.ply",
                         "ply\nformat ascii 1.0\nelement a 1\nproperty list float int b\n"
                         "end_header\nnan\n"),
               Catch::Contains("a 0: list count nan is not an integer"));
    const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n"
                             "property double y\nproperty double z\nelement face 1\n"
                             "property list uchar double vertex_indices\nend_header\n"
                             "0 0 0\n1 0 0\n0 1 0\n";
    CHECK_THAT(error_for(dir, "huge.ply", head + "3 0 1 1e300\n"),
               Catch::Contains("face 0: vertex index 1e+300 is not an index in [0, 3)"));
    CHECK_THAT(error_for(dir, "inf.ply", head + "3 0 1 inf\n"),
               Catch::Contains("vertex index inf"));
    CHECK_THAT(error_for(dir, "half.ply", head + "3 0 1 1.5\n"),
               Catch::Contains("vertex index 1.5"));
    CHECK_THAT(error_for(dir, "count.ply",
                         "ply\nformat ascii 1.0\nelement a 1\nproperty list double int b\n"
                         "end_header\n2.5 1 2\n"),
               Catch::Contains("list count 2.5"));
    CHECK(error_for(dir, "ok.ply", head + "3 0 1 2\n").empty());
}

TEST_CASE("Empty or garbage OBJ and 'solid' + garbage STL are errors, never clean empty meshes",
          "[obj][stl][hostile][cli]") {
    const auto dir = test::scratch_dir("garbage-meshes");
    CHECK_THAT(error_for(dir, "empty.obj", ""), Catch::Contains("empty.obj: holds no triangles"));
    CHECK_THAT(error_for(dir, "comments.obj", "# only a comment\n\n"),
               Catch::Contains("holds no triangles"));
    CHECK_THAT(error_for(dir, "garbage.obj", "v 0 0 0\nhello world\n"),
               Catch::Contains("garbage.obj: line 2: unknown OBJ statement 'hello'"));
    CHECK_THAT(error_for(dir, "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"),
               Catch::Contains("holds no triangles"));
    CHECK_THAT(error_for(dir, "garbage.stl", "solid x\nthis is garbage\n"),
               Catch::Contains("garbage.stl: line 2: expected 'facet' or 'endsolid', got 'this'"));
    CHECK_THAT(error_for(dir, "empty.stl", "solid x\nendsolid x\n"),
               Catch::Contains("holds no triangles"));
    CHECK_THAT(error_for(dir, "unended.stl", "solid x\n"), Catch::Contains("no 'endsolid'"));
    CHECK_THAT(error_for(dir, "four.stl",
                         "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                         "vertex 0 1 0\nvertex 1 1 0\nendloop\nendfacet\nendsolid\n"),
               Catch::Contains("more than 3 vertices"));
    CHECK_THAT(error_for(dir, "empty.off", "OFF\n0 0 0\n"), Catch::Contains("holds no triangles"));
    // What real files hold still reads: statements without triangles, a BOM,
    // several solids, CRLF line ends.
    CHECK(error_for(dir, "ok.obj",
                    "\xEF\xBB\xBFmtllib a.mtl\no x\nv 0 0 0\r\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
                    "usemtl m\ns off\nf 1/1/1 2/1/1 3/1/1\nl 1 2\n")
              .empty());
    const std::string facet = "facet normal 0 0 1\r\n outer loop\r\n  vertex 0 0 0\r\n"
                              "  vertex 1 0 0\r\n  vertex 0 1 0\r\n endloop\r\nendfacet\r\n";
    CHECK(error_for(dir, "ok.stl",
                    "solid a\r\n" + facet + "endsolid a\r\nsolid b\n" + facet + "endsolid\n")
              .empty());
    // And the CLI: exit 2, not PASS.
    for (const char* name : {"empty.obj", "garbage.obj", "garbage.stl"}) {
        const auto r = test::run_cli("check \"" + (dir / name).string() + "\"", "garbage-meshes");
        INFO(name << ": " << r.out << r.err);
        CHECK(r.status == 2);
        CHECK(r.out.find("PASS") == std::string::npos);
    }
}

TEST_CASE("A folder given as a mesh says it is a folder", "[hostile][cli]") {
    const auto dir = test::scratch_dir("mesh-folder");
    std::filesystem::create_directories(dir / "m.off");
    const auto r = test::run_cli("check \"" + (dir / "m.off").string() + "\"", "mesh-folder");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("m.off: is a directory, not a mesh file"));
}
