// SPDX-License-Identifier: MIT
// render(): the method's entry, with the sizes, levels and time it records.
#include <seamless/render/render.h>

#include <seamless/base/error.h>

#include <chrono>

namespace seamless {

Image render(const Scene& scene, const RenderOptions& opt, RenderStats* stats) {
    RenderStats local;
    RenderStats& st = stats ? *stats : local;
    st = RenderStats{};
    st.width = opt.width > 0 ? opt.width : scene.camera.width;
    st.height = opt.height > 0 ? opt.height : scene.camera.height;
    st.levels = opt.levels > 0 ? opt.levels : scene.levels;
    st.threads = opt.threads;
    // INTRACY and the reference trace the Bezier patches, which know nothing
    // of trims; TRAY traces the trimmed faces' triangles.
    if (opt.method != RenderMethod::tray && !scene.model.brep.empty())
        throw InputError(
            scene.source, "objects",
            std::string(opt.method == RenderMethod::intracy ? "INTRACY" : "the reference") +
                " renders untrimmed surfaces only, and the scene holds " +
                std::to_string(scene.model.brep.faces.size()) +
                " trimmed B-rep faces: render it with TRAY (--method tray)");
    const auto t0 = std::chrono::steady_clock::now();
    Image im;
    switch (opt.method) {
    case RenderMethod::intracy:
        st.method = "intracy";
        im = render_intracy(scene, opt, st);
        break;
    case RenderMethod::tray:
        st.method = "tray";
        im = render_tray(scene, opt, st);
        break;
    case RenderMethod::reference:
        st.method = "reference";
        im = render_reference(scene, opt, st);
        break;
    }
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return im;
}

} // namespace seamless
