// SPDX-License-Identifier: MIT
// seamless.render: `seamless render` as a function, the image an (H, W, 3)
// uint8 array with the PNG's bytes, the --stats fields as a dict.
#include "bindings.h"
#include "options.h"

#include <seamless/render/render.h>

#include <seamless/render/scene/render_stats_json.h>

#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <utility>

namespace seamless::python {
namespace {

RenderMethod method_of(const std::string& name) {
    if (name == "intracy") return RenderMethod::intracy;
    if (name == "tray") return RenderMethod::tray;
    if (name == "reference") return RenderMethod::reference;
    throw InputError("", "method", "expected 'intracy', 'tray' or 'reference', got '" + name + "'");
}

// Levels to bytes as write_png does, so the array equals the PNG's pixels.
void to_bytes(const Image& im, std::uint8_t* rgb) {
    std::vector<std::uint8_t> byte(static_cast<size_t>(std::max(im.levels, 2)));
    for (size_t k = 0; k < byte.size(); ++k)
        byte[k] = level_to_byte(static_cast<int>(k), im.levels);
    for (size_t k = 0; k < im.level.size(); ++k)
        rgb[k] = byte[std::min<size_t>(im.level[k], byte.size() - 1)];
}

struct RenderArgs {
    std::optional<std::pair<int, int>> size;
    std::optional<int> levels;
    std::string method;
    int threads = 0;
    bool dither = true;
};

RenderOptions render_options(const RenderArgs& a) {
    RenderOptions opt;
    opt.method = method_of(a.method);
    if (a.size) {
        opt.width = static_cast<int>(in_range(a.size->first, 1, 16384, "size"));
        opt.height = static_cast<int>(in_range(a.size->second, 1, 16384, "size"));
    }
    opt.levels = a.levels ? static_cast<int>(in_range(*a.levels, 2, 65536, "levels")) : 0;
    opt.threads = static_cast<int>(in_range(a.threads, 0, 1024, "threads"));
    opt.dither = a.dither;
    return opt;
}

py::tuple run(const std::string& scene_path, const RenderArgs& args, py::object progress) {
    RenderOptions opt = render_options(args);
    ProgressCallback callback(std::move(progress));
    opt.progress = callback.function();
    RenderStats st;
    Image im;
    {
        const py::gil_scoped_release release;
        const Scene scene = load_scene(scene_path);
        im = render(scene, opt, &st);
    }
    callback.rethrow();
    py::array_t<std::uint8_t> rgb({im.height, im.width, 3});
    {
        const py::gil_scoped_release release;
        to_bytes(im, rgb.mutable_data());
    }
    return py::make_tuple(rgb, from_json(render_stats_json(st)));
}

} // namespace

void bind_render(py::module_& m) {
    m.def(
        "render",
        [](py::object scene, std::optional<std::pair<int, int>> size, std::optional<int> levels,
           const std::string& method, int threads, bool dither, py::object progress) {
            const RenderArgs args{size, levels, method, threads, dither};
            return run(path_string(scene), args, std::move(progress));
        },
        py::arg("scene"), py::kw_only(), py::arg("size") = py::none(),
        py::arg("levels") = py::none(), py::arg("method") = "intracy", py::arg("threads") = 0,
        py::arg("dither") = true, py::arg("progress") = py::none(),
        "Renders a scene file as `seamless render` does: returns (image, stats), image an "
        "(H, W, 3) uint8 array equal to the PNG's pixels, stats the --stats fields. size "
        "(W, H) and levels default to the scene's; method 'intracy', 'tray' or 'reference'.");
}

} // namespace seamless::python
