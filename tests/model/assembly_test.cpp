// SPDX-License-Identifier: MIT
// Assemblies (model/assembly.h): written and read back by the version-2
// JSON format, validated with the field named, and flattened into one
// B-rep whose copies are the parts placed.
#include "brep_test_models.h"
#include "test_util.h"

#include <seamless/base/error.h>
#include <seamless/model/model.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

using namespace seamless;

namespace {

// The field validate_assembly names for m ("" when it passes).
std::string refused_field(const Model& m) {
    try {
        validate_assembly(m, "a.json");
    } catch (const InputError& e) {
        return e.field();
    }
    return "";
}

// The field the JSON reader names for text ("" when it reads).
std::string json_refused_field(const std::string& text) {
    try {
        parse_model_json(text, "a.json");
    } catch (const InputError& e) {
        return e.field();
    }
    return "";
}

} // namespace

TEST_CASE("Assemblies round-trip through version-2 JSON bit for bit", "[model][assembly]") {
    const Model m = test::small_assembly();
    validate_assembly(m, "a.json");
    const std::string text = to_json(m);
    CHECK(text.find("\"assembly\"") != std::string::npos);
    const Model back = parse_model_json(text, "a.json");
    CHECK(to_json(back) == text);
    REQUIRE(back.assembly.nodes.size() == m.assembly.nodes.size());
    for (size_t k = 0; k < m.assembly.nodes.size(); ++k) {
        CHECK(back.assembly.nodes[k].name == m.assembly.nodes[k].name);
        CHECK(back.assembly.nodes[k].parent == m.assembly.nodes[k].parent);
        CHECK(back.assembly.nodes[k].part == m.assembly.nodes[k].part);
        for (int i = 0; i < 12; ++i)
            CHECK(test::same_bytes(back.assembly.nodes[k].placement.m[i],
                                   m.assembly.nodes[k].placement.m[i]));
    }
    CHECK(back.assembly.colours == m.assembly.colours);
    CHECK(back.assembly.face_colours == m.assembly.face_colours);
    CHECK(back.assembly.parts.size() == 2);
    CHECK(back.assembly.parts[0].colour == 0);
    CHECK(back.assembly.parts[1].colour == -1);
}

TEST_CASE("A model without structure is written as before: no assembly member",
          "[model][assembly]") {
    const Model m = test::plate_with_hole();
    CHECK(m.assembly.empty());
    CHECK(to_json(m).find("assembly") == std::string::npos);
    CHECK(flatten_assembly(m).brep.faces.size() == m.brep.faces.size());
}

TEST_CASE("Assembly defects are refused with the field named", "[model][assembly]") {
    const auto refused = [](const Model& m, const std::string& field) {
        return refused_field(m) == field;
    };
    Model m = test::small_assembly();
    m.assembly.nodes[1].parent = 3; // a child before its parent
    CHECK(refused(m, "assembly.nodes[1].parent"));
    m = test::small_assembly();
    m.assembly.nodes[2].placement.m[5] = std::nan("");
    CHECK(refused(m, "assembly.nodes[2].placement[5]"));
    m = test::small_assembly();
    m.assembly.nodes[2].placement = AffineMap{{0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}};
    CHECK(refused(m, "assembly.nodes[2].placement"));
    m = test::small_assembly();
    m.assembly.nodes[2].part = 2;
    CHECK(refused(m, "assembly.nodes[2].part"));
    m = test::small_assembly();
    m.assembly.parts[0].face_count = 2;
    CHECK(refused(m, "assembly.parts"));
    m = test::small_assembly();
    m.assembly.colours[1].a = 1.5;
    CHECK(refused(m, "assembly.colours[1]"));
    m = test::small_assembly();
    m.assembly.face_colours = {0};
    CHECK(refused(m, "assembly.face_colours"));
    m = test::small_assembly();
    m.assembly.face_colours[1] = 7;
    CHECK(refused(m, "assembly.face_colours[1]"));
    m = test::small_assembly();
    m.brep.shells[0].faces = {1}; // the plate's shell uses the tube's face
    CHECK(refused(m, "assembly.parts[0]"));
}

TEST_CASE("Assembly JSON defects are refused with the field named", "[model][assembly]") {
    std::string text = to_json(test::small_assembly());
    const auto refused = [](const std::string& t, const std::string& field) {
        return json_refused_field(t) == field;
    };
    const std::string placement = "\"placement\": [1";
    const size_t at = text.find(placement);
    REQUIRE(at != std::string::npos);
    CHECK(refused(text.substr(0, at) + "\"placement\": [1, 2" + text.substr(at + placement.size()),
                  "assembly.nodes[0].placement"));
    const size_t colour = text.find("[1, 0, 0, 1]");
    REQUIRE(colour != std::string::npos);
    CHECK(refused(text.substr(0, colour) + "[1, 0, 0, 2]" + text.substr(colour + 12),
                  "assembly.colours[0][3]"));
    text.replace(text.find("\"version\": 2"), 12, "\"version\": 1");
    CHECK(refused(text, "brep"));
}

TEST_CASE("Flattening places every instance: copies mapped, names unique, colours resolved",
          "[model][assembly]") {
    const Model m = test::small_assembly();
    const Model flat = flatten_assembly(m);
    REQUIRE(flat.brep.faces.size() == 4); // one plate and three tubes
    CHECK(flat.surfaces.size() == 4);
    CHECK(flat.brep.shells.size() == 4);
    CHECK(flat.brep.edges.size() == 8 + 3 * 3);
    std::set<std::string> names;
    for (const BRepFace& f : flat.brep.faces) names.insert(f.name);
    CHECK(names == std::set<std::string>{"plate", "cylinder", "cylinder.2", "cylinder.3"});
    CHECK(flat.assembly.face_colours == std::vector<int>{0, 1, 1, 1});
    CHECK(!flat.assembly.has_tree());
    // tube-3: moved up 5 by "sub", then 30 along y by its own placement.
    const Vec3 p = m.surfaces[1].points[0];
    const Vec3 q = flat.surfaces[3].points[0];
    CHECK(q.x == p.x);
    CHECK(q.y == p.y + 30);
    CHECK(q.z == p.z + 5);
    // The mirrored tube turns its face.
    CHECK(flat.brep.faces[2].reversed != m.brep.faces[1].reversed);
    CHECK(flat.brep.faces[1].reversed == m.brep.faces[1].reversed);
    // Rigid placements keep tolerances: the identity exactly.
    CHECK(flat.brep.vertices[0].tolerance == m.brep.vertices[0].tolerance);
    CHECK(flat.brep.edges.back().tolerance <= m.brep.edges.back().tolerance * (1 + 1e-8));
    validate_brep(flat, "flat");
    // Flattened again: nothing left to place.
    CHECK(to_json(flatten_assembly(flat)) == to_json(flat));
}

TEST_CASE("load_model flattens an assembly unless asked to keep it", "[model][assembly]") {
    const std::filesystem::path dir = test::scratch_dir("assembly_load");
    const std::filesystem::path file = dir / "a.json";
    test::write_file(file, to_json(test::small_assembly()));
    const Model flat = load_model(file);
    CHECK(flat.brep.faces.size() == 4);
    CHECK(!flat.assembly.has_tree());
    ModelLoadOptions keep;
    keep.keep_assembly = true;
    const Model tree = load_model(file, keep);
    CHECK(tree.brep.faces.size() == 2);
    CHECK(tree.assembly.nodes.size() == 6);
}

namespace {

// small_assembly with the tube a solid, on a layer of its own.
Model with_solid_layer() {
    Model m = test::small_assembly();
    m.brep.solids.push_back({{1}, "tube solid"});
    m.assembly.parts[1].solid_count = 1;
    m.assembly.layers.push_back({"solids", true, {}, {0}, {}});
    return m;
}

} // namespace

TEST_CASE("Layers round-trip through JSON, are checked by index, and follow each copy",
          "[model][assembly]") {
    const Model m = with_solid_layer();
    validate_assembly(m, "a.json");
    const Model back = parse_model_json(to_json(m), "a.json");
    CHECK(back.assembly.layers == m.assembly.layers);
    CHECK_FALSE(back.assembly.layers[1].visible);
    CHECK(layer_faces(m, m.assembly.layers[2], false) == std::vector<int>{1});
    CHECK(layer_faces(m, m.assembly.layers[0], false).empty()); // a part only
    CHECK(layer_faces(m, m.assembly.layers[0], true) == std::vector<int>{0});

    // Placed: the part's one copy, the tube's face and solid in each of its three.
    const Model flat = flatten_assembly(m);
    const std::vector<AssemblyLayer>& placed = flat.assembly.layers;
    REQUIRE(placed.size() == 3);
    CHECK(placed[0].faces == std::vector<int>{0});
    CHECK(placed[0].parts.empty());
    CHECK(placed[1].faces == std::vector<int>{1, 2, 3});
    CHECK(placed[2].solids == std::vector<int>{0, 1, 2});
    CHECK(placed[2].faces.empty());
    validate_assembly(flat, "flat");
    for (size_t k = 0; k < placed.size(); ++k) {
        CHECK(placed[k].name == m.assembly.layers[k].name);
        CHECK(placed[k].visible == m.assembly.layers[k].visible);
        // Every copy of a face the layer covers, and nothing else.
        const std::vector<int> covered = layer_faces(m, m.assembly.layers[k], true);
        const std::vector<int> sources = {0, 1, 1, 1}; // the plate, then the tube thrice
        std::vector<int> want;
        for (size_t f = 0; f < sources.size(); ++f)
            if (std::count(covered.begin(), covered.end(), sources[f])) want.push_back(int(f));
        CHECK(layer_faces(flat, placed[k], true) == want);
    }

    Model bad = m;
    bad.assembly.layers[1].faces = {1, 2};
    CHECK(refused_field(bad) == "assembly.layers[1].faces[1]");
    bad = m;
    bad.assembly.layers[0].parts = {-1};
    CHECK(refused_field(bad) == "assembly.layers[0].parts[0]");
    bad = m;
    bad.assembly.layers[2].solids = {1};
    CHECK(refused_field(bad) == "assembly.layers[2].solids[0]");
    // And in JSON, before the B-rep is known: a negative index, a wrong type.
    const std::string text = to_json(m);
    const std::string vis = "\"visible\": false";
    const size_t at = text.find(vis);
    REQUIRE(at != std::string::npos);
    CHECK(json_refused_field(text.substr(0, at) + "\"visible\": 0" +
                             text.substr(at + vis.size())) == "assembly.layers[1].visible");
    const std::string faces = "\"faces\": [1]";
    const size_t f = text.rfind(faces); // the last layer's
    REQUIRE(f != std::string::npos);
    CHECK(json_refused_field(text.substr(0, f) + "\"faces\": [-1]" +
                             text.substr(f + faces.size())) == "assembly.layers[1].faces[0]");
}
