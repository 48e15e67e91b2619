// SPDX-License-Identifier: MIT
// Layers of STEP files read through XCAF (lib/model/step_iges/cad_layers.h),
// checked against the files' own text: each layer named in a
// PRESENTATION_LAYER_ASSIGNMENT, its solids (or whole parts) as many as the
// solids it assigns, its faces those of the shells it assigns, hidden when
// the file's INVISIBILITY names it; and the three files with overriding
// styled items, whose overrides colour faces of a part (the same in every
// instance), never an instance.
#include "test_util.h"

#include <seamless/base/files/input_file.h>
#include <seamless/model/model.h>

#include <catch2/catch.hpp>

#include <cctype>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <string>

using namespace seamless;

namespace {

std::filesystem::path corpus(const std::string& name) {
    return test::shared_dir() / "models" / "cad-corpus" / name;
}

// A STEP file's entities: "#12" -> its type and the "#k" it references.
struct Entity {
    std::string type;
    std::vector<std::string> refs;
    std::string name; // its first string argument
    std::string body; // its arguments
};

// "#12 = TYPE(body)" (records end at ';', which no name in these files holds).
std::map<std::string, Entity> entities(const std::string& file) {
    const std::string text = read_input_file(corpus(file), std::uintmax_t(1) << 30, "model");
    std::map<std::string, Entity> out;
    size_t at = text.find("DATA;");
    for (size_t end; at != std::string::npos && (end = text.find(';', at + 1)) != std::string::npos;
         at = end) {
        std::string r;
        for (size_t k = at + 1; k < end; ++k)
            if (text[k] != '\n' && text[k] != '\r') r += text[k];
        const size_t hash = r.find('#'), eq = r.find('='), open = r.find('(', eq);
        if (hash == std::string::npos || eq == std::string::npos || open == std::string::npos)
            continue;
        Entity e;
        for (size_t k = eq + 1; k < open; ++k)
            if (!std::isspace(static_cast<unsigned char>(r[k]))) e.type += r[k];
        e.body = r.substr(open + 1);
        for (size_t k = 0; k < e.body.size(); ++k)
            if (e.body[k] == '#') {
                size_t j = k + 1;
                while (j < e.body.size() && std::isdigit(static_cast<unsigned char>(e.body[j])))
                    ++j;
                e.refs.push_back(e.body.substr(k, j - k));
                k = j - 1;
            }
        const size_t q = e.body.find('\''), q2 = e.body.find('\'', q + 1);
        if (q != std::string::npos && q2 != std::string::npos &&
            e.body.find_first_not_of(" ", 0) == q)
            e.name = e.body.substr(q + 1, q2 - q - 1);
        std::string id;
        for (size_t k = hash; k < eq; ++k)
            if (!std::isspace(static_cast<unsigned char>(r[k]))) id += r[k];
        out[id] = std::move(e);
    }
    return out;
}

// What a file assigns to each named layer that a mesh keeps.
struct FileLayer {
    int solids = 0, shell_faces = 0;
    bool hidden = false;
};

std::map<std::string, FileLayer> file_layers(const std::map<std::string, Entity>& es) {
    std::map<std::string, FileLayer> out;
    std::set<std::string> hidden_assignments;
    for (const auto& [id, e] : es)
        if (e.type == "INVISIBILITY") hidden_assignments.insert(e.refs.begin(), e.refs.end());
    for (const auto& [id, e] : es) {
        if (e.type != "PRESENTATION_LAYER_ASSIGNMENT" || e.name.empty()) continue;
        FileLayer& l = out[e.name];
        l.hidden = l.hidden || hidden_assignments.count(id);
        for (const std::string& item : e.refs) {
            const auto it = es.find(item);
            if (it == es.end()) continue;
            if (it->second.type == "MANIFOLD_SOLID_BREP") ++l.solids;
            if (it->second.type == "OPEN_SHELL" || it->second.type == "CLOSED_SHELL")
                l.shell_faces += static_cast<int>(it->second.refs.size());
        }
    }
    return out;
}

// The colour a style means: the first COLOUR_RGB or predefined colour
// reached through its references.
std::optional<Rgba> style_colour(const std::map<std::string, Entity>& es, const std::string& id,
                                 int depth = 0) {
    const auto it = es.find(id);
    if (it == es.end() || depth > 12) return std::nullopt;
    const Entity& e = it->second;
    if (e.type == "COLOUR_RGB") {
        double r = 0, g = 0, b = 0;
        std::sscanf(e.body.substr(e.body.find(',') + 1).c_str(), "%lf,%lf,%lf", &r, &g, &b);
        return Rgba{r, g, b, 1};
    }
    if (e.type == "DRAUGHTING_PRE_DEFINED_COLOUR") {
        const std::map<std::string, Rgba> named = {
            {"red", {1, 0, 0, 1}},    {"green", {0, 1, 0, 1}},   {"blue", {0, 0, 1, 1}},
            {"yellow", {1, 1, 0, 1}}, {"magenta", {1, 0, 1, 1}}, {"cyan", {0, 1, 1, 1}},
            {"black", {0, 0, 0, 1}},  {"white", {1, 1, 1, 1}}};
        return named.count(e.name) ? std::optional<Rgba>(named.at(e.name)) : std::nullopt;
    }
    for (const std::string& r : e.refs)
        if (auto c = style_colour(es, r, depth + 1)) return c;
    return std::nullopt;
}

Model structured(const std::string& name) {
    ModelLoadOptions keep;
    keep.keep_assembly = true;
    return load_model(corpus(name), keep);
}

} // namespace

TEST_CASE("STEP layers: named as in the file, holding the solids and shells it assigns",
          "[model][step][layers][heavy]") {
    for (const char* file : {"nist_nist_ctc_05_asme1_ap242-e1.stp",
                             "nist_nist_ftc_07_asme1_ap242-e2.stp", "occt_as1-oc-214-mat.stp",
                             "occt_bug24283_spheres.stp", "occt_bug27453_165-174_piattello.stp",
                             "occt_bug27693_cornetta-step.stp", "occt_trj3_s1-al-214.stp",
                             "occt_trj3_s1-ct-214.stp", "pyocc_face_recognition_sample_part.stp"}) {
        INFO(file);
        const Model m = structured(file);
        const std::map<std::string, FileLayer> in_file = file_layers(entities(file));
        std::set<std::string> read;
        for (const AssemblyLayer& l : m.assembly.layers) {
            INFO(l.name);
            REQUIRE(in_file.count(l.name));
            read.insert(l.name);
            const FileLayer& f = in_file.at(l.name);
            CHECK(l.visible == !f.hidden);
            // A solid the file assigns is a whole part of a tree, else a solid.
            CHECK(static_cast<int>(l.parts.size() + l.solids.size()) == f.solids);
            CHECK(static_cast<int>(l.faces.size()) == f.shell_faces);
            for (int p : l.parts) CHECK(p < static_cast<int>(m.assembly.parts.size()));
            for (int s : l.solids) CHECK(s < static_cast<int>(m.brep.solids.size()));
            for (int k : l.faces) CHECK(k < static_cast<int>(m.brep.faces.size()));
        }
        // Every layer assigning a solid or a shell is read.
        for (const auto& [name, f] : in_file)
            if (f.solids + f.shell_faces > 0) CHECK(read.count(name));
        // Placed, the layers cover the copies of what they covered.
        const Model flat = flatten_assembly(m);
        REQUIRE(flat.assembly.layers.size() == m.assembly.layers.size());
        for (size_t k = 0; k < m.assembly.layers.size(); ++k)
            CHECK(layer_faces(flat, flat.assembly.layers[k], true).size() >=
                  layer_faces(m, m.assembly.layers[k], true).size());
    }
}

TEST_CASE("Overriding styled items colour a part's faces, the same in every instance",
          "[model][step][layers][heavy]") {
    int faces_overridden = 0;
    for (const char* file : {"nist_nist_ctc_05_asme1_ap242-e1.stp",
                             "nist_nist_ftc_07_asme1_ap242-e2.stp", "occt_trj3_s1-ct-214.stp"}) {
        INFO(file);
        const std::map<std::string, Entity> es = entities(file);
        // The faces an OVER_RIDING_STYLED_ITEM names (its item, after its
        // styles and before the item it overrides), with its surface colour.
        std::map<std::string, Rgba> overridden;
        for (const auto& [id, e] : es) {
            CHECK(e.type != "CONTEXT_DEPENDENT_OVER_RIDING_STYLED_ITEM"); // none per instance
            if (e.type != "OVER_RIDING_STYLED_ITEM" || e.refs.size() < 3) continue;
            const std::string& item = e.refs[e.refs.size() - 2];
            if (es.count(item) && es.at(item).type == "ADVANCED_FACE")
                if (auto c = style_colour(es, e.refs[0])) overridden[item] = *c;
        }
        const Model m = structured(file);
        const std::vector<int> colours = face_colours(m);
        int found = 0;
        for (size_t f = 0; f < m.brep.faces.size(); ++f) {
            const auto it = overridden.find(m.brep.faces[f].name);
            if (it == overridden.end()) continue;
            ++found;
            REQUIRE(colours[f] >= 0);
            const Rgba& c = m.assembly.colours[colours[f]];
            CHECK(c.r == Approx(it->second.r).margin(1e-3));
            CHECK(c.g == Approx(it->second.g).margin(1e-3));
            CHECK(c.b == Approx(it->second.b).margin(1e-3));
        }
        // Each overridden face read once: a part's face, not an instance's.
        CHECK(found == static_cast<int>(overridden.size()));
        faces_overridden += found;
    }
    CHECK(faces_overridden > 0); // FTC 07 and trj3 override faces
}
