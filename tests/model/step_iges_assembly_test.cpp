// SPDX-License-Identifier: MIT
// STEP assemblies and colours read through XCAF (lib/model/step_iges/
// cad_structure.h, assembly_reader.h): each part once in its own
// coordinates, the tree's nodes named as in the file, placed copies equal
// to the flattened read, KiCad's and OpenCASCADE's coloured parts keep
// their colours.
#include "test_util.h"

#include <seamless/base/files/input_file.h>
#include <seamless/model/model.h>

#include <catch2/catch.hpp>

#include <set>
#include <string>

using namespace seamless;

namespace {

std::filesystem::path corpus(const std::string& name) {
    return test::shared_dir() / "models" / "cad-corpus" / name;
}

Model structured(const std::string& name) {
    ModelLoadOptions keep;
    keep.keep_assembly = true;
    return load_model(corpus(name), keep);
}

// How often `what` occurs in the file's text.
int occurrences(const std::string& name, const std::string& what) {
    const std::string text = read_input_file(corpus(name), std::uintmax_t(1) << 30, "model");
    int n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

bool named_in_file(const std::string& file, const std::string& name) {
    return occurrences(file, "'" + name + "'") > 0;
}

} // namespace

TEST_CASE("STEP assemblies keep their tree: each part once, every node named as in the file",
          "[model][step][assembly][heavy]") {
    for (const char* file : {"occt_as1-oc-214-mat.stp", "occt_trj3_s1-ct-214.stp"}) {
        INFO(file);
        const Model m = structured(file);
        const Assembly& a = m.assembly;
        REQUIRE(a.has_tree());
        // Each part's faces once: as many as the file has face entities.
        CHECK(static_cast<int>(m.brep.faces.size()) == occurrences(file, "ADVANCED_FACE"));
        std::set<std::string> part_names;
        for (const AssemblyPart& p : a.parts) {
            CHECK(named_in_file(file, p.name));
            CHECK(p.face_count > 0);
            part_names.insert(p.name);
        }
        CHECK(part_names.size() == a.parts.size()); // distinct products, each once
        int placed_faces = 0;
        for (const AssemblyNode& n : a.nodes) {
            CHECK(named_in_file(file, n.name));
            if (n.part >= 0) placed_faces += a.parts[n.part].face_count;
        }
        CHECK(instance_count(a) > static_cast<int>(a.parts.size())); // parts used more than once
        // The flattened model is every instance placed, and what load_model gives.
        const Model flat = flatten_assembly(m);
        CHECK(static_cast<int>(flat.brep.faces.size()) == placed_faces);
        const Model loaded = load_model(corpus(file));
        CHECK(!loaded.assembly.has_tree());
        CHECK(to_json(loaded) == to_json(flat));
        // Structure crosses JSON v2 as it is.
        CHECK(to_json(parse_model_json(to_json(m), file)) == to_json(m));
    }
}

TEST_CASE("A KiCad part keeps its black body and metal pins; OpenCASCADE's abc part its colours",
          "[model][step][assembly][heavy]") {
    const Model dip = structured("ksu_dip_8_300.step");
    const std::vector<int> colours = face_colours(dip);
    bool dark = false, light = false;
    for (int c : colours) {
        REQUIRE(c >= 0); // every face coloured
        const Rgba& rgba = dip.assembly.colours[c];
        dark = dark || (rgba.r < 0.3 && rgba.g < 0.3 && rgba.b < 0.3);
        light = light || (rgba.r > 0.8 && rgba.g > 0.8 && rgba.b > 0.8);
    }
    CHECK(dark);
    CHECK(light);

    const char* abc = "occt_bug32596_abc_0_13.step";
    const Model m = load_model(corpus(abc)); // flattened: the colours stay per face
    const std::vector<int> faces = face_colours(m);
    int coloured = 0;
    for (int c : faces) coloured += c >= 0;
    CHECK(coloured == occurrences(abc, "COLOUR_RGB"));
    for (const Rgba& c : m.assembly.colours) CHECK(c.r > c.g);
}
