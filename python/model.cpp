// SPDX-License-Identifier: MIT
// seamless.load_model and seamless.Model: what `seamless info` reports of a
// model (surfaces, Bezier patches, bounding box of the control points, d_max,
// B-rep counts), the model itself kept for tessellate().
#include "bindings.h"
#include "model_binding.h"

#include <seamless/base/error.h>
#include <seamless/model/brep_counts.h>
#include <seamless/spline/knot_insertion.h>

#include <pybind11/stl.h>

#include <memory>

namespace seamless::python {
namespace {

py::tuple point(Vec3 p) {
    return py::make_tuple(p.x, p.y, p.z);
}

// The "brep" object of `seamless info --json`.
py::object brep_dict(const BRep& b) {
    if (b.empty()) return py::none();
    const BRepCounts c = count(b);
    py::list solids;
    for (const BRepSolid& s : b.solids)
        solids.append(py::dict(py::arg("name") = s.name, py::arg("shells") = s.shells));
    return py::dict(py::arg("solids") = solids, py::arg("shells") = c.shells,
                    py::arg("closed_shells") = c.closed_shells, py::arg("faces") = c.faces,
                    py::arg("faces_with_holes") = c.faces_with_holes, py::arg("loops") = c.loops,
                    py::arg("edges") = c.edges, py::arg("seam_edges") = c.seam_edges,
                    py::arg("degenerate_edges") = c.degenerate_edges,
                    py::arg("vertices") = c.vertices,
                    py::arg("max_edge_tolerance") = c.max_edge_tolerance,
                    py::arg("max_vertex_tolerance") = c.max_vertex_tolerance);
}

int patch_count(const Model& m) {
    int n = 0;
    for (const BSplineSurface& s : m.surfaces) n += bezier_patch_count(s);
    return n;
}

} // namespace

ModelLoadOptions load_options(const std::string& trimmed) {
    ModelLoadOptions options;
    if (trimmed == "brep")
        options.trimmed = TrimmedFaces::brep;
    else if (trimmed == "refuse")
        options.trimmed = TrimmedFaces::refuse;
    else if (trimmed == "skip")
        options.trimmed = TrimmedFaces::skip;
    else if (trimmed == "whole_surface")
        options.trimmed = TrimmedFaces::whole_surface;
    else
        throw InputError("", "trimmed",
                         "expected 'brep', 'refuse', 'skip' or 'whole_surface', got '" + trimmed +
                             "'");
    return options;
}

std::shared_ptr<Model> load(const std::string& path, const std::string& trimmed) {
    const ModelLoadOptions options = load_options(trimmed);
    const py::gil_scoped_release release; // STEP/IGES files take seconds
    return std::make_shared<Model>(load_model(path, options));
}

void bind_model(py::module_& m) {
    py::class_<Model, std::shared_ptr<Model>>(m, "Model",
                                              "A model's B-spline surfaces and, for CAD files "
                                              "with trimmed faces, its B-rep (load_model)")
        .def_property_readonly("source", [](const Model& s) { return s.source; })
        .def_property_readonly(
            "surfaces", [](const Model& s) { return s.surfaces.size(); },
            "number of B-spline surfaces")
        .def_property_readonly("surface_names",
                               [](const Model& s) {
                                   std::vector<std::string> names;
                                   for (const BSplineSurface& f : s.surfaces)
                                       names.push_back(f.name);
                                   return names;
                               })
        .def_property_readonly("patches", &patch_count, "number of Bezier patches")
        .def_property_readonly(
            "bbox",
            [](const Model& s) {
                const Box3 b = control_box(s);
                return py::make_tuple(point(b.lo), point(b.hi));
            },
            "((xmin, ymin, zmin), (xmax, ymax, zmax)) of the control points")
        .def_property_readonly(
            "d_max", [](const Model& s) { return d_max(s); },
            "largest extent of the control points' bounding box")
        .def_property_readonly(
            "brep", [](const Model& s) { return brep_dict(s.brep); },
            "B-rep counts as `seamless info --json` gives them, or None")
        .def_property_readonly("warnings", [](const Model& s) { return s.warnings; })
        .def("__repr__", [](const Model& s) {
            return "<seamless.Model '" + s.source + "': " + std::to_string(s.surfaces.size()) +
                   " surfaces, " + std::to_string(patch_count(s)) + " patches>";
        });
    m.def(
        "load_model",
        [](py::object path, const std::string& trimmed) {
            return load(path_string(path), trimmed);
        },
        py::arg("path"), py::arg("trimmed") = "brep",
        "Reads a model (.json, .bpt, .step/.stp, .iges/.igs). trimmed: what to do with "
        "STEP/IGES trimmed faces ('brep', 'refuse', 'skip', 'whole_surface').");
}

} // namespace seamless::python
