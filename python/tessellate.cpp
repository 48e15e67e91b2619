// SPDX-License-Identifier: MIT
// seamless.tessellate: `seamless tessellate` as a function, the mesh in
// numpy arrays, the --stats fields as a dict.
#include "bindings.h"
#include "model_binding.h"
#include "options.h"

#include <seamless/mesh/io/placed_mesh.h>
#include <seamless/mesh/placed_stats_json.h>
#include <seamless/tessellate/tessellation.h>

#include <pybind11/stl.h>

#include <algorithm>
#include <iterator>
#include <memory>
#include <optional>

namespace seamless::python {
namespace {

// tessellate()'s keywords, filled from Python's keyword arguments: the
// CLI's options (TessellationOptions holds the defaults), how a path is
// read, and the progress callable.
struct TessellateArgs {
    std::optional<double> tolerance, angle, eps1, eps2, seam_tolerance;
    long long threads = 0, max_depth = TessellationOptions{}.max_depth;
    long long max_triangles = TessellationOptions{}.max_triangles;
    std::string trimmed = "brep";
    py::object progress = py::none();
};

// A keyword's value as the type its field holds; TypeError naming the keyword otherwise.
template <class T> T keyword_value(py::handle value, const char* keyword) {
    try {
        return value.cast<T>();
    } catch (const py::cast_error&) {
        throw py::type_error(
            std::string("tessellate(): ") + keyword + ": unexpected type " +
            py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>());
    }
}

std::optional<double> optional_number(py::handle value, const char* keyword) {
    if (value.is_none()) return std::nullopt;
    return keyword_value<double>(value, keyword);
}

using KeywordSetter = void (*)(TessellateArgs&, py::handle);
struct Keyword {
    const char* name;
    KeywordSetter set;
};

// One entry per keyword: docs/python.md lists them with their defaults.
constexpr Keyword kKeywords[] = {
    {"tolerance",
     [](TessellateArgs& a, py::handle v) { a.tolerance = optional_number(v, "tolerance"); }},
    {"angle", [](TessellateArgs& a, py::handle v) { a.angle = optional_number(v, "angle"); }},
    {"eps1", [](TessellateArgs& a, py::handle v) { a.eps1 = optional_number(v, "eps1"); }},
    {"eps2", [](TessellateArgs& a, py::handle v) { a.eps2 = optional_number(v, "eps2"); }},
    {"seam_tolerance",
     [](TessellateArgs& a, py::handle v) {
         a.seam_tolerance = optional_number(v, "seam_tolerance");
     }},
    {"threads",
     [](TessellateArgs& a, py::handle v) { a.threads = keyword_value<long long>(v, "threads"); }},
    {"max_depth", [](TessellateArgs& a,
                     py::handle v) { a.max_depth = keyword_value<long long>(v, "max_depth"); }},
    {"max_triangles",
     [](TessellateArgs& a, py::handle v) {
         a.max_triangles = keyword_value<long long>(v, "max_triangles");
     }},
    {"trimmed",
     [](TessellateArgs& a, py::handle v) { a.trimmed = keyword_value<std::string>(v, "trimmed"); }},
    {"progress",
     [](TessellateArgs& a, py::handle v) { a.progress = py::reinterpret_borrow<py::object>(v); }},
};

TessellateArgs tessellate_args(const py::kwargs& kwargs) {
    TessellateArgs args;
    for (const auto& item : kwargs) {
        const std::string name = py::str(item.first);
        const auto k = std::find_if(std::begin(kKeywords), std::end(kKeywords),
                                    [&](const Keyword& w) { return name == w.name; });
        if (k == std::end(kKeywords))
            throw py::type_error("tessellate() got an unexpected keyword argument '" + name + "'");
        k->set(args, item.second);
    }
    return args;
}

// The CLI's option checks (tools/tessellate.cpp), naming the keyword.
TessellationOptions tessellation_options(const TessellateArgs& a) {
    TessellationOptions opt;
    opt.tolerance = a.tolerance ? positive(*a.tolerance, "tolerance") : 0;
    opt.eps1 = a.eps1 ? positive(*a.eps1, "eps1") : -1;
    opt.eps2 = a.eps2 ? positive(*a.eps2, "eps2") : -1;
    opt.seam_tolerance = a.seam_tolerance ? non_negative(*a.seam_tolerance, "seam_tolerance") : -1;
    const double degrees = a.angle ? in_range(*a.angle, 0, 180, "angle") : 0;
    opt.angle = degrees * 3.14159265358979323846 / 180;
    opt.threads = static_cast<int>(in_range(double(a.threads), 0, 1024, "threads"));
    opt.max_depth = static_cast<int>(in_range(double(a.max_depth), 0, 60, "max_depth"));
    opt.max_triangles =
        static_cast<std::int64_t>(in_range(double(a.max_triangles), 1, 2e9, "max_triangles"));
    opt.patch_trees = false; // the renderer's, not returned
    return opt;
}

std::shared_ptr<Mesh> run(py::object model_or_path, const TessellateArgs& args) {
    TessellationOptions opt = tessellation_options(args);
    if (!is_path(model_or_path) && !py::isinstance<Model>(model_or_path))
        throw py::type_error("tessellate: expected a seamless.Model or a path");
    const std::shared_ptr<const Model> model = is_path(model_or_path)
                                                   ? load(path_string(model_or_path), args.trimmed)
                                                   : model_or_path.cast<std::shared_ptr<Model>>();
    ProgressCallback callback(args.progress);
    opt.progress = callback.function();
    auto out = std::make_shared<Mesh>();
    out->source = model->source;
    {
        const py::gil_scoped_release release;
        Tessellation t = tessellate(*model, opt);
        out->stats =
            placed_stats_json(t.stats, {model->source, "", args.angle.value_or(0)}, t.mesh, *model);
        out->mesh = std::move(t.mesh);
        // Each triangle's B-rep face; none without a B-rep.
        if (!model->brep.empty()) out->face_id = triangle_faces(out->mesh, *model);
    }
    callback.rethrow();
    return out;
}

} // namespace

void bind_tessellate(py::module_& m) {
    // The defaults in the docstring from their one home.
    static const std::string doc =
        "tessellate(model, *, tolerance=None, angle=None, threads=0, max_triangles=" +
        std::to_string(TessellationOptions{}.max_triangles) +
        ", eps1=None, eps2=None, seam_tolerance=None, max_depth=" +
        std::to_string(TessellationOptions{}.max_depth) +
        ", trimmed='brep', progress=None) -> Mesh\n\n"
        "Crack-free adaptive tessellation of a Model or a model file, as `seamless tessellate` "
        "(docs/python.md): tolerance and seam_tolerance in model units, angle in degrees, "
        "threads 0 = every core; progress(fraction) is called now and then from worker threads.";
    m.def(
        "tessellate",
        [](py::object model, const py::kwargs& kwargs) {
            return run(std::move(model), tessellate_args(kwargs));
        },
        py::arg("model"), doc.c_str());
}

} // namespace seamless::python
