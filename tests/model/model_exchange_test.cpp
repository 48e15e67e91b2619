// SPDX-License-Identifier: MIT
// The binary model form of the STEP/IGES reader's answer (model_exchange.h):
// every member of Model comes back bit for bit, and damaged answers are
// refused with one line, never read out of bounds.
#include "model/brep_test_models.h"
#include "test_util.h"

#include <seamless/base/error.h>
#include <seamless/base/files/input_file.h>
#include <seamless/model/model_exchange.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>

using namespace seamless;

namespace {

// A model with every member set, including what JSON cannot carry: bytes
// that are not UTF-8 in names, -0.0, a subnormal, the origins and warnings.
Model full_model() {
    Model m = test::plate_with_hole();
    m.source = "part.step";
    m.surfaces[0].name = std::string("face \xff\xfe #12", 11);
    m.surfaces[0].knots_u = {-0.0, -0.0, 1, 1};
    m.surfaces[0].points[0].x = 4.9e-324;
    m.surfaces[0].weights = {1, 0.5, 2, 1.0 / 3};
    m.origins = {{"#12", "plane", false, 1.0 / 7}};
    m.warnings = {"part.step: approximated 1 surface", std::string("a\0b", 3)};
    m.brep.solids.push_back({{0}, "solid \x80"});
    m.brep.shells.insert(m.brep.shells.begin(), BRepShell{{0}, true});
    m.brep.edges[0].curve = -1; // degenerate
    return m;
}

bool same(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

std::string error_of(const std::string& bytes, const ModelLimits& limits = {}) {
    try {
        read_model_exchange(bytes, "x.step", limits);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST_CASE("The exchange form carries every member of a model bit for bit", "[model][exchange]") {
    const Model m = full_model();
    const std::string bytes = write_model_exchange(m);
    const Model r = read_model_exchange(bytes, "x.step");
    // Written again, the same bytes: nothing lost or reordered.
    CHECK(write_model_exchange(r) == bytes);
    CHECK(r.source == m.source);
    CHECK(r.surfaces[0].name == m.surfaces[0].name);
    CHECK(same(r.surfaces[0].knots_u, m.surfaces[0].knots_u));
    CHECK(std::signbit(r.surfaces[0].knots_u[0]));
    CHECK(r.surfaces[0].points[0].x == 4.9e-324);
    CHECK(same(r.surfaces[0].weights, m.surfaces[0].weights));
    REQUIRE(r.origins.size() == 1);
    CHECK(r.origins[0].entity == "#12");
    CHECK(r.origins[0].kind == "plane");
    CHECK_FALSE(r.origins[0].exact);
    CHECK(r.origins[0].approximation_error == 1.0 / 7);
    CHECK(r.warnings == m.warnings);
    CHECK(r.brep.solids[0].name == m.brep.solids[0].name);
    CHECK(r.brep.edges[0].curve == -1);
    CHECK(r.brep.faces.size() == m.brep.faces.size());
    CHECK(r.brep.shells[0].closed);
}

TEST_CASE("The exchange form carries an assembly: parts, placed nodes, colours and layers",
          "[model][exchange]") {
    const Model m = test::small_assembly();
    REQUIRE(m.assembly.has_tree());
    const std::string bytes = write_model_exchange(m);
    const Model r = read_model_exchange(bytes, "x.step");
    CHECK(write_model_exchange(r) == bytes);
    REQUIRE(r.assembly.parts.size() == m.assembly.parts.size());
    REQUIRE(r.assembly.nodes.size() == m.assembly.nodes.size());
    for (size_t k = 0; k < m.assembly.nodes.size(); ++k) {
        CHECK(r.assembly.nodes[k].name == m.assembly.nodes[k].name);
        CHECK(r.assembly.nodes[k].parent == m.assembly.nodes[k].parent);
        CHECK(r.assembly.nodes[k].part == m.assembly.nodes[k].part);
        CHECK(std::memcmp(r.assembly.nodes[k].placement.m, m.assembly.nodes[k].placement.m,
                          sizeof(double) * 12) == 0);
    }
    CHECK(r.assembly.colours == m.assembly.colours);
    CHECK(r.assembly.face_colours == m.assembly.face_colours);
    CHECK(r.assembly.solid_colours == m.assembly.solid_colours);
    REQUIRE(!m.assembly.layers.empty());
    CHECK(r.assembly.layers == m.assembly.layers);
    // A node naming a part that is not there is refused by name, and a layer's face.
    Model bad = m;
    bad.assembly.nodes.back().part = 99;
    CHECK_THAT(error_of(write_model_exchange(bad)), Catch::Contains("assembly.nodes["));
    bad = m;
    bad.assembly.layers.back().faces = {0, 5};
    CHECK_THAT(error_of(write_model_exchange(bad)),
               Catch::Contains("assembly.layers[1].faces[1]: index 5 out of range"));
}

TEST_CASE("The streamed form is the written form, its size known beforehand", "[model][exchange]") {
    // A surface of 1.2 MB of points: an array larger than a piece goes out
    // whole, the small members around it in pieces.
    Model m = full_model();
    BSplineSurface& s = m.surfaces[0];
    s.size_u = s.size_v = 224;
    s.knots_u = s.knots_v = {};
    for (int k = 0; k < 224 + s.degree_u + 1; ++k)
        s.knots_u.push_back(std::clamp(k - s.degree_u, 0, 224 - s.degree_u));
    s.knots_v = s.knots_u;
    s.points.assign(224 * 224, Vec3{1, 2, 3});
    s.weights.clear();
    const std::string bytes = write_model_exchange(m);
    REQUIRE(bytes.size() > (std::size_t(1) << 20));
    CHECK(model_exchange_size(m) == bytes.size());
    std::string streamed;
    int pieces = 0;
    CHECK(write_model_exchange(m, [&](const char* p, std::size_t n) {
        streamed.append(p, n);
        ++pieces;
        return true;
    }));
    CHECK(streamed == bytes);
    CHECK(pieces >= 3);
    CHECK(write_model_exchange(read_model_exchange(bytes, "x.step")) == bytes);
    // A sink that refuses: no more pieces, and false.
    int offered = 0;
    CHECK_FALSE(write_model_exchange(m, [&](const char*, std::size_t) {
        ++offered;
        return false;
    }));
    CHECK(offered == 1);
}

TEST_CASE("Every truncation and every flipped byte of an answer is refused or read whole",
          "[model][exchange]") {
    const std::string bytes = write_model_exchange(full_model());
    for (size_t n = 0; n < bytes.size(); ++n) {
        const std::string e = error_of(bytes.substr(0, n));
        INFO(n);
        CHECK_THAT(e, Catch::StartsWith("x.step: exchange"));
    }
    int refused = 0;
    for (size_t k = 0; k < bytes.size(); ++k) {
        std::string b = bytes;
        b[k] = static_cast<char>(b[k] ^ 0x80);
        const std::string e = error_of(b);
        refused += !e.empty();
        if (!e.empty()) CHECK_THAT(e, Catch::StartsWith("x.step: exchange"));
    }
    CHECK(refused > 0);
    CHECK_THAT(error_of(bytes + "x"), Catch::Contains("1 bytes after the model"));
}

TEST_CASE("Every truncation of an assembly's tail, its layers last, is refused",
          "[model][exchange]") {
    const std::string tree = write_model_exchange(test::small_assembly());
    for (size_t n = tree.size() - 200; n < tree.size(); ++n) {
        INFO(n);
        CHECK_THAT(error_of(tree.substr(0, n)), Catch::StartsWith("x.step: exchange.assembly"));
    }
}

TEST_CASE("Hostile counts in an answer are refused before anything is allocated",
          "[model][exchange]") {
    std::string bytes = write_model_exchange(full_model());
    const std::string tag = "seamless-model-exchange 2\n";
    // The source's length, then the surface count: 2^62 surfaces.
    const size_t count_at = tag.size() + 8 + std::strlen("part.step");
    const std::uint64_t huge = std::uint64_t(1) << 62;
    std::memcpy(&bytes[count_at], &huge, 8);
    CHECK_THAT(error_of(bytes), Catch::Contains("exchange.surfaces: 4611686018427387904 items "
                                                "exceed the limit of 1000000"));
    ModelLimits tight;
    tight.max_brep_items = 2;
    CHECK_THAT(error_of(write_model_exchange(full_model()), tight),
               Catch::Contains("exchange.brep.vertices: 8 items exceed the limit of 2"));
}

TEST_CASE("fuzz_model_exchange's seeds are answers in this build's form, layers among them",
          "[model][exchange]") {
    const auto seeds = test::data_dir() / ".." / "tests" / "fuzz" / "corpus" / "model_exchange";
    int read = 0, with_layers = 0;
    for (const auto& entry : std::filesystem::directory_iterator(seeds)) {
        INFO(entry.path());
        const std::string bytes =
            read_input_file(entry.path(), std::uintmax_t(1) << 24, "fuzz seed");
        const Model m = read_model_exchange(bytes, entry.path().string());
        CHECK(write_model_exchange(m) == bytes);
        ++read;
        with_layers += !m.assembly.layers.empty();
    }
    CHECK(read > 0);
    CHECK(with_layers > 0);
}
