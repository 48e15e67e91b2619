// SPDX-License-Identifier: MIT
// seamless.tessellate: `seamless tessellate` as a function, the mesh in
// numpy arrays, the --stats fields as a dict.
#include "bindings.h"
#include "model_binding.h"
#include "options.h"

#include <seamless/tessellate/tessellation.h>

#include <seamless/tessellate/tessellation_stats_json.h>

#include <pybind11/stl.h>

#include <memory>
#include <optional>

namespace seamless::python {
namespace {

struct TessellateArgs {
    std::optional<double> tolerance, angle, eps1, eps2, seam_tolerance;
    int threads = 0, max_depth = TessellationOptions{}.max_depth;
    long long max_triangles = TessellationOptions{}.max_triangles;
};

// The CLI's option checks (tools/tessellate.cpp), naming the keyword.
TessellationOptions tessellation_options(const TessellateArgs& a) {
    TessellationOptions opt;
    opt.tolerance = a.tolerance ? positive(*a.tolerance, "tolerance") : 0;
    opt.eps1 = a.eps1 ? positive(*a.eps1, "eps1") : -1;
    opt.eps2 = a.eps2 ? positive(*a.eps2, "eps2") : -1;
    opt.seam_tolerance = a.seam_tolerance ? non_negative(*a.seam_tolerance, "seam_tolerance") : -1;
    const double degrees = a.angle ? in_range(*a.angle, 0, 180, "angle") : 0;
    opt.angle = degrees * 3.14159265358979323846 / 180;
    opt.threads = static_cast<int>(in_range(a.threads, 0, 1024, "threads"));
    opt.max_depth = static_cast<int>(in_range(a.max_depth, 0, 60, "max_depth"));
    opt.max_triangles =
        static_cast<std::int64_t>(in_range(double(a.max_triangles), 1, 2e9, "max_triangles"));
    opt.patch_trees = false; // the renderer's, not returned
    return opt;
}

std::shared_ptr<Mesh> run(py::object model_or_path, const TessellateArgs& args,
                          const std::string& trimmed, py::object progress) {
    TessellationOptions opt = tessellation_options(args);
    if (!is_path(model_or_path) && !py::isinstance<Model>(model_or_path))
        throw py::type_error("tessellate: expected a seamless.Model or a path");
    const std::shared_ptr<const Model> model = is_path(model_or_path)
                                                   ? load(path_string(model_or_path), trimmed)
                                                   : model_or_path.cast<std::shared_ptr<Model>>();
    ProgressCallback callback(std::move(progress));
    opt.progress = callback.function();
    auto out = std::make_shared<Mesh>();
    out->source = model->source;
    {
        const py::gil_scoped_release release;
        Tessellation t = tessellate(*model, opt);
        out->stats = tessellation_stats_json(t.stats, {model->source, "", args.angle.value_or(0)});
        out->mesh = std::move(t.mesh);
    }
    callback.rethrow();
    return out;
}

} // namespace

void bind_tessellate(py::module_& m) {
    m.def(
        "tessellate",
        [](py::object model_or_path, std::optional<double> tolerance, std::optional<double> angle,
           int threads, long long max_triangles, std::optional<double> eps1,
           std::optional<double> eps2, std::optional<double> seam_tolerance, int max_depth,
           const std::string& trimmed, py::object progress) {
            const TessellateArgs args{tolerance,      angle,   eps1,      eps2,
                                      seam_tolerance, threads, max_depth, max_triangles};
            return run(std::move(model_or_path), args, trimmed, std::move(progress));
        },
        py::arg("model"), py::kw_only(), py::arg("tolerance") = py::none(),
        py::arg("angle") = py::none(), py::arg("threads") = 0,
        py::arg("max_triangles") = TessellationOptions{}.max_triangles,
        py::arg("eps1") = py::none(), py::arg("eps2") = py::none(),
        py::arg("seam_tolerance") = py::none(),
        py::arg("max_depth") = TessellationOptions{}.max_depth, py::arg("trimmed") = "brep",
        py::arg("progress") = py::none(),
        "Crack-free adaptive tessellation of a Model or a model file, as `seamless tessellate` "
        "(docs/python.md): tolerance and seam_tolerance in model units, angle in degrees, "
        "threads 0 = every core; progress(fraction) is called now and then from worker threads.");
}

} // namespace seamless::python
