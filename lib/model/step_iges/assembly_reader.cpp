// SPDX-License-Identifier: MIT
#include <seamless/model/step_iges/assembly_reader.h>

#include <seamless/model/step_iges/brep_reader.h>
#include <seamless/model/step_iges/cad_layers.h>

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
    // Each part's faces and solids in read_brep's order, for the layers.
    std::vector<TopTools_IndexedMapOfShape> part_faces(structure.parts.size()),
        part_solids(structure.parts.size());
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
        part_faces[k] = part.faces;
        TopExp::MapShapes(part.shape, TopAbs_SOLID, part_solids[k]);
        // Sewn (read_brep made solids of its own): layers name its faces only.
        if (part_solids[k].Extent() != p.solid_count) part_solids[k].Clear();
    }
    std::vector<AssemblyLayer> layers = tree_layers(structure, part_faces, part_solids);
    m.assembly = std::move(structure.assembly);
    m.assembly.layers = std::move(layers);
    for (int c : colours)
        if (c >= 0) {
            m.assembly.face_colours = std::move(colours);
            break;
        }
    validate_assembly(m, file);
    return m;
}

} // namespace seamless::step_iges
