// SPDX-License-Identifier: MIT
// The one table of mesh formats (lib/mesh/io/mesh_formats.h).
#include <seamless/base/error.h>
#include <seamless/mesh/io/mesh_formats.h>

#include <catch2/catch.hpp>

#include <cctype>

using namespace seamless;

TEST_CASE("mesh formats: the extensions as help texts list them") {
    CHECK(mesh_extensions() == ".off .obj .ply .stl .gltf .glb");
    for (const MeshFormatInfo& f : kMeshFormats) {
        CHECK(f.extension.size() >= 4);
        CHECK(f.extension[0] == '.');
        for (char c : f.extension) CHECK(std::tolower(static_cast<unsigned char>(c)) == c);
        CHECK(mesh_format_of(f.extension) == f.format);
        CHECK(!f.name.empty());
    }
}

TEST_CASE("mesh formats: an extension is found in any case, others are refused") {
    CHECK(mesh_format_of(".STL") == MeshFormat::stl);
    CHECK(mesh_format_of(".Glb") == MeshFormat::glb);
    CHECK(is_mesh_extension(".OFF"));
    CHECK_FALSE(mesh_format_of(".json").has_value());
    CHECK_FALSE(mesh_format_of("").has_value());
    CHECK_FALSE(mesh_format_of("off").has_value()); // the dot belongs to the extension
    CHECK_FALSE(is_mesh_extension(".gltf2"));
    CHECK(mesh_format(std::filesystem::path("a/b.PLY")) == MeshFormat::ply);
    try {
        mesh_format(std::filesystem::path("out/mesh.TXT"));
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(e.file() == "out/mesh.TXT");
        CHECK(std::string(e.what()) ==
              "out/mesh.TXT: unknown mesh extension '.txt' (expected .off .obj .ply .stl .gltf "
              ".glb)");
    }
    CHECK_THROWS_AS(mesh_format(".3ds", "model.3ds"), InputError);
}
