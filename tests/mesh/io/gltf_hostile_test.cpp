// SPDX-License-Identifier: MIT
// Regressions of issue 12 in the glTF reader: offsets that wrap size_t (1),
// nesting that overflowed tinygltf's recursive parser (2), one accessor
// shared by many primitives (9), images decoded for nothing (10).
#include "test_util.h"

#include <seamless/base/error.h>
#include <seamless/mesh/io/mesh_io.h>

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <string>

using namespace seamless;

namespace {

std::string base64(const std::string& in) {
    static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    size_t i = 0;
    for (; i + 2 < in.size(); i += 3) {
        const uint32_t v = (uint8_t(in[i]) << 16) | (uint8_t(in[i + 1]) << 8) | uint8_t(in[i + 2]);
        for (int k = 18; k >= 0; k -= 6) out += t[(v >> k) & 63];
    }
    if (i + 1 == in.size()) {
        const uint32_t v = uint8_t(in[i]) << 16;
        out += std::string{t[(v >> 18) & 63], t[(v >> 12) & 63], '=', '='};
    } else if (i + 2 == in.size()) {
        const uint32_t v = (uint8_t(in[i]) << 16) | (uint8_t(in[i + 1]) << 8);
        out += std::string{t[(v >> 18) & 63], t[(v >> 12) & 63], t[(v >> 6) & 63], '='};
    }
    return out;
}

template <class T> void put(std::string& s, T v) {
    s.append(reinterpret_cast<const char*>(&v), sizeof v);
}

// A buffer with `n` triangles of a fan: positions (float32 VEC3) then uint32
// indices, and a .gltf that embeds it. `view_offset` and `accessor_offset`
// are written as given (decimal text: they may exceed 2^53). `primitives`
// copies of one primitive share the accessors; `extra` is inserted as the
// document's last member.
struct Gltf {
    int triangles = 1;
    std::string view_offset = "0", accessor_offset = "0";
    int primitives = 1;
    std::string extra;
    std::string text() const {
        std::string buf;
        const int nv = triangles + 2;
        for (int i = 0; i < nv; ++i) {
            put<float>(buf, static_cast<float>(i % 7));
            put<float>(buf, static_cast<float>(i / 7));
            put<float>(buf, static_cast<float>(i % 3));
        }
        const size_t pos_bytes = buf.size();
        for (int t = 0; t < triangles; ++t) {
            put<uint32_t>(buf, 0);
            put<uint32_t>(buf, t + 1);
            put<uint32_t>(buf, t + 2);
        }
        std::string prims;
        for (int p = 0; p < primitives; ++p)
            prims += std::string(p ? "," : "") + R"({"attributes": {"POSITION": 0}, "indices": 1})";
        return R"({"asset": {"version": "2.0"},
  "buffers": [{"byteLength": )" +
               std::to_string(buf.size()) + R"(, "uri": "data:application/octet-stream;base64,)" +
               base64(buf) + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": )" +
               view_offset + R"(, "byteLength": )" + std::to_string(pos_bytes) + R"(},
                  {"buffer": 0, "byteOffset": )" +
               std::to_string(pos_bytes) + R"(, "byteLength": )" +
               std::to_string(buf.size() - pos_bytes) + R"(}],
  "accessors": [{"bufferView": 0, "byteOffset": )" +
               accessor_offset + R"(, "componentType": 5126, "count": )" + std::to_string(nv) +
               R"(, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5125, "count": )" +
               std::to_string(3 * triangles) + R"(, "type": "SCALAR"}],
  "meshes": [{"primitives": [)" +
               prims + R"(]}])" + extra + "}";
    }
};

} // namespace

TEST_CASE("glTF byteOffset near 2^64 is refused, not read before the buffer", "[gltf][hostile]") {
    const auto dir = test::scratch_dir("gltf-offset-wraps");
    Gltf ok;
    test::write_file(dir / "ok.gltf", ok.text());
    CHECK(read_mesh(dir / "ok.gltf").triangle_count() == 1);
    for (auto [view, accessor] : {std::pair{"18446744073709511616", "0"}, // 2^64 - 40000
                                  std::pair{"0", "18446744073709551600"}, // 2^64 - 16
                                  std::pair{"18446744073709551612", "8"}}) {
        Gltf g;
        g.view_offset = view;
        g.accessor_offset = accessor;
        INFO(view << " + " << accessor);
        test::write_file(dir / "wraps.gltf", g.text());
        CHECK_THROWS_AS(read_mesh(dir / "wraps.gltf"), InputError);
    }
}

// Found by fuzz_glb in the CI smoke run: an accessor of 0 elements was not
// checked, and its byteOffset near 2^64 moved the element pointer before the
// buffer (undefined behaviour UBSan reports, in the sanitizer run of this test).
TEST_CASE("glb accessor of 0 elements with a byteOffset near 2^64 is refused", "[gltf][hostile]") {
    const std::filesystem::path file = std::filesystem::path(SEAMLESS_SOURCE_DIR) / "tests" /
                                       "fuzz" / "corpus" / "glb" /
                                       "empty-accessor-offset-wraps.glb";
    REQUIRE(std::filesystem::is_regular_file(file));
    CHECK_THROWS_AS(read_mesh(file), InputError);
}

TEST_CASE("glTF nested 200,000 levels deep is refused before parsing, no stack overflow",
          "[gltf][hostile][cli]") {
    const auto dir = test::scratch_dir("gltf-deep-nesting");
    Gltf g;
    g.extra = R"(, "extras": )" + std::string(200000, '[') + std::string(200000, ']');
    test::write_file(dir / "deep.gltf", g.text());
    const auto r = test::run_cli("check \"" + (dir / "deep.gltf").string() + "\"", "gltf-deep");
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("deep.gltf: JSON nested deeper than 64 levels"));
    // Nesting a real file uses is fine.
    g.extra = R"(, "extras": )" + std::string(30, '[') + std::string(30, ']');
    test::write_file(dir / "shallow.gltf", g.text());
    CHECK(read_mesh(dir / "shallow.gltf").triangle_count() == 1);
}

TEST_CASE("glb primitives sharing one accessor read it once and cannot multiply the output",
          "[gltf][hostile]") {
    const auto dir = test::scratch_dir("gltf-shared-accessor");
    Gltf two;
    two.primitives = 2;
    test::write_file(dir / "two.gltf", two.text());
    const TriangleMesh m = read_mesh(dir / "two.gltf");
    CHECK(m.vertex_count() == 3); // the positions once, not once per primitive
    CHECK(m.triangle_count() == 2);
    // 400 primitives over 2,000 triangles: 800,000 triangles from a 64 KB file.
    Gltf many;
    many.triangles = 2000;
    many.primitives = 400;
    test::write_file(dir / "many.gltf", many.text());
    try {
        read_mesh(dir / "many.gltf");
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK_THAT(std::string(e.what()), Catch::Contains("one per byte of the file"));
    }
}

TEST_CASE("glTF images are not decoded: an undecodable image does not stop reading",
          "[gltf][hostile]") {
    const auto dir = test::scratch_dir("gltf-image");
    // A PNG signature and a header claiming 16000 x 16000 pixels, then nothing:
    // a decoder would fail (or, completed, allocate 768 MB); the mesh needs none.
    std::string png = "\x89PNG\r\n\x1a\n";
    png += std::string("\0\0\0\x0dIHDR", 8);
    png += std::string("\0\0\x3e\x80\0\0\x3e\x80\x08\x02\0\0\0", 13);
    png += std::string("\0\0\0\0", 4);
    Gltf g;
    g.extra = R"(, "images": [{"uri": "data:image/png;base64,)" + base64(png) + R"("}])";
    test::write_file(dir / "image.gltf", g.text());
    CHECK(read_mesh(dir / "image.gltf").triangle_count() == 1);
}

TEST_CASE("glTF external buffers must be regular files", "[gltf][hostile]") {
    const auto dir = test::scratch_dir("gltf-external");
    Gltf g;
    std::string t = g.text();
    const auto at = t.find("data:application");
    t.replace(at, t.find('"', at) - at, "/dev/zero");
    test::write_file(dir / "zero.gltf", t);
    CHECK_THROWS_AS(read_mesh(dir / "zero.gltf"), InputError);
}
