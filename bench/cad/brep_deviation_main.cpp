// SPDX-License-Identifier: MIT
// brep_deviation MODEL MESH [--threads N] [--spacing R]: the two-way deviation
// of any mesh of a CAD model against the model's B-rep
// (lib/mesh/deviation/brep_deviation.h), printed as JSON; the CAD benchmark
// (run_cad_bench.py) measures seamless's and OpenCASCADE's meshes with it.
// A model without a B-rep (untrimmed faces only) is measured against its
// surfaces with measure_deviation (surface -> mesh only: the mesh carries no
// (u,v)). Exit 2 with one line on stderr when the model or mesh is refused.
#include <seamless/base/error.h>
#include <seamless/mesh/deviation/brep_deviation.h>
#include <seamless/mesh/deviation/deviation.h>
#include <seamless/mesh/io/mesh_io.h>
#include <seamless/model/model.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <iostream>
#include <string>

using namespace seamless;

namespace {

nlohmann::json stats_json(const DeviationStats& s) {
    return {{"max", s.max}, {"rms", s.rms}, {"samples", s.samples}};
}

int run(int argc, char** argv) {
    std::string model_path, mesh_path;
    BRepDeviationOptions options;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--threads" && i + 1 < argc)
            options.threads = std::stoi(argv[++i]);
        else if (a == "--spacing" && i + 1 < argc)
            options.relative_spacing = std::stod(argv[++i]);
        else if (model_path.empty())
            model_path = a;
        else if (mesh_path.empty())
            mesh_path = a;
        else
            model_path.clear();
    }
    if (model_path.empty() || mesh_path.empty()) {
        std::cerr << "usage: brep_deviation MODEL MESH [--threads N] [--spacing R]\n";
        return 2;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const Model model = load_model(model_path);
    const TriangleMesh mesh = read_mesh(mesh_path);
    const double read =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    nlohmann::json js{{"model", model_path},
                      {"mesh", mesh_path},
                      {"read_seconds", read},
                      {"triangles", mesh.triangle_count()}};
    Deviation d;
    if (!model.brep.empty()) {
        js["measure"] = "brep";
        js["faces"] = model.brep.faces.size();
        d = measure_brep_deviation(model, mesh, options);
    } else {
        // Untrimmed: every surface is a face; only surface -> mesh without (u,v).
        js["measure"] = "surfaces";
        js["faces"] = model.surfaces.size();
        DeviationOptions o;
        o.threads = options.threads;
        d = measure_deviation(model, mesh, o);
    }
    js["face_to_mesh"] = stats_json(d.surface_to_mesh);
    js["mesh_to_face"] = stats_json(d.mesh_to_surface);
    js["seconds"] = d.seconds;
    std::cout << js.dump(2) << "\n";
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const InputError& e) {
        std::cerr << e.what() << "\n";
    } catch (const std::exception& e) {
        std::cerr << "brep_deviation: " << e.what() << "\n";
    }
    return 2;
}
