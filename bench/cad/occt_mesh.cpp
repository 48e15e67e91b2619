// SPDX-License-Identifier: MIT
// occt_mesh FILE.step|.iges -o OUT.ply: OpenCASCADE's side of the CAD
// benchmark (issue 28, docs/results/cad.md). Reads the file with
// STEPControl_Reader / IGESControl_Reader, meshes it with
// BRepMesh_IncrementalMesh at a deflection and angle on 1 or N threads, and
// writes (a PLY with face and solid ids) what OpenCASCADE gives as its users
// get it from StlAPI_Writer or RWGltf_CafWriter: every face's
// Poly_Triangulation with its location, reversed faces flipped, nodes per face
// (the nodes of an edge two faces share are not merged; they are bit-identical
// where OpenCASCADE put them so, and `seamless check` welds those). Prints the
// figures as JSON on stdout.
// Lengths stay in the file's unit, as seamless reads them (not converted to
// millimetres), so both meshes are measured against the same B-rep.
#include <seamless/base/triangle_mesh.h>
#include <seamless/mesh/io/mesh_io.h>

#include <BRepBndLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <IMeshTools_Parameters.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPConstruct_UnitContext.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <StepData_GlobalFactors.hxx>
#include <StepData_StepModel.hxx>
#include <StepGeom_GeomRepContextAndGlobUnitAssCtxAndGlobUncertaintyAssCtx.hxx>
#include <StepRepr_GlobalUnitAssignedContext.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace {

struct Args {
    std::string input, output;
    double deflection = 0;          // absolute, file units
    double relative_deflection = 0; // else this times the bounding box diagonal
    double angle = 0.5;             // radians
    int threads = 1;
    int repeat = 1;    // meshings timed; the median is reported
    bool info = false; // read only: the faces, the diagonal, the reading time
};

double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

bool is_iges(const std::string& path) {
    std::string ext = path.substr(path.find_last_of('.') + 1);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == "igs" || ext == "iges";
}

// The file's length unit kept, as lib/model/step_iges reads it: IGES's global
// section declared millimetres, STEP's first unit context made the system unit.
void keep_file_unit(XSControl_Reader& reader, bool iges) {
    if (iges) {
        auto model = Handle(IGESData_IGESModel)::DownCast(reader.Model());
        if (model.IsNull()) return;
        IGESData_GlobalSection gs = model->GlobalSection();
        gs.SetUnitFlag(2);
        gs.SetUnitName(new TCollection_HAsciiString("MM"));
        model->SetGlobalSection(gs);
        return;
    }
    auto& step = static_cast<STEPControl_Reader&>(reader);
    step.SetSystemLengthUnit(1.0);
    StepData_GlobalFactors::Intance().SetCascadeUnit(1.0);
    const Handle(StepData_StepModel) model = step.StepModel();
    for (int k = 1; !model.IsNull() && k <= model->NbEntities(); ++k) {
        const Handle(Standard_Transient) e = model->Value(k);
        auto ctx = Handle(StepRepr_GlobalUnitAssignedContext)::DownCast(e);
        if (auto c = Handle(
                StepGeom_GeomRepContextAndGlobUnitAssCtxAndGlobUncertaintyAssCtx)::DownCast(e))
            ctx = c->GlobalUnitAssignedContext();
        STEPConstruct_UnitContext unit;
        if (!ctx.IsNull() && unit.ComputeFactors(ctx) == 0 && unit.LengthDone() &&
            unit.LengthFactor() > 0) {
            step.SetSystemLengthUnit(unit.LengthFactor());
            return;
        }
    }
}

TopoDS_Shape read_shape(const std::string& path) {
    const bool iges = is_iges(path);
    std::unique_ptr<XSControl_Reader> reader;
    if (iges)
        reader = std::make_unique<IGESControl_Reader>();
    else
        reader = std::make_unique<STEPControl_Reader>();
    if (reader->ReadFile(path.c_str()) != IFSelect_RetDone)
        throw std::runtime_error("OpenCASCADE cannot read the file");
    keep_file_unit(*reader, iges);
    reader->TransferRoots();
    TopoDS_Shape shape = reader->OneShape();
    if (shape.IsNull()) throw std::runtime_error("OpenCASCADE transferred no shape");
    return shape;
}

double diagonal(const TopoDS_Shape& shape) {
    Bnd_Box box;
    BRepBndLib::AddOptimal(shape, box, Standard_False, Standard_False);
    if (box.IsVoid()) return 0;
    return std::sqrt(box.SquareExtent());
}

double mesh_once(const TopoDS_Shape& shape, double deflection, const Args& a) {
    BRepTools::Clean(shape);
    IMeshTools_Parameters prm;
    prm.Deflection = deflection;
    prm.Angle = a.angle;
    prm.Relative = Standard_False;
    prm.InParallel = a.threads > 1;
    const double t0 = now();
    BRepMesh_IncrementalMesh mesher(shape, prm);
    return now() - t0;
}

struct Collected {
    seamless::TriangleMesh mesh;
    int faces = 0, unmeshed = 0;
};

// One face occurrence's triangles, of solid `solid` (-1: none).
void collect_face(const TopoDS_Face& f, int solid, Collected& c) {
    ++c.faces;
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(f, loc);
    if (tri.IsNull() || tri->NbTriangles() == 0) {
        ++c.unmeshed;
        return;
    }
    const gp_Trsf tr = loc.Transformation();
    const int base = c.mesh.vertex_count();
    for (int i = 1; i <= tri->NbNodes(); ++i) {
        gp_Pnt p = tri->Node(i);
        if (!loc.IsIdentity()) p.Transform(tr);
        c.mesh.positions.push_back({p.X(), p.Y(), p.Z()});
    }
    const bool reversed = f.Orientation() == TopAbs_REVERSED;
    for (int t = 1; t <= tri->NbTriangles(); ++t) {
        int i0, i1, i2;
        tri->Triangle(t).Get(i0, i1, i2);
        if (reversed) std::swap(i1, i2);
        c.mesh.triangles.push_back({base + i0 - 1, base + i1 - 1, base + i2 - 1});
        c.mesh.triangle_part.push_back(0);
        c.mesh.triangle_face.push_back(c.faces - 1);
        c.mesh.triangle_solid.push_back(solid);
    }
}

// Every face occurrence (an assembly's instances each with its location),
// solid by solid, then the faces in no solid; face and solid ids in that
// order, so that `seamless check` judges each solid apart as it does
// seamless's meshes (docs/check.md).
Collected collect(const TopoDS_Shape& shape) {
    Collected c;
    c.mesh.part_names = {"shape"};
    int solids = 0;
    for (TopExp_Explorer s(shape, TopAbs_SOLID); s.More(); s.Next(), ++solids)
        for (TopExp_Explorer ex(s.Current(), TopAbs_FACE); ex.More(); ex.Next())
            collect_face(TopoDS::Face(ex.Current()), solids, c);
    for (TopExp_Explorer ex(shape, TopAbs_FACE, TopAbs_SOLID); ex.More(); ex.Next())
        collect_face(TopoDS::Face(ex.Current()), -1, c);
    return c;
}

int usage() {
    std::cerr << "usage: occt_mesh FILE.step|.stp|.iges|.igs [-o OUT.off] (--deflection D | "
                 "--relative-deflection R) [--angle RAD] [--threads N] [--repeat N]\n"
                 "       occt_mesh FILE --info   (faces, bounding box diagonal, reading time)\n";
    return 2;
}

bool parse(int argc, char** argv, Args& a) {
    for (int i = 1; i < argc; ++i) {
        const std::string s = argv[i];
        const bool has_value = i + 1 < argc;
        if (s == "-o" && has_value)
            a.output = argv[++i];
        else if (s == "--deflection" && has_value)
            a.deflection = std::stod(argv[++i]);
        else if (s == "--relative-deflection" && has_value)
            a.relative_deflection = std::stod(argv[++i]);
        else if (s == "--angle" && has_value)
            a.angle = std::stod(argv[++i]);
        else if (s == "--threads" && has_value)
            a.threads = std::max(1, std::stoi(argv[++i]));
        else if (s == "--repeat" && has_value)
            a.repeat = std::max(1, std::stoi(argv[++i]));
        else if (s == "--info")
            a.info = true;
        else if (a.input.empty() && s.rfind("-", 0) != 0)
            a.input = s;
        else
            return false;
    }
    return !a.input.empty() && (a.info || a.deflection > 0 || a.relative_deflection > 0);
}

int run(const Args& a) {
    // stdout is the JSON alone: the readers' progress messages go nowhere.
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    // OpenCASCADE's parallel loops run on TBB (Debian's build): capped here.
    const tbb::global_control cap(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(a.threads));
    nlohmann::json js{{"file", a.input}, {"threads", a.threads}, {"angle", a.angle}};
    const double r0 = now();
    const TopoDS_Shape shape = read_shape(a.input);
    js["read_seconds"] = now() - r0;
    const double diag = diagonal(shape);
    if (a.info) {
        int faces = 0;
        for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) ++faces;
        js["diagonal"] = diag;
        js["faces"] = faces;
        std::cout << js.dump(2) << "\n";
        return 0;
    }
    const double deflection = a.deflection > 0 ? a.deflection : a.relative_deflection * diag;
    js["diagonal"] = diag;
    js["deflection"] = deflection;
    std::vector<double> times;
    for (int r = 0; r < a.repeat; ++r) times.push_back(mesh_once(shape, deflection, a));
    std::sort(times.begin(), times.end());
    js["mesh_seconds"] = times[times.size() / 2];
    js["mesh_seconds_all"] = times;
    const Collected c = collect(shape);
    js["faces"] = c.faces;
    js["unmeshed_faces"] = c.unmeshed;
    js["triangles"] = c.mesh.triangle_count();
    js["vertices"] = c.mesh.vertex_count();
    js["vertices_merged"] = false; // per face, as StlAPI and RWGltf write them
    if (!a.output.empty() && c.mesh.triangle_count() > 0) seamless::write_mesh(a.output, c.mesh);
    js["output"] = c.mesh.triangle_count() > 0 ? a.output : "";
    std::cout << js.dump(2) << "\n";
    return c.mesh.triangle_count() > 0 ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
    Args a;
    try {
        if (!parse(argc, argv, a)) return usage();
        return run(a);
    } catch (const Standard_Failure& e) {
        std::cerr << a.input << ": OpenCASCADE: " << e.GetMessageString() << "\n";
    } catch (const std::exception& e) {
        std::cerr << a.input << ": " << e.what() << "\n";
    }
    return 2;
}
