// SPDX-License-Identifier: MIT
// STEP and IGES through OpenCASCADE: this folder is the only code that
// includes its headers, built into the reader's own executable
// (seamless-step-iges, reader_main.cpp), which the library runs for each
// STEP or IGES file (step_iges_loader.cpp): a crash in OpenCASCADE ends that
// process, not the caller's, and other runs never map its libraries.
// Each face of the transferred file (file_transfer.h) becomes one surface
// (surface_conversion.h) unless it is trimmed (face_range.h).
#include <seamless/model/step_iges.h>

#include <seamless/base/error.h>
#include <seamless/model/step_iges/assembly_reader.h>
#include <seamless/model/step_iges/brep_reader.h>
#include <seamless/model/step_iges/cad_layers.h>
#include <seamless/model/step_iges/cad_structure.h>
#include <seamless/model/step_iges/face_range.h>
#include <seamless/model/step_iges/file_transfer.h>
#include <seamless/model/step_iges/messages.h>
#include <seamless/model/step_iges/read_in_process.h>
#include <seamless/model/step_iges/surface_conversion.h>

#include <BRep_Tool.hxx>
#include <IGESControl_Reader.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <STEPControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <Standard_OutOfMemory.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <map>
#include <mutex>

namespace seamless {

namespace {

using namespace step_iges;

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

// The faces of a transferred file as surfaces, with what was left out or
// approximated.
class FaceReader {
  public:
    FaceReader(const std::string& file, const ModelLoadOptions& options)
        : file_(file), options_(options) {
        m_.source = file;
    }

    // Face k (1-based) of t, named `name`: a surface of the model, or trimmed.
    void read(const TransferredFile& t, int k, const std::string& name) {
        const TopoDS_Face face = TopoDS::Face(t.faces(k));
        const Handle(Geom_Surface) surf = BRep_Tool::Surface(face); // located
        if (surf.IsNull()) throw InputError(file_, name, "face without a surface");
        const FaceRange r = face_range(face, surf);
        if (!r.natural) {
            trimmed_.push_back(name);
            if (options_.trimmed != TrimmedFaces::whole_surface) return;
        }
        if (static_cast<long long>(m_.surfaces.size()) >= options_.limits.max_surfaces)
            throw InputError(file_, "",
                             "more than " + std::to_string(options_.limits.max_surfaces) +
                                 " surfaces exceed the limit");
        Converted c = convert(surf, r.u1, r.u2, r.v1, r.v2, options_.approximation_tolerance);
        if (c.surface.IsNull())
            throw InputError(file_, name,
                             "cannot convert its " + kind_of(surf) +
                                 " surface to a B-spline surface");
        // Keep the face's outward side as the surface's dP/du x dP/dv side.
        if (face.Orientation() == TopAbs_REVERSED) c.surface->UReverse();
        if (static_cast<long long>(c.surface->NbUPoles()) * c.surface->NbVPoles() >
            options_.limits.max_control_points)
            throw InputError(file_, name,
                             std::to_string(c.surface->NbUPoles()) + " x " +
                                 std::to_string(c.surface->NbVPoles()) +
                                 " control points exceed the limit of " +
                                 std::to_string(options_.limits.max_control_points));
        BSplineSurface s = to_model(c.surface, name);
        validate_surface(s, file_, name);
        m_.surfaces.push_back(std::move(s));
        m_.origins.push_back({name, kind_of(surf), c.exact, c.error});
        if (!c.exact)
            approximated_.push_back(name + " (" + kind_of(surf) + ", " + fmt(c.error) + ")");
    }

    // The model, with warnings for what was skipped or approximated (or the
    // refusal of trimmed faces).
    Model finish() {
        if (!trimmed_.empty()) {
            const std::string what = std::to_string(trimmed_.size()) + " trimmed face" +
                                     (trimmed_.size() == 1 ? "" : "s") + " (" +
                                     list_names(trimmed_) + ")";
            switch (options_.trimmed) {
            case TrimmedFaces::brep: // read_brep's, not here
            case TrimmedFaces::refuse:
                throw InputError(file_, "",
                                 what + ": trimmed faces are not supported (--skip-trimmed "
                                        "leaves them out, --untrimmed takes their whole surfaces)");
            case TrimmedFaces::skip:
                m_.warnings.push_back(file_ + ": skipped " + what);
                break;
            case TrimmedFaces::whole_surface:
                m_.warnings.push_back(file_ + ": took the whole surfaces of " + what);
                break;
            }
        }
        if (!approximated_.empty())
            m_.warnings.push_back(
                file_ + ": approximated " + std::to_string(approximated_.size()) + " surface" +
                (approximated_.size() == 1 ? "" : "s") +
                " without an exact NURBS form, largest distances: " + list_names(approximated_));
        if (m_.surfaces.empty())
            throw InputError(file_, "",
                             "no surfaces left after skipping " + std::to_string(trimmed_.size()) +
                                 " trimmed faces");
        return std::move(m_);
    }

  private:
    const std::string& file_;
    const ModelLoadOptions& options_;
    Model m_;
    std::vector<std::string> trimmed_, approximated_;
};

// The flattened model's face colours and layers, when the file has any.
void add_colours(Model& m, const CadStructure& s, const TransferredFile& t) {
    m.assembly.layers = flat_layers(s, t, m.brep);
    std::vector<int> colours = flat_face_colours(s, t.faces);
    if (std::all_of(colours.begin(), colours.end(), [](int c) { return c < 0; })) return;
    m.assembly.colours = s.assembly.colours;
    m.assembly.face_colours = std::move(colours);
}

bool has_trimmed_face(const TransferredFile& t) {
    for (int k = 1; k <= t.faces.Extent(); ++k) {
        const TopoDS_Face face = TopoDS::Face(t.faces(k));
        const Handle(Geom_Surface) surf = BRep_Tool::Surface(face);
        if (!surf.IsNull() && !face_range(face, surf).natural) return true;
    }
    return false;
}

Model read_locked(const std::filesystem::path& path, const ModelLoadOptions& options) {
    const TransferredFile t = transfer_document(path);
    const std::string file = path.string();
    const std::vector<std::string> names = face_names(t);
    // Files without trimmed faces stay lists of whole surfaces.
    if (options.trimmed == TrimmedFaces::brep && has_trimmed_face(t)) {
        // An assembly: each part once, in its own coordinates (load_model
        // places the instances). Otherwise the flattened shape, with its colours.
        CadStructure structure = cad_structure(t);
        if (structure.keeps_tree()) return read_assembly(t, std::move(structure), file, options);
        Model m = read_brep(t, names, file, options);
        add_colours(m, structure, t);
        return m;
    }
    FaceReader faces(file, options);
    for (int k = 1; k <= t.faces.Extent(); ++k) faces.read(t, k, names[k - 1]);
    return faces.finish();
}

Model read_with_occt(const std::filesystem::path& path, const ModelLoadOptions& options) {
    std::lock_guard<std::mutex> lock(occt_mutex());
    silence_occt();
    try {
        return read_locked(path, options);
    } catch (const Standard_OutOfMemory&) {
        throw std::bad_alloc(); // the reader's process reports it as such
    } catch (const Standard_Failure& e) {
        const char* what = e.GetMessageString();
        throw InputError(path.string(), "",
                         std::string("OpenCASCADE failed to read it (") + e.DynamicType()->Name() +
                             (what && *what ? std::string(": ") + what : std::string()) + ")");
    }
}

} // namespace

Model step_iges::read_step_iges_in_process(const std::filesystem::path& path,
                                           const ModelLoadOptions& options) {
    return read_with_occt(path, options);
}

void step_iges::prepare_reader() {
    std::lock_guard<std::mutex> lock(occt_mutex());
    silence_occt();
    STEPControl_Reader step; // their constructors load the readers' protocols
    IGESControl_Reader iges;
}

} // namespace seamless
