// SPDX-License-Identifier: MIT
// STEP and IGES through OpenCASCADE: the only file that includes its headers,
// built as its own module (libseamless_step_iges.so) that step_iges_loader.cpp
// loads when a STEP or IGES file is read: OpenCASCADE's 17 libraries cost every
// other run of the tool ~800 page faults and ~45 ms at start-up (AMD EPYC VM,
// 2026-12-02: `seamless --version` 58 ms with them).
#include <seamless/model/step_iges.h>

#include <seamless/base/error.h>

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <BndLib_AddSurface.hxx>
#include <Bnd_Box.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <GeomConvert.hxx>
#include <GeomConvert_ApproxSurface.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_Conic.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Line.hxx>
#include <Geom_OffsetSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_SurfaceOfLinearExtrusion.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Check.hxx>
#include <Interface_InterfaceModel.hxx>
#include <Interface_ReportEntity.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Precision.hxx>
#include <STEPConstruct_UnitContext.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <StepData_GlobalFactors.hxx>
#include <StepData_StepModel.hxx>
#include <StepGeom_GeomRepContextAndGlobUnitAssCtxAndGlobUncertaintyAssCtx.hxx>
#include <StepGeom_GeometricRepresentationItem.hxx>
#include <StepRepr_GlobalUnitAssignedContext.hxx>
#include <StepShape_TopologicalRepresentationItem.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>

namespace seamless {

namespace {

std::string fmt(double x, int digits = 3) {
    std::ostringstream os;
    os.precision(digits);
    os << x;
    return os.str();
}

// OpenCASCADE's data exchange keeps its settings and its messenger in globals:
// one reader at a time.
std::mutex& occt_mutex() {
    static std::mutex m;
    return m;
}

// OpenCASCADE prints its messages to stdout by default; ours are InputErrors
// and Model::warnings, so its printers go.
void silence_occt() {
    static std::once_flag once;
    std::call_once(once, [] { Message::DefaultMessenger()->ChangePrinters().Clear(); });
}

// "B-spline", "plane", ...: what the file's surface is, for messages and `info`.
std::string kind_of(const Handle(Geom_Surface) & s) {
    if (s->IsKind(STANDARD_TYPE(Geom_BSplineSurface))) return "B-spline";
    if (s->IsKind(STANDARD_TYPE(Geom_BezierSurface))) return "Bezier";
    if (s->IsKind(STANDARD_TYPE(Geom_Plane))) return "plane";
    if (s->IsKind(STANDARD_TYPE(Geom_CylindricalSurface))) return "cylinder";
    if (s->IsKind(STANDARD_TYPE(Geom_ConicalSurface))) return "cone";
    if (s->IsKind(STANDARD_TYPE(Geom_SphericalSurface))) return "sphere";
    if (s->IsKind(STANDARD_TYPE(Geom_ToroidalSurface))) return "torus";
    if (s->IsKind(STANDARD_TYPE(Geom_SurfaceOfRevolution))) return "surface of revolution";
    if (s->IsKind(STANDARD_TYPE(Geom_SurfaceOfLinearExtrusion))) return "surface of extrusion";
    if (auto o = Handle(Geom_OffsetSurface)::DownCast(s))
        return "offset " + kind_of(o->BasisSurface());
    if (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s))
        return kind_of(t->BasisSurface());
    return s->DynamicType()->Name();
}

// Curves GeomConvert turns into B-splines exactly: lines, conics, Bezier and
// B-spline curves (trimmed or not).
bool exact_curve(Handle(Geom_Curve) c) {
    while (auto t = Handle(Geom_TrimmedCurve)::DownCast(c)) c = t->BasisCurve();
    return c->IsKind(STANDARD_TYPE(Geom_Line)) || c->IsKind(STANDARD_TYPE(Geom_Conic)) ||
           c->IsKind(STANDARD_TYPE(Geom_BezierCurve)) ||
           c->IsKind(STANDARD_TYPE(Geom_BSplineCurve));
}

// The surface GeomConvert::SurfaceToBSplineSurface converts exactly, or null
// (it would approximate the others silently, to 1e-4).
Handle(Geom_Surface) exact_form(Handle(Geom_Surface) s) {
    while (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s)) s = t->BasisSurface();
    if (auto o = Handle(Geom_OffsetSurface)::DownCast(s)) {
        s = o->Surface(); // the equivalent plane, quadric or torus, when there is one
        if (s.IsNull()) return s;
    }
    if (s->IsKind(STANDARD_TYPE(Geom_ElementarySurface)) ||
        s->IsKind(STANDARD_TYPE(Geom_BezierSurface)) ||
        s->IsKind(STANDARD_TYPE(Geom_BSplineSurface)))
        return s;
    if (auto r = Handle(Geom_SurfaceOfRevolution)::DownCast(s))
        return exact_curve(r->BasisCurve()) ? s : Handle(Geom_Surface)();
    if (auto e = Handle(Geom_SurfaceOfLinearExtrusion)::DownCast(s))
        return exact_curve(e->BasisCurve()) ? s : Handle(Geom_Surface)();
    return Handle(Geom_Surface)();
}

// An entity the file reader could not read as its type says (a misspelt
// entity name, a parameter of the wrong kind) stays in the model with a fail
// message, and the entities referring to it get null references that
// OpenCASCADE 7.6's transfer dereferences (SIGSEGV in
// StepToGeom::MakeCartesianPoint on a torus whose CARTESIAN_POINT is misspelt;
// tests/fuzz/occt-crashes/). A file with such an entity among its geometry or
// topology (every IGES entity; STEP's geometric and topological
// representation items) is refused before the transfer. Elsewhere (a STEP
// presentation style, as splinecage.stp's curve_font) it is left to OpenCASCADE.
void refuse_error_entities(const Handle(Interface_InterfaceModel) & model, const std::string& file,
                           bool iges) {
    for (Standard_Integer i = 1; i <= model->NbEntities(); ++i) {
        if (!model->IsErrorEntity(i)) continue;
        const Handle(Standard_Transient) entity = model->Value(i);
        if (!iges && !entity.IsNull() &&
            !entity->IsKind(STANDARD_TYPE(StepGeom_GeometricRepresentationItem)) &&
            !entity->IsKind(STANDARD_TYPE(StepShape_TopologicalRepresentationItem)))
            continue;
        std::string what = "entity " + std::to_string(i);
        const Handle(TCollection_HAsciiString) label = model->StringLabel(entity);
        if (!label.IsNull()) what = "entity " + std::string(label->ToCString());
        const Handle(Interface_ReportEntity) report = model->ReportEntity(i);
        if (!report.IsNull() && !report->Check().IsNull() && report->Check()->NbFails() > 0)
            what += " (" + std::string(report->Check()->CFail(1)) + ")";
        throw InputError(file, "",
                         std::string("not a readable ") + (iges ? "IGES" : "STEP") +
                             " file: OpenCASCADE could not read " + what);
    }
}

struct Converted {
    Handle(Geom_BSplineSurface) surface;
    bool exact = true;
    double error = 0;
};

// The part [u1, u2] x [v1, v2] of `s` as a non-periodic B-spline surface of
// degree at most kMaxDegree: exact where possible, else approximated within
// `rel_tol` times its bounding box diagonal.
Converted convert(const Handle(Geom_Surface) & s, double u1, double u2, double v1, double v2,
                  double rel_tol) {
    Converted c;
    Handle(Geom_Surface) exact = exact_form(s);
    if (!exact.IsNull()) {
        auto bs = Handle(Geom_BSplineSurface)::DownCast(exact);
        double U1, U2, V1, V2;
        exact->Bounds(U1, U2, V1, V2);
        if (!bs.IsNull() && U1 == u1 && U2 == u2 && V1 == v1 && V2 == v2)
            c.surface = Handle(Geom_BSplineSurface)::DownCast(bs->Copy());
        else
            c.surface = GeomConvert::SurfaceToBSplineSurface(
                new Geom_RectangularTrimmedSurface(exact, u1, u2, v1, v2));
        if (c.surface->IsUPeriodic()) c.surface->SetUNotPeriodic();
        if (c.surface->IsVPeriodic()) c.surface->SetVNotPeriodic();
        if (c.surface->UDegree() <= kMaxDegree && c.surface->VDegree() <= kMaxDegree) return c;
    }
    Handle(Geom_Surface) part = new Geom_RectangularTrimmedSurface(s, u1, u2, v1, v2);
    Bnd_Box box;
    BndLib_AddSurface::Add(GeomAdaptor_Surface(part), 0.0, box);
    const double tol = rel_tol * std::sqrt(box.SquareExtent());
    for (GeomAbs_Shape cont : {GeomAbs_C1, GeomAbs_C0}) {
        GeomConvert_ApproxSurface approx(part, tol, cont, cont, kMaxDegree, kMaxDegree, 1000, 0);
        if (!approx.HasResult()) continue;
        c.surface = approx.Surface();
        c.exact = false;
        c.error = approx.MaxError();
        if (c.surface->IsUPeriodic()) c.surface->SetUNotPeriodic();
        if (c.surface->IsVPeriodic()) c.surface->SetVNotPeriodic();
        return c;
    }
    c.surface.Nullify();
    return c;
}

BSplineSurface to_model(const Handle(Geom_BSplineSurface) & b, const std::string& name) {
    BSplineSurface s;
    s.name = name;
    s.degree_u = b->UDegree();
    s.degree_v = b->VDegree();
    s.size_u = b->NbUPoles();
    s.size_v = b->NbVPoles();
    TColStd_Array1OfReal ku(1, s.size_u + s.degree_u + 1), kv(1, s.size_v + s.degree_v + 1);
    b->UKnotSequence(ku);
    b->VKnotSequence(kv);
    s.knots_u.assign(ku.begin(), ku.end());
    s.knots_v.assign(kv.begin(), kv.end());
    // The outermost knots never act on the domain; where only they keep a
    // knot vector from being clamped (periodic surfaces made non-periodic),
    // clamp it.
    for (auto [knots, p] : {std::pair{&s.knots_u, s.degree_u}, std::pair{&s.knots_v, s.degree_v}}) {
        std::vector<double>& U = *knots;
        const size_t n = U.size();
        if (U[1] == U[p] && U[p] < U[p + 1]) U.front() = U[p];
        if (U[n - 2] == U[n - 1 - p] && U[n - 2 - p] < U[n - 1 - p]) U.back() = U[n - 1 - p];
    }
    const bool rational = b->IsURational() || b->IsVRational();
    s.points.reserve(static_cast<size_t>(s.size_u) * s.size_v);
    for (int i = 1; i <= s.size_u; ++i)
        for (int j = 1; j <= s.size_v; ++j) {
            const gp_Pnt p = b->Pole(i, j);
            s.points.push_back({p.X(), p.Y(), p.Z()});
            if (rational) s.weights.push_back(b->Weight(i, j));
        }
    return s;
}

// The parameter rectangle a face covers and whether it is bounded by exactly
// that rectangle (its natural boundary): one wire, every pcurve on the
// rectangle's sides, and in each direction where the surface is bounded (not
// periodic, not infinite) the rectangle reaching the surface's bounds, all
// within the boundary's tolerance. The rectangle is snapped to the bounds in
// those directions, so an untrimmed B-spline face is its whole surface.
struct FaceRange {
    double u1, u2, v1, v2;
    bool natural;
};

FaceRange face_range(const TopoDS_Face& face, const Handle(Geom_Surface) & s) {
    FaceRange r{};
    BRepTools::UVBounds(face, r.u1, r.u2, r.v1, r.v2);
    double U1, U2, V1, V2;
    s->Bounds(U1, U2, V1, V2);
    const bool bounded_u =
        !s->IsUPeriodic() && !Precision::IsInfinite(U1) && !Precision::IsInfinite(U2);
    const bool bounded_v =
        !s->IsVPeriodic() && !Precision::IsInfinite(V1) && !Precision::IsInfinite(V2);
    double tol3 = Precision::Confusion();
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next())
        tol3 = std::max(tol3, BRep_Tool::Tolerance(TopoDS::Edge(e.Current())));
    GeomAdaptor_Surface adaptor(s);
    const double tu = std::max(adaptor.UResolution(2 * tol3), 1e-9 * std::abs(r.u2 - r.u1));
    const double tv = std::max(adaptor.VResolution(2 * tol3), 1e-9 * std::abs(r.v2 - r.v1));
    int wires = 0;
    for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) ++wires;
    r.natural = wires == 1;
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More() && r.natural; e.Next()) {
        double f, l;
        Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Current()), face, f, l);
        if (pc.IsNull()) {
            r.natural = false;
            break;
        }
        for (int k = 0; k <= 8; ++k) {
            const gp_Pnt2d p = pc->Value(f + (l - f) * k / 8);
            const bool on_u_side = std::min(std::abs(p.X() - r.u1), std::abs(p.X() - r.u2)) <= tu;
            const bool on_v_side = std::min(std::abs(p.Y() - r.v1), std::abs(p.Y() - r.v2)) <= tv;
            if (!on_u_side && !on_v_side) r.natural = false;
        }
    }
    if (bounded_u) {
        if (std::abs(r.u1 - U1) > tu || std::abs(r.u2 - U2) > tu) r.natural = false;
        r.u1 = U1, r.u2 = U2;
    }
    if (bounded_v) {
        if (std::abs(r.v1 - V1) > tv || std::abs(r.v2 - V2) > tv) r.natural = false;
        r.v1 = V1, r.v2 = V2;
    }
    return r;
}

// "#55" for STEP, "DE9" for IGES (the names the shipped JSON conversions use).
std::string entity_label(const Handle(XSControl_TransferReader) & tr,
                         const Handle(Interface_InterfaceModel) & model, const TopoDS_Shape& shape,
                         bool iges) {
    Handle(Standard_Transient) ent = tr->EntityFromShapeResult(shape, 1);
    if (ent.IsNull()) ent = tr->EntityFromShapeResult(shape, -1);
    if (ent.IsNull()) return "";
    Handle(TCollection_HAsciiString) label = model->StringLabel(ent);
    if (label.IsNull()) return "";
    std::string s = label->ToCString();
    if (iges && !s.empty() && s[0] == 'D') s = "DE" + s.substr(1);
    return s;
}

// OpenCASCADE converts lengths to millimetres; we keep the file's numbers
// (the shipped JSON conversions do too). IGES: declare the file's unit to be
// millimetres before the transfer.
void keep_iges_units(const Handle(Interface_InterfaceModel) & model) {
    auto iges = Handle(IGESData_IGESModel)::DownCast(model);
    if (iges.IsNull()) return;
    IGESData_GlobalSection gs = iges->GlobalSection();
    gs.SetUnitFlag(2); // millimetres
    gs.SetUnitName(new TCollection_HAsciiString("MM"));
    iges->SetGlobalSection(gs);
}

// STEP: make the file's length unit (that of its first unit context, in
// millimetres) the transfer's system unit. The unit is a process-wide
// setting that unit factors are computed against: millimetres first.
void keep_step_units(STEPControl_Reader& reader) {
    reader.SetSystemLengthUnit(1.0);
    StepData_GlobalFactors::Intance().SetCascadeUnit(1.0);
    const Handle(StepData_StepModel) model = reader.StepModel();
    if (model.IsNull()) return;
    for (int k = 1; k <= model->NbEntities(); ++k) {
        const Handle(Standard_Transient) ent = model->Value(k);
        Handle(StepRepr_GlobalUnitAssignedContext) ctx =
            Handle(StepRepr_GlobalUnitAssignedContext)::DownCast(ent);
        if (auto complex = Handle(
                StepGeom_GeomRepContextAndGlobUnitAssCtxAndGlobUncertaintyAssCtx)::DownCast(ent))
            ctx = complex->GlobalUnitAssignedContext();
        if (ctx.IsNull()) continue;
        STEPConstruct_UnitContext units;
        if (units.ComputeFactors(ctx) == 0 && units.LengthDone() && units.LengthFactor() > 0) {
            reader.SetSystemLengthUnit(units.LengthFactor());
            return;
        }
    }
}

std::string list_names(const std::vector<std::string>& names) {
    std::string s;
    const size_t shown = std::min<size_t>(names.size(), 20);
    for (size_t k = 0; k < shown; ++k) s += (k ? ", " : "") + names[k];
    if (names.size() > shown) s += ", ... " + std::to_string(names.size() - shown) + " more";
    return s;
}

Model read_locked(const std::filesystem::path& path, const ModelLoadOptions& options) {
    const std::string file = path.string();
    std::string ext = path.extension().string();
    for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    const bool iges = ext == ".iges" || ext == ".igs";
    const std::string format = iges ? "IGES" : "STEP";

    std::unique_ptr<XSControl_Reader> reader;
    if (iges) {
        reader = std::make_unique<IGESControl_Reader>();
        // Keep B-splines as written: no knot removal or splitting to raise continuity.
        Interface_Static::SetIVal("read.iges.bspline.continuity", 0);
    } else {
        reader = std::make_unique<STEPControl_Reader>();
    }
    if (reader->ReadFile(file.c_str()) != IFSelect_RetDone)
        throw InputError(file, "", "not a readable " + format + " file");
    if (iges)
        keep_iges_units(reader->Model());
    else
        keep_step_units(static_cast<STEPControl_Reader&>(*reader));
    if (reader->Model().IsNull() || reader->Model()->NbEntities() == 0)
        throw InputError(file, "", "not a readable " + format + " file (no entities)");
    refuse_error_entities(reader->Model(), file, iges);
    if (reader->NbRootsForTransfer() == 0)
        throw InputError(file, "", "no surfaces (the " + format + " file has nothing to transfer)");
    reader->TransferRoots();
    const TopoDS_Shape shape = reader->OneShape();
    if (shape.IsNull())
        throw InputError(file, "", "no surfaces (OpenCASCADE transferred no shape from it)");
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    if (faces.IsEmpty()) throw InputError(file, "", "no surfaces (no faces or bare surfaces)");

    const Handle(XSControl_TransferReader) tr = reader->WS()->TransferReader();
    const Handle(Interface_InterfaceModel) model = reader->WS()->Model();
    Model m;
    m.source = file;
    std::vector<std::string> trimmed, approximated;
    std::map<std::string, int> name_uses;
    for (int k = 1; k <= faces.Extent(); ++k) {
        const TopoDS_Face face = TopoDS::Face(faces(k));
        std::string name = entity_label(tr, model, face, iges);
        if (name.empty()) name = "face-" + std::to_string(k - 1);
        if (int uses = name_uses[name]++; uses > 0)
            name.append(".").append(std::to_string(uses + 1));
        const Handle(Geom_Surface) surf = BRep_Tool::Surface(face); // located
        if (surf.IsNull()) throw InputError(file, name, "face without a surface");
        const FaceRange r = face_range(face, surf);
        if (!r.natural) {
            trimmed.push_back(name);
            if (options.trimmed != TrimmedFaces::whole_surface) continue;
        }
        if (static_cast<long long>(m.surfaces.size()) >= options.limits.max_surfaces)
            throw InputError(file, "",
                             "more than " + std::to_string(options.limits.max_surfaces) +
                                 " surfaces exceed the limit");
        Converted c = convert(surf, r.u1, r.u2, r.v1, r.v2, options.approximation_tolerance);
        if (c.surface.IsNull())
            throw InputError(file, name,
                             "cannot convert its " + kind_of(surf) +
                                 " surface to a B-spline surface");
        // Keep the face's outward side as the surface's dP/du x dP/dv side.
        if (face.Orientation() == TopAbs_REVERSED) c.surface->UReverse();
        if (static_cast<long long>(c.surface->NbUPoles()) * c.surface->NbVPoles() >
            options.limits.max_control_points)
            throw InputError(file, name,
                             std::to_string(c.surface->NbUPoles()) + " x " +
                                 std::to_string(c.surface->NbVPoles()) +
                                 " control points exceed the limit of " +
                                 std::to_string(options.limits.max_control_points));
        BSplineSurface s = to_model(c.surface, name);
        validate_surface(s, file, name);
        m.surfaces.push_back(std::move(s));
        m.origins.push_back({name, kind_of(surf), c.exact, c.error});
        if (!c.exact)
            approximated.push_back(name + " (" + kind_of(surf) + ", " + fmt(c.error) + ")");
    }
    if (!trimmed.empty()) {
        const std::string what = std::to_string(trimmed.size()) + " trimmed face" +
                                 (trimmed.size() == 1 ? "" : "s") + " (" + list_names(trimmed) +
                                 ")";
        switch (options.trimmed) {
        case TrimmedFaces::refuse:
            throw InputError(file, "",
                             what + ": trimmed faces are not supported (--skip-trimmed leaves "
                                    "them out, --untrimmed takes their whole surfaces)");
        case TrimmedFaces::skip:
            m.warnings.push_back(file + ": skipped " + what);
            break;
        case TrimmedFaces::whole_surface:
            m.warnings.push_back(file + ": took the whole surfaces of " + what);
            break;
        }
    }
    if (!approximated.empty())
        m.warnings.push_back(
            file + ": approximated " + std::to_string(approximated.size()) + " surface" +
            (approximated.size() == 1 ? "" : "s") +
            " without an exact NURBS form, largest distances: " + list_names(approximated));
    if (m.surfaces.empty())
        throw InputError(file, "",
                         "no surfaces left after skipping " + std::to_string(trimmed.size()) +
                             " trimmed faces");
    return m;
}

Model read_with_occt(const std::filesystem::path& path, const ModelLoadOptions& options) {
    std::lock_guard<std::mutex> lock(occt_mutex());
    silence_occt();
    try {
        return read_locked(path, options);
    } catch (const Standard_Failure& e) {
        const char* what = e.GetMessageString();
        throw InputError(path.string(), "",
                         std::string("OpenCASCADE failed to read it (") + e.DynamicType()->Name() +
                             (what && *what ? std::string(": ") + what : std::string()) + ")");
    }
}

} // namespace

} // namespace seamless

// The module's one entry (step_iges_loader.cpp finds it by this name).
extern "C" __attribute__((visibility("default"))) void
seamless_read_step_iges(const std::filesystem::path* path,
                        const seamless::ModelLoadOptions* options, seamless::Model* out) {
    *out = seamless::read_with_occt(*path, *options);
}
