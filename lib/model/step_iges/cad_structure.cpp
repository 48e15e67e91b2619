// SPDX-License-Identifier: MIT
// The XCAF document's tree walked from its free shapes: an assembly's
// components are instances (a location and a reference to the product's
// label), a simple shape is a part, met once however often it is placed.
// Colours follow STEP's styling as XCAF keeps it: a surface colour over a
// generic one, a face's over its solid's over its part's. Layers: cad_layers.h.
#include <seamless/model/step_iges/cad_structure.h>

#include <seamless/model/step_iges/cad_layers.h>

#include <Quantity_ColorRGBA.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDF_Tool.hxx>
#include <TDataStd_Name.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopTools_MapOfShape.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Trsf.hxx>

#include <algorithm>
#include <cstring>
#include <map>

namespace seamless::step_iges {

std::string utf8(const TCollection_ExtendedString& s) {
    std::string out(static_cast<size_t>(s.LengthOfCString()) + 1, '\0');
    Standard_PCharacter p = out.data();
    s.ToUTF8CString(p);
    out.resize(std::strlen(out.c_str()));
    return out;
}

namespace {

std::string label_name(const TDF_Label& label) {
    Handle(TDataStd_Name) name;
    return label.FindAttribute(TDataStd_Name::GetID(), name) ? utf8(name->Get()) : std::string();
}

std::string entry(const TDF_Label& label) {
    TCollection_AsciiString s;
    TDF_Tool::Entry(label, s);
    return s.ToCString();
}

AffineMap placement(const TopLoc_Location& loc) {
    AffineMap m;
    const gp_Trsf t = loc.Transformation();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) m.m[4 * r + c] = t.Value(r + 1, c + 1);
    return m;
}

class StructureReader {
  public:
    explicit StructureReader(const Handle(TDocStd_Document) & doc)
        : doc_(doc), shapes_(XCAFDoc_DocumentTool::ShapeTool(doc->Main())),
          colours_(XCAFDoc_DocumentTool::ColorTool(doc->Main())) {}

    CadStructure read() {
        TDF_LabelSequence roots;
        shapes_->GetFreeShapes(roots);
        for (int k = 1; k <= roots.Length(); ++k)
            visit(roots.Value(k), -1, TopLoc_Location(), label_name(roots.Value(k)));
        s_.layers = read_layers(doc_, [&](const TDF_Label& label) {
            const auto it = part_of_.find(entry(label));
            return it == part_of_.end() ? -1 : static_cast<int>(it->second);
        });
        return std::move(s_);
    }

  private:
    // The node of `label` (a product) placed by `loc` below `parent`.
    void visit(const TDF_Label& label, int parent, const TopLoc_Location& loc, std::string name) {
        AssemblyNode node;
        node.name = std::move(name);
        node.parent = parent;
        node.placement = placement(loc);
        const bool assembly = XCAFDoc_ShapeTool::IsAssembly(label);
        if (!assembly) node.part = part(label);
        if (node.name.empty())
            node.name = !assembly ? s_.assembly.parts[node.part].name : label_name(label);
        s_.assembly.nodes.push_back(std::move(node));
        if (!assembly) return;
        const int self = static_cast<int>(s_.assembly.nodes.size()) - 1;
        TDF_LabelSequence components;
        XCAFDoc_ShapeTool::GetComponents(label, components);
        for (int k = 1; k <= components.Length(); ++k) {
            const TDF_Label& c = components.Value(k);
            TDF_Label ref;
            if (!XCAFDoc_ShapeTool::GetReferredShape(c, ref)) continue;
            std::string instance = label_name(c);
            if (instance.empty()) instance = label_name(ref);
            visit(ref, self, XCAFDoc_ShapeTool::GetLocation(c), std::move(instance));
        }
    }

    // The index of the part of `label`, added on first use.
    int part(const TDF_Label& label) {
        const auto [it, added] = part_of_.try_emplace(entry(label), s_.parts.size());
        if (!added) return it->second;
        AssemblyPart p;
        p.name = label_name(label);
        if (p.name.empty()) p.name = "part-" + std::to_string(it->second);
        p.colour = colour(label);
        CadPart cad;
        cad.shape = XCAFDoc_ShapeTool::GetShape(label);
        TDF_LabelSequence subs;
        XCAFDoc_ShapeTool::GetSubShapes(label, subs);
        for (int k = 1; k <= subs.Length(); ++k) {
            const int c = colour(subs.Value(k));
            if (c < 0) continue;
            const TopoDS_Shape sub = XCAFDoc_ShapeTool::GetShape(subs.Value(k));
            cad.colours.push_back({sub, c, sub.ShapeType() == TopAbs_FACE});
        }
        s_.assembly.parts.push_back(std::move(p));
        s_.parts.push_back(std::move(cad));
        return it->second;
    }

    // The label's surface colour, else its generic one: an index into the
    // assembly's colours (each distinct colour once), or -1.
    int colour(const TDF_Label& label) {
        Quantity_ColorRGBA c;
        if (!colours_->GetColor(label, XCAFDoc_ColorSurf, c) &&
            !colours_->GetColor(label, XCAFDoc_ColorGen, c))
            return -1;
        Rgba rgba;
        // The file's numbers: OpenCASCADE reads STEP's and IGES's colours as sRGB.
        c.GetRGB().Values(rgba.r, rgba.g, rgba.b, Quantity_TOC_sRGB);
        rgba.a = c.Alpha();
        std::vector<Rgba>& all = s_.assembly.colours;
        for (size_t k = 0; k < all.size(); ++k)
            if (all[k] == rgba) return static_cast<int>(k);
        all.push_back(rgba);
        return static_cast<int>(all.size()) - 1;
    }

    Handle(TDocStd_Document) doc_;
    Handle(XCAFDoc_ShapeTool) shapes_;
    Handle(XCAFDoc_ColorTool) colours_;
    CadStructure s_;
    std::map<std::string, size_t> part_of_;
};

} // namespace

bool CadStructure::keeps_tree() const {
    bool assembly = false;
    for (const AssemblyNode& n : this->assembly.nodes) assembly = assembly || n.part < 0;
    if (!assembly) return false;
    TopTools_MapOfShape seen; // edges without their location: shared if one TShape
    for (const CadPart& part : parts) {
        TopTools_MapOfShape own;
        for (TopExp_Explorer e(part.shape, TopAbs_EDGE); e.More(); e.Next())
            own.Add(e.Current().Located(TopLoc_Location()));
        for (TopTools_MapOfShape::Iterator it(own); it.More(); it.Next())
            if (!seen.Add(it.Value())) return false;
    }
    return true;
}

CadStructure cad_structure(const TransferredFile& t) {
    return StructureReader(t.document).read();
}

} // namespace seamless::step_iges

namespace seamless::step_iges {

std::vector<int> part_face_colours(const CadStructure& s, size_t k,
                                   const TopTools_IndexedMapOfShape& faces) {
    const CadPart& part = s.parts[k];
    std::vector<int> out(faces.Extent(), s.assembly.parts[k].colour);
    std::vector<bool> own(faces.Extent(), false);
    for (const SubShapeColour& sc : part.colours)
        for (TopExp_Explorer e(sc.shape, TopAbs_FACE); e.More(); e.Next()) {
            const int f = faces.FindIndex(e.Current()) - 1;
            if (f < 0 || (own[f] && !sc.face_level)) continue;
            out[f] = sc.colour;
            own[f] = own[f] || sc.face_level;
        }
    return out;
}

std::vector<int> flat_face_colours(const CadStructure& s, const TopTools_IndexedMapOfShape& faces) {
    // Each part's faces without their location: what every copy shares.
    TopTools_DataMapOfShapeInteger colour_of;
    for (size_t k = 0; k < s.parts.size(); ++k) {
        TopTools_IndexedMapOfShape own;
        TopExp::MapShapes(s.parts[k].shape, TopAbs_FACE, own);
        const std::vector<int> c = part_face_colours(s, k, own);
        for (int f = 1; f <= own.Extent(); ++f)
            if (c[f - 1] >= 0) colour_of.Bind(own(f).Located(TopLoc_Location()), c[f - 1]);
    }
    std::vector<int> out(faces.Extent(), -1);
    for (int f = 1; f <= faces.Extent(); ++f)
        if (const int* c = colour_of.Seek(faces(f).Located(TopLoc_Location()))) out[f - 1] = *c;
    return out;
}

} // namespace seamless::step_iges
