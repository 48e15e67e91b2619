// SPDX-License-Identifier: MIT
// seamless.Mesh (numpy views of a TriangleMesh's arrays, no copy),
// seamless.read_mesh and seamless.write_mesh (every format of mesh_io.h).
#include "bindings.h"

#include <seamless/base/error.h>
#include <seamless/mesh/io/mesh_io.h>

#include <pybind11/stl.h>

#include <cmath>
#include <memory>

namespace seamless::python {
namespace {

// Vec3 and std::array<int, 3> are plain triples: numpy strides over them as (n, 3).
static_assert(sizeof(Vec3) == 3 * sizeof(double));
static_assert(sizeof(std::array<int, 3>) == 3 * sizeof(int));
static_assert(sizeof(std::array<Vec3, 3>) == 9 * sizeof(double));

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Ints = py::array_t<long long, py::array::c_style | py::array::forcecast>;

void expect_shape(const py::array& a, py::ssize_t rows, std::vector<py::ssize_t> inner,
                  const char* field) {
    bool ok =
        a.ndim() == static_cast<py::ssize_t>(inner.size()) + 1 && (rows < 0 || a.shape(0) == rows);
    for (size_t k = 0; ok && k < inner.size(); ++k) ok = a.shape(k + 1) == inner[k];
    if (!ok) {
        std::string want = rows < 0 ? "(n" : "(" + std::to_string(rows);
        for (py::ssize_t d : inner) want += ", " + std::to_string(d);
        throw InputError("", field, "expected an array of shape " + want + ")");
    }
}

// A Mesh from arrays, checked as read_mesh checks a file: finite
// coordinates, indices of existing vertices.
std::shared_ptr<Mesh> mesh_from_arrays(const Doubles& vertices, const Ints& triangles,
                                       const py::object& surface_id, const py::object& normals) {
    expect_shape(vertices, -1, {3}, "vertices");
    expect_shape(triangles, -1, {3}, "triangles");
    auto out = std::make_shared<Mesh>();
    TriangleMesh& mesh = out->mesh;
    const double* v = vertices.data();
    for (py::ssize_t i = 0; i < vertices.shape(0); ++i, v += 3) {
        if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
            throw InputError("", "vertices[" + std::to_string(i) + "]", "not finite");
        mesh.positions.push_back({v[0], v[1], v[2]});
    }
    const long long* t = triangles.data();
    const py::ssize_t nf = triangles.shape(0);
    for (py::ssize_t i = 0; i < nf; ++i, t += 3) {
        for (int c = 0; c < 3; ++c)
            if (t[c] < 0 || t[c] >= mesh.vertex_count())
                throw InputError("", "triangles[" + std::to_string(i) + "]",
                                 "vertex index " + std::to_string(t[c]) + " out of range");
        mesh.triangles.push_back({int(t[0]), int(t[1]), int(t[2])});
    }
    if (!surface_id.is_none()) {
        const Ints ids = surface_id.cast<Ints>();
        if (ids.ndim() != 1 || ids.shape(0) != nf)
            throw InputError("", "surface_id", "expected one index per triangle");
        for (py::ssize_t i = 0; i < nf; ++i) {
            if (ids.data()[i] < 0 || ids.data()[i] > 1'000'000'000)
                throw InputError("", "surface_id[" + std::to_string(i) + "]", "out of range");
            mesh.triangle_surface.push_back(int(ids.data()[i]));
        }
    }
    if (!normals.is_none()) {
        const Doubles n = normals.cast<Doubles>();
        expect_shape(n, nf, {3, 3}, "normals");
        const double* p = n.data();
        mesh.corner_normals.resize(static_cast<size_t>(nf));
        for (auto& corners : mesh.corner_normals)
            for (Vec3& c : corners) c = {p[0], p[1], p[2]}, p += 3;
    }
    return out;
}

// The view `make` returns, or None when the attribute is absent.
template <class Make> py::object optional_view(bool present, Make make) {
    return present ? py::object(make()) : py::object(py::none());
}

void bind_mesh_class(py::module_& m) {
    py::class_<Mesh, std::shared_ptr<Mesh>>(m, "Mesh",
                                            "A triangle mesh; its arrays are read-only numpy "
                                            "views of the library's storage (no copy)")
        .def(py::init(&mesh_from_arrays), py::arg("vertices"), py::arg("triangles"),
             py::arg("surface_id") = py::none(), py::arg("normals") = py::none(),
             "A mesh from arrays (copied and checked): vertices (n, 3), triangles (m, 3), "
             "optional surface_id (m,) and corner normals (m, 3, 3)")
        .def_property_readonly(
            "vertices",
            [](py::object self) {
                const TriangleMesh& t = self.cast<const Mesh&>().mesh;
                return readonly_view<double>(t.positions.data(), {t.vertex_count(), 3}, self);
            },
            "(n, 3) float64 positions, model units")
        .def_property_readonly(
            "triangles",
            [](py::object self) {
                // The library's indices are non-negative ints: the same bits as uint32.
                const TriangleMesh& t = self.cast<const Mesh&>().mesh;
                return readonly_view<std::uint32_t>(t.triangles.data(), {t.triangle_count(), 3},
                                                    self);
            },
            "(m, 3) uint32 vertex indices, oriented as the surfaces' dP/du x dP/dv")
        .def_property_readonly(
            "normals",
            [](py::object self) {
                const TriangleMesh& t = self.cast<const Mesh&>().mesh;
                return optional_view(!t.corner_normals.empty(), [&] {
                    return readonly_view<double>(t.corner_normals.data(),
                                                 {t.triangle_count(), 3, 3}, self);
                });
            },
            "(m, 3, 3) float64 unit surface normals at each triangle's corners, or None")
        .def_property_readonly(
            "uvs",
            [](py::object self) {
                const TriangleMesh& t = self.cast<const Mesh&>().mesh;
                return optional_view(!t.corner_uvs.empty(), [&] {
                    return readonly_view<double>(t.corner_uvs.data(), {t.triangle_count(), 3, 2},
                                                 self);
                });
            },
            "(m, 3, 2) float64 (u, v) of each corner on its source surface, or None")
        .def_property_readonly(
            "surface_id",
            [](py::object self) {
                const TriangleMesh& t = self.cast<const Mesh&>().mesh;
                return optional_view(!t.triangle_surface.empty(), [&] {
                    return readonly_view<std::int32_t>(t.triangle_surface.data(),
                                                       {t.triangle_count()}, self);
                });
            },
            "(m,) int32 source surface of each triangle (index into surface_names), or None")
        .def_property_readonly(
            "face_id",
            [](py::object self) {
                const std::vector<int>& ids = self.cast<const Mesh&>().face_id;
                return optional_view(!ids.empty(), [&] {
                    return readonly_view<std::int32_t>(ids.data(), {py::ssize_t(ids.size())}, self);
                });
            },
            "(m,) int32 B-rep face of each triangle (-1 where not known), or None without a "
            "B-rep")
        .def_property_readonly("surface_names", [](const Mesh& s) { return s.mesh.surface_names; })
        .def_property_readonly("source", [](const Mesh& s) { return s.source; })
        .def_property_readonly(
            "stats",
            [](const Mesh& s) { return s.stats.empty() ? py::none() : from_json(s.stats); },
            "tessellate()'s statistics (the fields of `seamless tessellate --stats`), or None")
        .def("__repr__", [](const Mesh& s) {
            return "<seamless.Mesh: " + std::to_string(s.mesh.vertex_count()) + " vertices, " +
                   std::to_string(s.mesh.triangle_count()) + " triangles>";
        });
}

} // namespace

void bind_mesh(py::module_& m) {
    bind_mesh_class(m);
    m.def(
        "read_mesh",
        [](py::object path) {
            auto out = std::make_shared<Mesh>();
            out->source = path_string(path);
            const py::gil_scoped_release release;
            out->mesh = read_mesh(out->source);
            return out;
        },
        py::arg("path"), "Reads a mesh file (.off .obj .ply .stl .gltf .glb)");
    m.def(
        "write_mesh",
        [](const Mesh& mesh, py::object path) {
            const std::string p = path_string(path);
            const py::gil_scoped_release release;
            write_mesh(p, mesh.mesh);
        },
        py::arg("mesh"), py::arg("path"),
        "Writes a mesh in the format of the path's extension (.off .obj .ply .stl .gltf .glb), "
        "as `seamless tessellate -o` does; no partial file on failure");
}

} // namespace seamless::python
