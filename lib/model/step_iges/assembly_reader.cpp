// SPDX-License-Identifier: MIT
#include <seamless/model/step_iges/assembly_reader.h>

#include <seamless/model/step_iges/brep_reader.h>

#include <TopExp.hxx>

#include <map>

namespace seamless::step_iges {
namespace {

// Names unique across the parts, as face_names makes them within one.
class UniqueAcrossParts {
  public:
    void operator()(std::string& name) {
        if (int n = uses_[name]++; n > 0) name.append(".").append(std::to_string(n + 1));
    }

  private:
    std::map<std::string, int> uses_;
};

} // namespace

Model read_assembly(const TransferredFile& t, CadStructure structure, const std::string& file,
                    const ModelLoadOptions& options) {
    Model m;
    m.source = file;
    UniqueAcrossParts face_names_all, solid_names_all;
    std::vector<int> colours;
    for (size_t k = 0; k < structure.parts.size(); ++k) {
        TransferredFile part = {t.readers, t.iges, structure.parts[k].shape, {}, t.transfer,
                                t.model,   {}};
        TopExp::MapShapes(part.shape, TopAbs_FACE, part.faces);
        if (part.faces.IsEmpty()) continue; // a product without faces: nothing to place
        std::vector<std::string> names = face_names(part);
        for (std::string& name : names) face_names_all(name);
        Model pm = read_brep(part, names, file, options);
        for (BRepSolid& s : pm.brep.solids) solid_names_all(s.name);
        AssemblyPart& p = structure.assembly.parts[k];
        p.face_count = static_cast<int>(pm.brep.faces.size());
        p.shell_count = static_cast<int>(pm.brep.shells.size());
        p.solid_count = static_cast<int>(pm.brep.solids.size());
        append_brep(m.brep, pm.brep, static_cast<int>(m.surfaces.size()), AffineMap{});
        m.surfaces.insert(m.surfaces.end(), std::make_move_iterator(pm.surfaces.begin()),
                          std::make_move_iterator(pm.surfaces.end()));
        m.origins.insert(m.origins.end(), pm.origins.begin(), pm.origins.end());
        m.warnings.insert(m.warnings.end(), pm.warnings.begin(), pm.warnings.end());
        const std::vector<int> c = part_face_colours(structure, k, part.faces);
        colours.insert(colours.end(), c.begin(), c.end());
    }
    m.assembly = std::move(structure.assembly);
    for (int c : colours)
        if (c >= 0) {
            m.assembly.face_colours = std::move(colours);
            break;
        }
    validate_assembly(m, file);
    return m;
}

} // namespace seamless::step_iges
