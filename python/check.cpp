// SPDX-License-Identifier: MIT
// seamless.check: `seamless check --json` as a function, the report a dict.
#include "bindings.h"
#include "options.h"

#include <seamless/mesh/check/check.h>
#include <seamless/mesh/check/check_json.h>
#include <seamless/mesh/check/defect_faces.h>
#include <seamless/mesh/io/mesh_io.h>

#include <pybind11/stl.h>

#include <memory>
#include <optional>

namespace seamless::python {

void bind_check(py::module_& m) {
    m.def(
        "check",
        [](py::object mesh_or_path, bool closed, std::optional<double> gap, bool weld, bool whole) {
            CheckOptions opt;
            opt.require_closed = closed;
            opt.gap = gap ? positive(*gap, "gap") : 0;
            opt.weld = weld;
            opt.by_solid = !whole;
            std::shared_ptr<const Mesh> mesh;
            if (is_path(mesh_or_path)) {
                auto read = std::make_shared<Mesh>();
                read->source = path_string(mesh_or_path);
                const py::gil_scoped_release release;
                read->mesh = read_mesh(read->source);
                mesh = std::move(read);
            } else if (py::isinstance<Mesh>(mesh_or_path)) {
                mesh = mesh_or_path.cast<std::shared_ptr<Mesh>>();
            } else {
                throw py::type_error("check: expected a seamless.Mesh or a path");
            }
            std::string json;
            bool passed = false;
            std::vector<DefectFace> faces;
            {
                const py::gil_scoped_release release;
                const CheckReport report = check_mesh(mesh->mesh, opt);
                passed = check_passed(report, opt);
                json = check_report_json(report);
                faces = defect_faces(mesh->mesh, report);
            }
            py::dict d = from_json(json);
            // As the CLI adds them to the library's report.
            d["file"] = mesh->source.empty() ? py::object(py::none()) : py::str(mesh->source);
            d["passed"] = passed;
            if (!faces.empty()) {
                py::list list;
                for (const DefectFace& f : faces) {
                    py::dict e;
                    e["defects"] = f.defects;
                    e["face"] = f.face;
                    e["part"] = f.part;
                    list.append(e);
                }
                d["defect_faces"] = list;
            }
            return d;
        },
        py::arg("mesh"), py::kw_only(), py::arg("closed") = false, py::arg("gap") = py::none(),
        py::arg("weld") = true, py::arg("union") = false,
        "Watertightness check of a Mesh or a mesh file: the report of `seamless check --json` "
        "as a dict (docs/check.md); closed: also fail unless every component is closed; gap: "
        "absolute crack and T-junction tolerance, model units; weld=False: --no-weld; "
        "union=True: --union (the mesh judged whole, not each solid apart).");
}

} // namespace seamless::python
