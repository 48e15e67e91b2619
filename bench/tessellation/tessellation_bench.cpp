// SPDX-License-Identifier: MIT
// seamless against OpenCASCADE 7.6 BRepMesh_IncrementalMesh at the same
// requested deviation (issue 11), and the error-against-run-time sweeps of
// seamless (paper section 8). OpenCASCADE gets the same surfaces as faces
// (Geom_BSplineSurface, a clamped B-spline surface whole, any other as its
// Bezier patches; BRepBuilderAPI_MakeFace), sewn into one shape
// (BRepBuilderAPI_Sewing) as its users do; both meshes are measured by the
// same code (lib/mesh/deviation/deviation.h) and checked by lib/mesh/check/check.h.
// Writes docs/results/tessellation.md and tessellation.svg:
//   seamless_bench_tessellation --docs docs/results
#include <seamless/base/files/atomic_file.h>
#include <seamless/base/parallel/huge_pages.h>
#include <seamless/mesh/check/check.h>
#include <seamless/mesh/deviation/deviation.h>
#include <seamless/mesh/deviation/sweep.h>
#include <seamless/model/model.h>
#include <seamless/tessellate/tessellation.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineSurface.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Poly_Triangulation.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace fs = std::filesystem;
using namespace seamless;

namespace {

double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

std::string num(double x, int digits = 3) {
    std::ostringstream os;
    os << std::setprecision(digits) << x;
    return os.str();
}

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            if (colon != std::string::npos) return line.substr(colon + 2);
        }
    return "unknown";
}

// The load averages (1, 5, 15 minutes) of /proc/loadavg: the machine is shared.
std::string load_average() {
    std::ifstream in("/proc/loadavg");
    double a = 0, b = 0, c = 0;
    in >> a >> b >> c;
    return num(a, 2) + " / " + num(b, 2) + " / " + num(c, 2);
}

std::string today() {
    const std::time_t t = std::time(nullptr);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%d", std::gmtime(&t));
    return buf;
}

// ---- OpenCASCADE side --------------------------------------------------

void knot_vector(const std::vector<double>& k, Handle(TColStd_HArray1OfReal) & values,
                 Handle(TColStd_HArray1OfInteger) & mults) {
    std::vector<double> v;
    std::vector<int> m;
    for (double x : k) {
        if (!v.empty() && x == v.back())
            ++m.back();
        else
            v.push_back(x), m.push_back(1);
    }
    values = new TColStd_HArray1OfReal(1, static_cast<int>(v.size()));
    mults = new TColStd_HArray1OfInteger(1, static_cast<int>(v.size()));
    for (size_t i = 0; i < v.size(); ++i) {
        values->SetValue(static_cast<int>(i) + 1, v[i]);
        mults->SetValue(static_cast<int>(i) + 1, m[i]);
    }
}

bool clamped(const std::vector<double>& k, int p) {
    const size_t n = k.size();
    for (int i = 1; i <= p; ++i)
        if (k[i] != k[0] || k[n - 1 - i] != k[n - 1]) return false;
    return true;
}

Handle(Geom_BSplineSurface) occ_surface(const BSplineSurface& s) {
    TColgp_Array2OfPnt poles(1, s.size_u, 1, s.size_v);
    TColStd_Array2OfReal w(1, s.size_u, 1, s.size_v);
    for (int i = 0; i < s.size_u; ++i)
        for (int j = 0; j < s.size_v; ++j) {
            const Vec3 p = s.point(i, j);
            poles.SetValue(i + 1, j + 1, gp_Pnt(p.x, p.y, p.z));
            w.SetValue(i + 1, j + 1, s.weight(i, j));
        }
    Handle(TColStd_HArray1OfReal) uk, vk;
    Handle(TColStd_HArray1OfInteger) um, vm;
    knot_vector(s.knots_u, uk, um);
    knot_vector(s.knots_v, vk, vm);
    if (s.rational())
        return new Geom_BSplineSurface(poles, w, uk->Array1(), vk->Array1(), um->Array1(),
                                       vm->Array1(), s.degree_u, s.degree_v);
    return new Geom_BSplineSurface(poles, uk->Array1(), vk->Array1(), um->Array1(), vm->Array1(),
                                   s.degree_u, s.degree_v);
}

Handle(Geom_BSplineSurface) occ_patch(const BezierPatch& b) {
    TColgp_Array2OfPnt poles(1, b.p + 1, 1, b.q + 1);
    TColStd_Array2OfReal w(1, b.p + 1, 1, b.q + 1);
    for (int i = 0; i <= b.p; ++i)
        for (int j = 0; j <= b.q; ++j) {
            const Vec3 p = b.point(i, j);
            poles.SetValue(i + 1, j + 1, gp_Pnt(p.x, p.y, p.z));
            w.SetValue(i + 1, j + 1, b.at(i, j).w);
        }
    TColStd_Array1OfReal uk(1, 2), vk(1, 2);
    TColStd_Array1OfInteger um(1, 2), vm(1, 2);
    uk.SetValue(1, b.u0), uk.SetValue(2, b.u1), vk.SetValue(1, b.v0), vk.SetValue(2, b.v1);
    um.SetValue(1, b.p + 1), um.SetValue(2, b.p + 1), vm.SetValue(1, b.q + 1),
        vm.SetValue(2, b.q + 1);
    return new Geom_BSplineSurface(poles, w, uk, vk, um, vm, b.p, b.q);
}

struct OccModel {
    TopoDS_Shape shape;
    std::map<const Geom_Surface*, int> surface_of; // face surface -> model surface
    int faces = 0;
};

OccModel occ_model(const Model& model) {
    OccModel out;
    BRepBuilderAPI_Sewing sew(1e-6 * d_max(model));
    const std::vector<BezierPatch> patches = bezier_patches(model);
    auto add = [&](Handle(Geom_BSplineSurface) g, int surface) {
        BRepBuilderAPI_MakeFace mf(g, Precision::Confusion());
        if (!mf.IsDone()) return;
        out.surface_of[g.get()] = surface;
        sew.Add(mf.Face());
        ++out.faces;
    };
    for (int si = 0; si < static_cast<int>(model.surfaces.size()); ++si) {
        const BSplineSurface& s = model.surfaces[si];
        bool whole = clamped(s.knots_u, s.degree_u) && clamped(s.knots_v, s.degree_v);
        if (whole) {
            try {
                add(occ_surface(s), si);
            } catch (const Standard_Failure&) {
                whole = false;
            }
        }
        if (!whole)
            for (const BezierPatch& b : patches)
                if (b.surface == si) add(occ_patch(b), si);
    }
    sew.Perform();
    out.shape = sew.SewedShape();
    return out;
}

// The triangulation of every face as one mesh with the faces' (u,v).
TriangleMesh occ_mesh(const OccModel& m, const Model& model) {
    TriangleMesh mesh;
    for (const BSplineSurface& s : model.surfaces) mesh.surface_names.push_back(s.name);
    for (TopExp_Explorer ex(m.shape, TopAbs_FACE); ex.More(); ex.Next()) {
        const TopoDS_Face& f = TopoDS::Face(ex.Current());
        TopLoc_Location loc;
        const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(f, loc);
        if (tri.IsNull()) continue;
        TopLoc_Location sloc;
        const Handle(Geom_Surface) gs = BRep_Tool::Surface(f, sloc);
        const auto it = m.surface_of.find(gs.get());
        const int surface = it == m.surface_of.end() ? -1 : it->second;
        const gp_Trsf tr = loc.Transformation();
        const int base = mesh.vertex_count();
        for (int i = 1; i <= tri->NbNodes(); ++i) {
            gp_Pnt p = tri->Node(i);
            if (!loc.IsIdentity()) p.Transform(tr);
            mesh.positions.push_back({p.X(), p.Y(), p.Z()});
        }
        const bool uv = tri->HasUVNodes();
        const bool reversed = f.Orientation() == TopAbs_REVERSED;
        for (int t = 1; t <= tri->NbTriangles(); ++t) {
            int a, b, c;
            tri->Triangle(t).Get(a, b, c);
            if (reversed) std::swap(b, c);
            mesh.triangles.push_back({base + a - 1, base + b - 1, base + c - 1});
            mesh.triangle_surface.push_back(surface);
            if (uv) {
                std::array<std::array<double, 2>, 3> c3;
                int k = 0;
                for (int n : {a, b, c}) {
                    const gp_Pnt2d q = tri->UVNode(n);
                    c3[k++] = {q.X(), q.Y()};
                }
                mesh.corner_uvs.push_back(c3);
            }
        }
    }
    if (mesh.corner_uvs.size() != mesh.triangles.size()) mesh.corner_uvs.clear();
    return mesh;
}

double occ_seconds(const OccModel& m, double deflection, bool parallel) {
    BRepTools::Clean(m.shape);
    IMeshTools_Parameters prm;
    prm.Deflection = deflection;
    prm.Angle = 0.5;
    prm.Relative = Standard_False;
    prm.InParallel = parallel;
    const double t0 = now();
    BRepMesh_IncrementalMesh mesher(m.shape, prm);
    return now() - t0;
}

// ---- one comparison row --------------------------------------------------

struct MeshFigures {
    int triangles = 0, degenerate = 0, cracks = 0, border_edges = 0;
    Deviation deviation;
    double bound = -1; // certified (seamless only)
    double seconds1 = 0, seconds2 = -1;
};

MeshFigures figures(const Model& model, const TriangleMesh& mesh) {
    MeshFigures f;
    f.triangles = mesh.triangle_count();
    const CheckReport r = check_mesh(mesh);
    f.degenerate = static_cast<int>(r.degenerate_triangles.size());
    f.cracks = static_cast<int>(r.cracks.size());
    f.border_edges = r.border_edges;
    f.deviation = measure_deviation(model, mesh);
    return f;
}

struct Row {
    std::string name;
    double d_max = 0, D = 0;
    int faces = 0;
    MeshFigures occ, ours;
};

// `our_runs`: seamless's alternating 1- and 2-thread runs (default `runs`).
Row compare(const std::string& name, const Model& model, double D, int runs, int our_runs = 0) {
    Row row;
    row.name = name;
    row.d_max = d_max(model);
    row.D = D;
    const OccModel occ = occ_model(model);
    row.faces = occ.faces;
    std::vector<double> s1, s2;
    for (int r = 0; r < runs; ++r) {
        s1.push_back(occ_seconds(occ, D, false));
        s2.push_back(occ_seconds(occ, D, true));
    }
    row.occ = figures(model, occ_mesh(occ, model));
    row.occ.seconds1 = median(s1);
    row.occ.seconds2 = median(s2);

    TessellationOptions opt;
    opt.tolerance = D;
    opt.patch_trees = false; // as the CLI's tessellate: the trees are the renderer's
    std::vector<double> t1, t2;
    Tessellation t;
    for (int r = 0; r < (our_runs > 0 ? our_runs : runs); ++r)
        for (int threads : {1, 2}) {
            opt.threads = threads;
            const double t0 = now();
            t = tessellate(model, opt);
            (threads == 1 ? t1 : t2).push_back(now() - t0);
        }
    row.ours = figures(model, t.mesh);
    row.ours.deviation = measure_deviation(model, t); // also the subpatch samples
    row.ours.bound = t.stats.max_error_bound;
    row.ours.seconds1 = median(t1);
    row.ours.seconds2 = median(t2);
    std::cout << name << " D " << D << ": OpenCASCADE " << row.occ.triangles << " triangles, "
              << row.occ.seconds1 << " / " << row.occ.seconds2 << " s, measured "
              << row.occ.deviation.max() << "; seamless " << row.ours.triangles << " triangles, "
              << row.ours.seconds1 << " / " << row.ours.seconds2 << " s, measured "
              << row.ours.deviation.max() << ", bound " << row.ours.bound << std::endl;
    return row;
}

// OpenCASCADE's error against time and triangles for the plot.
struct OccPoint {
    double D = 0, triangles = 0, seconds = 0, measured = 0;
};

std::vector<OccPoint> occ_sweep(const Model& model, const std::vector<double>& Ds, int runs) {
    std::vector<OccPoint> pts;
    const OccModel occ = occ_model(model);
    for (double D : Ds) {
        std::vector<double> s;
        for (int r = 0; r < runs; ++r) s.push_back(occ_seconds(occ, D, false));
        const TriangleMesh mesh = occ_mesh(occ, model);
        pts.push_back(
            {D, double(mesh.triangle_count()), median(s), measure_deviation(model, mesh).max()});
        std::cout << "OpenCASCADE sweep D " << D << ": " << mesh.triangle_count() << " triangles"
                  << std::endl;
    }
    return pts;
}

// ---- report ------------------------------------------------------------------

struct ModelSweep {
    std::string name, path;
    double d_max = 0;
    std::vector<SweepRow> planarity, tolerance;
};

std::string figures_cells(const MeshFigures& f) {
    std::ostringstream os;
    os << f.triangles << " | " << f.degenerate << " | " << f.cracks << " | " << f.border_edges
       << " | " << num(f.deviation.surface_to_mesh.max) << " | "
       << num(f.deviation.mesh_to_surface.max) << " | "
       << (f.bound >= 0 ? num(f.bound) : std::string("—")) << " | " << num(f.seconds1) << " | "
       << (f.seconds2 >= 0 ? num(f.seconds2) : std::string("—"));
    return os.str();
}

void sweep_table(std::ostringstream& os, const std::vector<SweepRow>& rows, bool tolerance,
                 bool& all_ok, double& worst) {
    os << "| " << (tolerance ? "D requested" : "f") << " | triangles | tessellate s | bound | "
       << "surf->mesh | mesh->surf | same-param | measured / bound | ok |\n"
       << "|---:|---:|---:|---:|---:|---:|---:|---:|:--:|\n";
    for (const SweepRow& r : rows) {
        const Deviation& d = r.deviation;
        os << "| " << num(tolerance ? r.tolerance : r.factor) << " | " << r.tess.triangles << " | "
           << num(r.tess.seconds) << " | " << num(r.tess.max_error_bound) << " | "
           << num(d.surface_to_mesh.max) << " | " << num(d.mesh_to_surface.max) << " | "
           << num(d.mesh_same_parameter.max) << " | " << num(r.tightness(), 2) << " | "
           << (r.within_bound() ? "yes" : "**NO**") << " |\n";
        all_ok = all_ok && r.within_bound();
        worst = std::min(worst, r.tightness());
    }
    os << "\n";
}

std::string markdown(const std::vector<Row>& rows, const std::vector<ModelSweep>& sweeps,
                     const std::string& command) {
    std::ostringstream os;
    os << "# Tessellation: a certified deviation, error against run time, and OpenCASCADE\n\n"
       << "Generated by `" << command << "` on " << today() << ".\n"
       << "Machine: " << cpu_model() << ", " << std::thread::hardware_concurrency()
       << " hardware threads, shared with other jobs while this ran (load average "
       << load_average()
       << " at the end; wall-clock times carry tens of percent of noise: compare within a "
          "row). Release build. Both meshers timed on 1 and on 2 threads (seamless: "
          "`TessellationOptions::threads`, the same mesh on any count).\n\n";
    os << "## seamless and OpenCASCADE at the same requested deviation\n\n"
          "OpenCASCADE 7.6 `BRepMesh_IncrementalMesh` (linear deflection D, angular 0.5, "
          "absolute) on the model's surfaces as faces (`Geom_BSplineSurface`, a clamped "
          "B-spline surface whole, others as their Bezier patches; `BRepBuilderAPI_MakeFace`) "
          "sewn into one shape (`BRepBuilderAPI_Sewing`, tolerance 1e-6 d_max); seamless "
          "`tessellate --tolerance D`. Both meshes measured by `lib/mesh/deviation/deviation.h` "
          "(surface->mesh: 33 x 33 points per Bezier patch, plus 2 x 2 per subpatch for "
          "seamless; mesh->surface: corners, edge midpoints and centroid of every triangle, "
          "Newton-projected on its surface) and checked by `lib/mesh/check/check.h` (welded by "
          "position; degenerate triangles; crack = a border edge running along another; border "
          "edges include the model's own boundary). Seconds: median of the runs (seamless at "
          "teapot D = 1e-4 d_max: at least 11 alternating 1- and 2-thread runs); OpenCASCADE on "
          "1 thread and with `InParallel` on 2.\n\n"
          "| model | D | mesher | triangles | degenerate | cracks | border edges | "
          "surf->mesh | mesh->surf | certified bound | s, 1 thread | s, 2 threads |\n"
          "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const Row& r : rows) {
        os << "| " << r.name << " | " << num(r.D) << " | OpenCASCADE (" << r.faces << " faces) | "
           << figures_cells(r.occ) << " |\n";
        os << "| " << r.name << " | " << num(r.D) << " | seamless | " << figures_cells(r.ours)
           << " |\n";
    }
    os << "\n";
    for (const Row& r : rows)
        if (r.name == "teapot" && r.D == 0.001) {
            const double ratio = r.ours.seconds2 / std::max(r.occ.seconds2, 1e-12);
            os << "Goal at teapot D = 0.001: seamless <= 92,602 triangles (" << r.ours.triangles
               << ": " << (r.ours.triangles <= 92602 ? "met" : "**not met**")
               << "), certified bound <= D (" << num(r.ours.bound) << ": "
               << (r.ours.bound <= r.D ? "met" : "**not met**")
               << "), 2-thread time <= 1/3 of OpenCASCADE's 2-thread time (" << num(ratio, 2)
               << " of it: " << (ratio <= 1.0 / 3 ? "met" : "**not met**") << ").\n\n";
        }
    for (const Row& r : rows)
        if (r.name == "teapot" && std::abs(r.D - 1e-4 * r.d_max) < 1e-9 * r.d_max) {
            const double speedup = r.ours.seconds1 / std::max(r.ours.seconds2, 1e-12);
            os << "Goal at teapot D = 1e-4 d_max = " << num(r.D) << ": two-thread speed-up >= 1.7 ("
               << num(speedup, 3) << ": " << (speedup >= 1.7 ? "met" : "**not met**")
               << "; seamless " << num(r.ours.seconds1) << " s on 1 thread, "
               << num(r.ours.seconds2) << " s on 2).\n\n";
        }
    os << "## The certified bound against the measured deviation\n\n"
          "**bound**: `max_error_bound`, the certified two-way distance between surfaces and "
          "mesh (lib/tessellate/bounds/error_bound.h); **surf->mesh**, **mesh->surf**: measured as "
          "above; **same-param**: triangle samples to the surface at their interpolated (u,v) "
          "(the parametric distance, with the parametrisation's tangential drift: not bounded, "
          "shown for comparison); **measured / bound**: max(surf->mesh, mesh->surf) / bound, "
          "1 for an exact bound. Distances in model units.\n\n";
    bool all_ok = true;
    double worst = 1;
    for (const ModelSweep& m : sweeps) {
        os << "### " << m.name << "\n\n`" << m.path << "`, d_max = " << num(m.d_max, 6) << "\n\n";
        if (!m.planarity.empty()) {
            os << "Planarity tolerances of the paper, scaled by f (eps1 = f 0.001 d_max, "
                  "eps2 = f 0.02 d_max):\n\n";
            sweep_table(os, m.planarity, false, all_ok, worst);
        }
        if (!m.tolerance.empty()) {
            os << "Requested deviation D (`--tolerance`):\n\n";
            sweep_table(os, m.tolerance, true, all_ok, worst);
        }
    }
    os << "Measured <= bound in every row: " << (all_ok ? "**yes**" : "**NO**")
       << "; smallest measured / bound: " << num(worst, 2) << ".\n";
    return os.str();
}

// One log-log panel: error / d_max against triangles or seconds.
void panel(std::ostringstream& os, const std::vector<ModelSweep>& sweeps,
           const std::vector<OccPoint>& occ, double occ_dmax, double ox, double oy, double w,
           double h, bool by_time, const std::vector<std::string>& colours) {
    double x0 = 1e300, x1 = 0, y0 = 1e300, y1 = 0;
    auto grow = [&](double x, double y) {
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    };
    auto xof = [&](const SweepRow& r) {
        return by_time ? std::max(r.tess.seconds, 1e-5) : double(r.tess.triangles);
    };
    for (const ModelSweep& m : sweeps)
        for (const SweepRow& r : m.tolerance)
            for (double e : {r.tess.max_error_bound, r.deviation.max()})
                grow(xof(r), std::max(e / m.d_max, 1e-12));
    for (const OccPoint& p : occ)
        grow(by_time ? std::max(p.seconds, 1e-5) : p.triangles,
             std::max(p.measured / occ_dmax, 1e-12));
    if (!(x1 > 0)) return;
    const double lx0 = std::floor(std::log10(x0)), lx1 = std::ceil(std::log10(x1));
    const double ly0 = std::floor(std::log10(y0)), ly1 = std::ceil(std::log10(y1));
    auto X = [&](double x) { return ox + w * (std::log10(x) - lx0) / std::max(lx1 - lx0, 1.0); };
    auto Y = [&](double y) {
        return oy + h - h * (std::log10(y) - ly0) / std::max(ly1 - ly0, 1.0);
    };
    os << "<rect x='" << ox << "' y='" << oy << "' width='" << w << "' height='" << h
       << "' fill='none' stroke='#444'/>\n";
    for (double e = lx0; e <= lx1; ++e) {
        const double x = X(std::pow(10, e));
        os << "<line x1='" << x << "' y1='" << oy << "' x2='" << x << "' y2='" << oy + h
           << "' stroke='#ddd'/><text x='" << x << "' y='" << oy + h + 16
           << "' text-anchor='middle'>1e" << e << "</text>\n";
    }
    for (double e = ly0; e <= ly1; ++e) {
        const double y = Y(std::pow(10, e));
        os << "<line x1='" << ox << "' y1='" << y << "' x2='" << ox + w << "' y2='" << y
           << "' stroke='#ddd'/><text x='" << ox - 6 << "' y='" << y + 4 << "' text-anchor='end'>1e"
           << e << "</text>\n";
    }
    os << "<text x='" << ox + w / 2 << "' y='" << oy + h + 36 << "' text-anchor='middle'>"
       << (by_time ? "tessellation seconds (1 thread)" : "triangles") << "</text>\n";
    for (size_t i = 0; i < sweeps.size(); ++i) {
        const ModelSweep& m = sweeps[i];
        const std::string& c = colours[i % colours.size()];
        for (int measured = 0; measured < 2; ++measured) {
            os << "<polyline fill='none' stroke='" << c << "' stroke-width='1.5'"
               << (measured ? " stroke-dasharray='5,3'" : "") << " points='";
            for (const SweepRow& r : m.tolerance) {
                const double e = measured ? r.deviation.max() : r.tess.max_error_bound;
                os << X(xof(r)) << "," << Y(std::max(e / m.d_max, 1e-12)) << " ";
            }
            os << "'/>\n";
            for (const SweepRow& r : m.tolerance) {
                const double e = measured ? r.deviation.max() : r.tess.max_error_bound;
                const double x = X(xof(r)), y = Y(std::max(e / m.d_max, 1e-12));
                if (measured)
                    os << "<rect x='" << x - 3 << "' y='" << y - 3
                       << "' width='6' height='6' fill='white' stroke='" << c << "'/>\n";
                else
                    os << "<circle cx='" << x << "' cy='" << y << "' r='3' fill='" << c << "'/>\n";
            }
        }
    }
    if (!occ.empty()) {
        os << "<polyline fill='none' stroke='black' stroke-width='1.5' stroke-dasharray='2,2' "
              "points='";
        for (const OccPoint& p : occ)
            os << X(by_time ? std::max(p.seconds, 1e-5) : p.triangles) << ","
               << Y(std::max(p.measured / occ_dmax, 1e-12)) << " ";
        os << "'/>\n";
        for (const OccPoint& p : occ) {
            const double x = X(by_time ? std::max(p.seconds, 1e-5) : p.triangles);
            const double y = Y(std::max(p.measured / occ_dmax, 1e-12));
            os << "<path d='M" << x << "," << y - 4 << " L" << x - 4 << "," << y + 3 << " L"
               << x + 4 << "," << y + 3 << " Z' fill='black'/>\n";
        }
    }
}

std::string svg(const std::vector<ModelSweep>& sweeps, const std::vector<OccPoint>& occ,
                double occ_dmax) {
    const std::vector<std::string> colours{"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                           "#ff7f0e", "#17becf", "#8c564b", "#e377c2"};
    const double W = 1000, H = 500, pw = 380, ph = 340;
    std::ostringstream os;
    os << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H
       << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' "
          "fill='white'/>\n";
    os << "<text x='" << W / 2
       << "' y='22' text-anchor='middle' font-size='15'>Error / d_max at requested deviations: "
          "seamless certified bound (solid, dots), seamless measured (dashed, squares), "
          "OpenCASCADE measured on the teapot (black, triangles)</text>\n";
    panel(os, sweeps, occ, occ_dmax, 80, 50, pw, ph, false, colours);
    panel(os, sweeps, occ, occ_dmax, 540, 50, pw, ph, true, colours);
    os << "<text x='20' y='" << 50 + ph / 2 << "' transform='rotate(-90 20 " << 50 + ph / 2
       << ")' text-anchor='middle'>error / d_max</text>\n";
    for (size_t i = 0; i < sweeps.size(); ++i) {
        const double x = 80 + 120 * static_cast<double>(i % 7), y = H - 30;
        os << "<rect x='" << x << "' y='" << y - 10 << "' width='12' height='12' fill='"
           << colours[i % colours.size()] << "'/><text x='" << x + 16 << "' y='" << y << "'>"
           << sweeps[i].name << "</text>\n";
    }
    os << "<path d='M" << 80 + 120 * 7 << "," << H - 40 << " l-5,8 l10,0 Z' fill='black'/><text x='"
       << 80 + 120 * 7 + 10 << "' y='" << H - 30 << "'>OpenCASCADE</text>\n";
    os << "</svg>\n";
    return os.str();
}

} // namespace

int main(int argc, char** argv) {
    std::string docs;
    int runs = 3;
    bool quick = false;
    std::string only;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--docs" && i + 1 < argc)
            docs = argv[++i];
        else if (a == "--runs" && i + 1 < argc)
            runs = std::max(1, std::atoi(argv[++i]));
        else if (a == "--quick")
            quick = true;
        else if (a == "--only" && i + 1 < argc)
            only = argv[++i];
        else {
            std::cerr << "usage: seamless_bench_tessellation [--docs DIR] [--runs N] [--quick] "
                         "[--only MODEL]\n"
                         "  --quick: sweeps stop at 60,000 triangles instead of 250,000\n"
                         "  --only MODEL: only MODEL's comparison rows (teapot, teacup or "
                         "fuselage), printed; no sweeps, no docs\n";
            return 2;
        }
    }
    const fs::path src = SEAMLESS_SOURCE_DIR;
    const fs::path models = src / "data/models";
    const fs::path fuselage = models / "cad/bug28366_fuselage.json";
    // Repetitions in one process refill the pages the previous one freed, as in
    // a long-running application: with glibc's defaults a one-thread teapot
    // repetition at D = 0.001 re-faulted about 8,000 pages (~90 ms here, i11o).
    keep_freed_memory();
    try {
        std::vector<Row> rows;
        const Model teapot = load_model(models / "teapot.json");
        const Model teacup = load_model(models / "teacup.json");
        const Model fuse = load_model(fuselage);
        const auto wanted = [&](const char* name) { return only.empty() || only == name; };
        if (wanted("teapot"))
            for (double D : {0.01, 0.001, 0.0001})
                rows.push_back(compare("teapot", teapot, D, runs));
        // Issue 11's two-thread speed-up goal is stated at D = 1e-4 d_max. Its
        // ratio of two medians moved 1.47-1.83 between idle runs of 3: at least
        // 11 alternating 1- and 2-thread runs here.
        if (wanted("teapot"))
            rows.push_back(
                compare("teapot", teapot, 1e-4 * d_max(teapot), runs, std::max(runs, 11)));
        if (wanted("teacup"))
            for (double D : {0.01, 0.001, 0.0001})
                rows.push_back(compare("teacup", teacup, D, runs));
        // The fuselage (d_max 206) at the teapot's D relative to d_max, about.
        if (wanted("fuselage"))
            for (double D : {0.2, 0.02, 0.002}) rows.push_back(compare("fuselage", fuse, D, runs));
        if (!only.empty()) return 0;

        std::vector<ModelSweep> sweeps;
        for (const char* name :
             {"teapot", "teacup", "teaspoon", "torus", "sphere", "torus_exact"}) {
            const fs::path p = models / (std::string(name) + ".json");
            const Model m = load_model(p);
            ModelSweep ms{name, "data/models/" + std::string(name) + ".json", d_max(m), {}, {}};
            SweepOptions o;
            o.first_decade = 0; // f = 1, 0.1, 0.01: the default and 10x, 100x finer
            o.decades = 2;
            o.steps_per_decade = 1;
            o.max_triangles = quick ? 60'000 : 250'000;
            o.threads = 1; // beside OpenCASCADE's points, also on one thread
            ms.planarity = sweep_tolerances(m, o);
            o.tolerance = true; // D = f 0.001 d_max for f = 10 .. 0.01
            o.first_decade = 1;
            o.decades = 2; // down to D = 1e-4 d_max
            ms.tolerance = sweep_tolerances(m, o);
            std::cout << name << ": sweeps done" << std::endl;
            sweeps.push_back(std::move(ms));
        }
        const std::vector<OccPoint> occ =
            occ_sweep(teapot, std::vector<double>{0.03, 0.01, 0.003, 0.001, 0.0003, 0.0001}, runs);
        std::string command = "seamless_bench_tessellation --docs " + docs;
        if (runs != 3) command += " --runs " + std::to_string(runs);
        if (quick) command += " --quick";
        const std::string md = markdown(rows, sweeps, command);
        if (docs.empty()) {
            std::cout << md;
        } else {
            // The hand-written profile (perf record / perf report, from "## Profile"
            // on) is kept below the generated part.
            const fs::path out = fs::path(docs) / "tessellation.md";
            std::string kept;
            if (std::ifstream in{out}) {
                std::stringstream old;
                old << in.rdbuf();
                const std::string text = old.str();
                const auto at = text.find("\n## Profile");
                if (at != std::string::npos) kept = text.substr(at);
            }
            write_text_atomically(out, md + kept);
            write_text_atomically(fs::path(docs) / "tessellation.svg",
                                  svg(sweeps, occ, d_max(teapot)));
        }
    } catch (const std::exception& e) {
        std::cerr << "seamless_bench_tessellation: " << e.what() << "\n";
        return 2;
    }
    return 0;
}
