// SPDX-License-Identifier: MIT
// The Python module's units (docs/python.md): each binds one concept of the
// library and its CLI command. Only argument conversion lives here; the work
// is the library's.
#pragma once

#include <seamless/base/triangle_mesh.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <functional>
#include <string>
#include <vector>

namespace seamless::python {

namespace py = pybind11;

// A mesh as Python holds it: the library's TriangleMesh, whose arrays numpy
// views without a copy (the views keep this object alive), and where it came from.
struct Mesh {
    TriangleMesh mesh;
    std::vector<int> face_id; // per triangle B-rep face, -1 unknown; empty without a B-rep
    std::string source;       // the file read or the model tessellated; "" when built from arrays
    std::string stats;        // tessellate's statistics as JSON ("" when not tessellated)
};

void bind_errors(py::module_& m);
void bind_model(py::module_& m);
void bind_mesh(py::module_& m);
void bind_tessellate(py::module_& m);
void bind_check(py::module_& m);
void bind_render(py::module_& m);

// A read-only numpy array of `shape` over `data`, owned by `owner` (no copy).
template <class T>
py::array readonly_view(const void* data, std::vector<py::ssize_t> shape, py::handle owner) {
    py::array a(py::dtype::of<T>(), std::move(shape), static_cast<const T*>(data), owner);
    a.attr("setflags")(py::arg("write") = false);
    return a;
}

// JSON text as Python objects (json.loads).
py::object from_json(const std::string& text);

// A model or mesh argument given as a path: str or os.PathLike.
bool is_path(py::handle h);
std::string path_string(py::handle h);

// TessellationOptions::progress / RenderOptions::progress calling a Python
// callable from the library's worker threads while the caller has released
// the GIL. An exception the callable raises stops further calls and is raised
// by rethrow() once the work is done (the library's work is not interrupted
// from inside a worker).
class ProgressCallback {
  public:
    explicit ProgressCallback(py::object callable);
    std::function<void(double)> function();
    void rethrow(); // with the GIL held
  private:
    struct State;
    std::shared_ptr<State> state_;
};

} // namespace seamless::python
