// SPDX-License-Identifier: MIT
// The structure of a transferred file's XCAF document (file_transfer.h,
// transfer_document): the tree of products and instances with their names
// and placements, each distinct part's shape in its own coordinates, and
// the colours of parts and of their solids and faces, the layers. Internal to the
// STEP/IGES module: it exposes OpenCASCADE's types.
#pragma once

#include <seamless/model/assembly.h>
#include <seamless/model/step_iges/file_transfer.h>

#include <TCollection_ExtendedString.hxx>
#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

namespace seamless::step_iges {

// A colour of a part's sub-shape: a face's own (face_level) or its solid's,
// shell's or compound's, for every face inside it.
struct SubShapeColour {
    TopoDS_Shape shape;
    int colour = -1; // index into Assembly::colours
    bool face_level = false;
};

struct CadPart {
    TopoDS_Shape shape; // in the part's coordinates
    std::vector<SubShapeColour> colours;
};

// A layer as XCAF keeps it (cad_layers.h): the shapes assigned to it, each
// a part's or a sub-shape of one.
struct CadLayerItem {
    int part = -1;      // index into CadStructure::parts
    TopoDS_Shape shape; // a sub-shape of the part's shape; null: the whole part
};

struct CadLayer {
    std::string name;
    bool visible = true;
    std::vector<CadLayerItem> items; // what XCAF gives that lies in a part
};

struct CadStructure {
    // parts[k] is assembly.parts[k] (name and colour set, counts not yet);
    // nodes and colours are complete.
    Assembly assembly;
    std::vector<CadPart> parts;
    std::vector<CadLayer> layers;
    // Whether the parts can be read one by one: the file has an assembly
    // (products placed by instances) and no two parts share an edge (IGES
    // files' roots and some STEP files' products do; read apart, their
    // shared edges would become two and the mesh would crack there).
    bool keeps_tree() const;
};

// A name of XCAF's (TDataStd_Name, a layer's) as UTF-8.
std::string utf8(const TCollection_ExtendedString& s);

// The structure of t.document; t must come from transfer_document.
CadStructure cad_structure(const TransferredFile& t);

// The colour index (-1: none) of each of `faces` (a flattened shape's: an
// instance's copy of a part's face has the face's colour), resolved face
// over solid over part.
std::vector<int> flat_face_colours(const CadStructure& s, const TopTools_IndexedMapOfShape& faces);

// The same for the faces of part k, `faces` being the part shape's.
std::vector<int> part_face_colours(const CadStructure& s, size_t k,
                                   const TopTools_IndexedMapOfShape& faces);

} // namespace seamless::step_iges
