// SPDX-License-Identifier: MIT
// seamless info MODEL: what a model holds.
#include "commands.h"
#include "model_options.h"

#include <seamless/model/brep_counts.h>
#include <seamless/model/model.h>
#include <seamless/spline/knot_insertion.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>

namespace seamless::cli {
namespace {

// "[0 x4, 1, 2, 3 x4]": each distinct knot with its multiplicity; long vectors elided.
std::string summarise_knots(const std::vector<double>& U) {
    std::vector<std::pair<double, int>> runs;
    for (double t : U) {
        if (!runs.empty() && runs.back().first == t)
            ++runs.back().second;
        else
            runs.push_back({t, 1});
    }
    std::ostringstream os;
    os.precision(6);
    os << '[';
    const size_t n = runs.size();
    for (size_t k = 0; k < n; ++k) {
        if (n > 8 && k == 3) {
            os << "... " << (n - 6) << " more, ";
            k = n - 3;
        }
        os << runs[k].first;
        if (runs[k].second > 1) os << " x" << runs[k].second;
        if (k + 1 < n) os << ", ";
    }
    os << ']';
    return os.str();
}

std::string plural(int n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

nlohmann::json brep_json(const BRep& b) {
    const BRepCounts c = count(b);
    nlohmann::json solids = nlohmann::json::array();
    for (const BRepSolid& s : b.solids) solids.push_back({{"name", s.name}, {"shells", s.shells}});
    return {{"solids", solids},
            {"shells", c.shells},
            {"closed_shells", c.closed_shells},
            {"faces", c.faces},
            {"faces_with_holes", c.faces_with_holes},
            {"loops", c.loops},
            {"edges", c.edges},
            {"seam_edges", c.seam_edges},
            {"degenerate_edges", c.degenerate_edges},
            {"vertices", c.vertices},
            {"max_edge_tolerance", c.max_edge_tolerance},
            {"max_vertex_tolerance", c.max_vertex_tolerance}};
}

void print_brep(const BRep& b) {
    const BRepCounts c = count(b);
    std::cout << "B-rep: " << plural(c.solids, "solid", "solids") << ", "
              << plural(c.shells, "shell", "shells") << " (" << c.closed_shells << " closed), "
              << plural(c.faces, "face", "faces") << " (" << c.faces_with_holes << " with holes), "
              << plural(c.loops, "loop", "loops") << ", " << plural(c.edges, "edge", "edges")
              << " (" << c.seam_edges << " seam, " << c.degenerate_edges << " degenerate), "
              << plural(c.vertices, "vertex", "vertices") << "; largest edge tolerance "
              << c.max_edge_tolerance << "\n";
    for (size_t k = 0; k < b.solids.size(); ++k)
        if (!b.solids[k].name.empty())
            std::cout << "solid " << k << ": " << b.solids[k].name << "\n";
}

nlohmann::json assembly_json(const Assembly& a) {
    nlohmann::json parts = nlohmann::json::array(), nodes = nlohmann::json::array(),
                   colours = nlohmann::json::array();
    for (const AssemblyPart& p : a.parts)
        parts.push_back({{"name", p.name},
                         {"faces", p.face_count},
                         {"solids", p.solid_count},
                         {"colour", p.colour}});
    for (const AssemblyNode& n : a.nodes)
        nodes.push_back({{"name", n.name},
                         {"parent", n.parent},
                         {"part", n.part},
                         {"placement", std::vector<double>(n.placement.m, n.placement.m + 12)}});
    for (const Rgba& c : a.colours) colours.push_back({c.r, c.g, c.b, c.a});
    int coloured = 0;
    for (int c : a.face_colours) coloured += c >= 0;
    return {{"parts", parts},
            {"nodes", nodes},
            {"colours", colours},
            {"instances", instance_count(a)},
            {"faces_coloured", coloured}};
}

// The tree, one node a line, indented by depth: "name (part k)" or
// "name [assembly]", with the node's offset from its parent when it has one.
void print_assembly(const Assembly& a) {
    std::cout << "assembly: " << plural(static_cast<int>(a.parts.size()), "part", "parts") << ", "
              << plural(instance_count(a), "instance", "instances") << ", "
              << plural(static_cast<int>(a.colours.size()), "colour", "colours") << "\n";
    std::vector<int> depth(a.nodes.size(), 0);
    for (size_t k = 0; k < a.nodes.size(); ++k) {
        const AssemblyNode& n = a.nodes[k];
        if (n.parent >= 0) depth[k] = depth[n.parent] + 1;
        std::cout << std::string(2 * depth[k] + 2, ' ') << n.name;
        if (n.part >= 0)
            std::cout << " (part " << n.part << ": " << a.parts[n.part].name << ", "
                      << plural(a.parts[n.part].face_count, "face", "faces") << ")";
        else
            std::cout << " [assembly]";
        const double* m = n.placement.m;
        if (m[3] != 0 || m[7] != 0 || m[11] != 0)
            std::cout << " at (" << m[3] << ", " << m[7] << ", " << m[11] << ")";
        std::cout << "\n";
    }
}

nlohmann::json layers_json(const std::vector<AssemblyLayer>& layers) {
    nlohmann::json out = nlohmann::json::array();
    for (const AssemblyLayer& l : layers)
        out.push_back({{"name", l.name},
                       {"visible", l.visible},
                       {"parts", l.parts},
                       {"solids", l.solids},
                       {"faces", l.faces}});
    return out;
}

// "3 faces (#12, #13, #14)": the count and the first few names.
std::string named_items(const std::vector<int>& items, const char* one, const char* many,
                        const std::function<std::string(int)>& name) {
    std::string s = plural(static_cast<int>(items.size()), one, many) + " (";
    const size_t shown = std::min<size_t>(items.size(), 5);
    for (size_t k = 0; k < shown; ++k) s += (k ? ", " : "") + name(items[k]);
    if (items.size() > shown) s += ", ... " + std::to_string(items.size() - shown) + " more";
    return s + ")";
}

// One line per layer: what it holds, by name.
void print_layers(const Model& m) {
    const std::vector<AssemblyLayer>& layers = m.assembly.layers;
    std::cout << plural(static_cast<int>(layers.size()), "layer", "layers") << ":\n";
    for (const AssemblyLayer& l : layers) {
        std::vector<std::string> what;
        if (!l.parts.empty())
            what.push_back(named_items(l.parts, "part", "parts",
                                       [&](int k) { return m.assembly.parts[k].name; }));
        if (!l.solids.empty())
            what.push_back(named_items(l.solids, "solid", "solids",
                                       [&](int k) { return m.brep.solids[k].name; }));
        if (!l.faces.empty())
            what.push_back(
                named_items(l.faces, "face", "faces", [&](int k) { return m.brep.faces[k].name; }));
        std::cout << "  " << l.name << (l.visible ? "" : " (hidden)") << ": ";
        for (size_t k = 0; k < what.size(); ++k) std::cout << (k ? ", " : "") << what[k];
        std::cout << (what.empty() ? "no parts, solids or faces\n" : "\n");
    }
}

} // namespace

void add_info(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand("info", "Describe a model: surfaces, degrees, knots, Bezier "
                                           "patches, B-rep solids, faces, loops and edges, "
                                           "bounding box and d_max");
    auto model = std::make_shared<std::string>();
    auto as_json = std::make_shared<bool>(false);
    auto load = std::make_shared<ModelLoadOptions>();
    cmd->add_option("MODEL", *model,
                    "model file (.json, Newell .bpt, STEP .step/.stp, IGES .iges/.igs)")
        ->required();
    cmd->add_flag("--json", *as_json, "print the report as JSON");
    add_model_options(cmd, *load);
    cmd->callback([&action, model, as_json, load] {
        action = [model, as_json, load] {
            ModelLoadOptions keep = *load;
            keep.keep_assembly = true;
            const Model tree = load_model(*model, keep);
            print_warnings(tree);
            // The rest describes the model as placed, as other commands see it.
            const Model m = flatten_assembly(tree);
            const Box3 box = control_box(m);
            int total = 0;
            nlohmann::json js;
            js["model"] = *model;
            for (size_t k = 0; k < m.surfaces.size(); ++k) {
                const BSplineSurface& s = m.surfaces[k];
                const SurfaceOrigin* origin = k < m.origins.size() ? &m.origins[k] : nullptr;
                const int patches = bezier_patch_count(s);
                total += patches;
                if (*as_json) {
                    js["surfaces"].push_back({{"name", s.name},
                                              {"degree", {s.degree_u, s.degree_v}},
                                              {"size", {s.size_u, s.size_v}},
                                              {"knots_u", s.knots_u},
                                              {"knots_v", s.knots_v},
                                              {"rational", s.rational()},
                                              {"bezier_patches", patches}});
                    if (origin)
                        js["surfaces"].back()["origin"] = {
                            {"entity", origin->entity},
                            {"kind", origin->kind},
                            {"exact", origin->exact},
                            {"approximation_error", origin->approximation_error}};
                } else {
                    std::cout << s.name << ": degree " << s.degree_u << "x" << s.degree_v
                              << ", net " << s.size_u << "x" << s.size_v << ", "
                              << (s.rational() ? "rational" : "polynomial") << ", knots_u "
                              << summarise_knots(s.knots_u) << ", knots_v "
                              << summarise_knots(s.knots_v) << ", " << patches << " Bezier patch"
                              << (patches == 1 ? "" : "es");
                    if (origin) {
                        std::cout << ", from " << origin->kind;
                        if (origin->exact)
                            std::cout << " (exact)";
                        else
                            std::cout << " (approximated, error " << origin->approximation_error
                                      << ")";
                    }
                    std::cout << "\n";
                }
            }
            const double dmax = box.max_extent();
            if (*as_json) {
                js["surface_count"] = m.surfaces.size();
                js["bezier_patches"] = total;
                js["bbox"] = {{"min", {box.lo.x, box.lo.y, box.lo.z}},
                              {"max", {box.hi.x, box.hi.y, box.hi.z}}};
                js["d_max"] = dmax;
                if (!m.brep.empty()) js["brep"] = brep_json(m.brep);
                if (tree.assembly.has_tree()) js["assembly"] = assembly_json(tree.assembly);
                if (!tree.assembly.layers.empty()) js["layers"] = layers_json(tree.assembly.layers);
                js["warnings"] = m.warnings;
                std::cout << js.dump(2) << "\n";
            } else {
                std::cout.precision(10);
                std::cout << m.surfaces.size() << " surface" << (m.surfaces.size() == 1 ? "" : "s")
                          << ", " << total << " Bezier patches\n"
                          << "bbox of control points: [" << box.lo.x << ", " << box.lo.y << ", "
                          << box.lo.z << "] .. [" << box.hi.x << ", " << box.hi.y << ", "
                          << box.hi.z << "]\n"
                          << "d_max: " << dmax << "\n";
                if (!m.brep.empty()) print_brep(m.brep);
                if (tree.assembly.has_tree()) print_assembly(tree.assembly);
                if (!tree.assembly.layers.empty()) print_layers(tree);
            }
            return 0;
        };
    });
}

} // namespace seamless::cli
