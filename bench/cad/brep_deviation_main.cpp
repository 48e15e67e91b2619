// SPDX-License-Identifier: MIT
// brep_deviation MODEL MESH [--threads N] [--spacing R]: the two-way deviation
// of any mesh of a CAD model against the model's B-rep
// (lib/mesh/deviation/brep_deviation.h), printed as JSON; the CAD benchmark
// (run_cad_bench.py) measures seamless's and OpenCASCADE's meshes with it.
// A model without a B-rep (untrimmed surfaces only) is measured as the B-rep
// whose faces are its surfaces' whole rectangles. Exit 2 with one line on stderr when the model or
// mesh is refused.
#include <seamless/base/error.h>
#include <seamless/mesh/deviation/brep_deviation.h>
#include <seamless/mesh/io/mesh_io.h>
#include <seamless/model/model.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <iostream>
#include <string>

using namespace seamless;

namespace {

// The boundary of a surface's domain from corner a to corner b (in (u,v)):
// its 3D curve a polyline through kBoundaryPoints exact points, its pcurve
// the straight segment. The polyline's chords are off the surface by about
// L^2 / (8 R kBoundaryPoints^2) (length L, radius of curvature R): with 2049
// points, under 1e-6 of a whole circle's length (1e-4 D at D = 1e-4 x diagonal
// was measured with 129).
constexpr int kBoundaryPoints = 2049;

int add_boundary(BRep& brep, const BSplineSurface& s, Vec3 a, Vec3 b) {
    BSplineCurve curve, pcurve{1, {0, 0, 1, 1}, {a, b}, {}};
    curve.knots = {0};
    for (int i = 0; i < kBoundaryPoints; ++i) {
        const double t = double(i) / (kBoundaryPoints - 1);
        const Vec3 uv = a + t * (b - a);
        curve.points.push_back(evaluate(s, uv.x, uv.y).point);
        curve.knots.push_back(t);
    }
    curve.knots.push_back(1);
    brep.curves.push_back(std::move(curve));
    brep.pcurves.push_back(std::move(pcurve));
    const int n = static_cast<int>(brep.curves.size()) - 1;
    brep.edges.push_back({n, 0, 1, -1, -1, 0});
    return n;
}

// Every surface as one face bounded by its domain's rectangle (the edges of
// neighbouring surfaces are not shared: the measure does not need it).
void whole_surfaces_brep(Model& m) {
    for (int i = 0; i < static_cast<int>(m.surfaces.size()); ++i) {
        const BSplineSurface& s = m.surfaces[i];
        const Vec3 c[4] = {{s.u_min(), s.v_min(), 0},
                           {s.u_max(), s.v_min(), 0},
                           {s.u_max(), s.v_max(), 0},
                           {s.u_min(), s.v_max(), 0}};
        BRepLoop loop;
        for (int k = 0; k < 4; ++k) {
            const int e = add_boundary(m.brep, s, c[k], c[(k + 1) % 4]);
            loop.coedges.push_back({e, false, e});
        }
        m.brep.faces.push_back({i, false, {loop}, s.name});
    }
}

nlohmann::json stats_json(const DeviationStats& s) {
    return {
        {"max", s.max}, {"rms", s.rms}, {"samples", s.samples}, {"at", {s.at.x, s.at.y, s.at.z}}};
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
    Model model = load_model(model_path);
    const TriangleMesh mesh = read_mesh(mesh_path);
    const double read =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    nlohmann::json js{{"model", model_path},
                      {"mesh", mesh_path},
                      {"read_seconds", read},
                      {"triangles", mesh.triangle_count()}};
    js["measure"] = model.brep.empty() ? "whole surfaces" : "brep";
    if (model.brep.empty()) whole_surfaces_brep(model);
    js["faces"] = model.brep.faces.size();
    int closed = 0;
    for (const BRepShell& shell : model.brep.shells) closed += shell.closed;
    js["solids"] = model.brep.solids.size();
    js["shells"] = model.brep.shells.size();
    js["closed_shells"] = closed;
    const Deviation d = measure_brep_deviation(model, mesh, options);
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
