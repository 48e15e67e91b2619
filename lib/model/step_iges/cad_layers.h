// SPDX-License-Identifier: MIT
// The layers of a transferred file's XCAF document (XCAFDoc_LayerTool:
// STEP's PRESENTATION_LAYER_ASSIGNMENT, IGES's levels) and what they cover in
// the model read from it, by index (AssemblyLayer). XCAF keeps a layer's
// shapes, not its other items: curves and points assigned to a layer are
// dropped here, as they have no face, and so are styled items (XCAF skips
// them). Internal to the STEP/IGES module: it exposes OpenCASCADE's types.
#pragma once

#include <seamless/model/assembly.h>
#include <seamless/model/brep.h>
#include <seamless/model/step_iges/cad_structure.h>

#include <TDF_Label.hxx>
#include <TDocStd_Document.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <functional>
#include <vector>

namespace seamless::step_iges {

// The document's layers, in its order; part_of(label): the index of the part
// a product's label is, -1 for none. A shape of a layer that lies in no part
// (an instance's, an assembly's) is left out.
std::vector<CadLayer> read_layers(const Handle(TDocStd_Document) & doc,
                                  const std::function<int(const TDF_Label&)>& part_of);

// The layers of `brep`, read from t as one flattened shape (read_brep): its
// faces are t.faces, its solids t.shape's in TopExp::MapShapes order unless
// read_brep sewed solids of its own (then a layer names their faces). An
// item of a part placed N times covers its N copies.
std::vector<AssemblyLayer> flat_layers(const CadStructure& s, const TransferredFile& t,
                                       const BRep& brep);

// The layers of a model that keeps the tree (assembly_reader.h): a whole
// part as the part, a sub-shape of part k by part k's own faces and solids
// (faces[k], solids[k]; read_brep's order) after those of the parts before.
std::vector<AssemblyLayer> tree_layers(const CadStructure& s,
                                       const std::vector<TopTools_IndexedMapOfShape>& faces,
                                       const std::vector<TopTools_IndexedMapOfShape>& solids);

} // namespace seamless::step_iges
