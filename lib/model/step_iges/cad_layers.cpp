// SPDX-License-Identifier: MIT
#include <seamless/model/step_iges/cad_layers.h>

#include <NCollection_DataMap.hxx>
#include <TCollection_AsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_MapOfShape.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_LayerTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include <algorithm>
#include <memory>

namespace seamless::step_iges {
namespace {

TopoDS_Shape unplaced(const TopoDS_Shape& s) {
    return s.Located(TopLoc_Location());
}

// The indices of a list of shapes (a map's, plus `offset`) by shape wherever
// placed: a part's face placed N times is N faces of a flattened model.
class ShapeIndices {
  public:
    ShapeIndices(const TopTools_IndexedMapOfShape& shapes, int offset) {
        for (int k = 1; k <= shapes.Extent(); ++k) {
            const TopoDS_Shape key = unplaced(shapes(k));
            if (!index_.IsBound(key)) index_.Bind(key, {});
            index_.ChangeFind(key).push_back(offset + k - 1);
        }
    }
    // Appends the indices of s to out; whether there were any.
    bool find(const TopoDS_Shape& s, std::vector<int>& out) const {
        const std::vector<int>* k = index_.Seek(unplaced(s));
        if (k) out.insert(out.end(), k->begin(), k->end());
        return k != nullptr;
    }

  private:
    NCollection_DataMap<TopoDS_Shape, std::vector<int>, TopTools_ShapeMapHasher> index_;
};

// Adds what `shape` covers to `layer`: its solids that the model has, and
// its faces outside them.
void add_shape(const TopoDS_Shape& shape, const ShapeIndices& faces, const ShapeIndices& solids,
               AssemblyLayer& layer) {
    TopTools_MapOfShape in_solid;
    for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next())
        if (solids.find(e.Current(), layer.solids))
            for (TopExp_Explorer f(e.Current(), TopAbs_FACE); f.More(); f.Next())
                in_solid.Add(unplaced(f.Current()));
    for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next())
        if (!in_solid.Contains(unplaced(f.Current()))) faces.find(f.Current(), layer.faces);
}

void sort_unique(std::vector<int>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

AssemblyLayer named(const CadLayer& l) {
    AssemblyLayer out;
    out.name = l.name;
    out.visible = l.visible;
    return out;
}

void finish(AssemblyLayer& layer) {
    sort_unique(layer.parts);
    sort_unique(layer.solids);
    sort_unique(layer.faces);
}

} // namespace

std::vector<CadLayer> read_layers(const Handle(TDocStd_Document) & doc,
                                  const std::function<int(const TDF_Label&)>& part_of) {
    const Handle(XCAFDoc_LayerTool) tool = XCAFDoc_DocumentTool::LayerTool(doc->Main());
    TDF_LabelSequence labels;
    tool->GetLayerLabels(labels);
    std::vector<CadLayer> out;
    for (int k = 1; k <= labels.Length(); ++k) {
        CadLayer layer;
        TCollection_ExtendedString name;
        tool->GetLayer(labels.Value(k), name);
        layer.name = utf8(name);
        layer.visible = tool->IsVisible(labels.Value(k));
        TDF_LabelSequence shapes;
        tool->GetShapesOfLayer(labels.Value(k), shapes);
        for (int i = 1; i <= shapes.Length(); ++i) {
            const TDF_Label& label = shapes.Value(i);
            CadLayerItem item;
            if (XCAFDoc_ShapeTool::IsSubShape(label)) {
                item.part = part_of(label.Father());
                item.shape = XCAFDoc_ShapeTool::GetShape(label);
            } else {
                item.part = part_of(label);
            }
            if (item.part >= 0) layer.items.push_back(std::move(item));
        }
        out.push_back(std::move(layer));
    }
    return out;
}

std::vector<AssemblyLayer> flat_layers(const CadStructure& s, const TransferredFile& t,
                                       const BRep& brep) {
    // read_brep keeps t's faces, in order (sewing replaces them one for one).
    if (t.faces.Extent() != static_cast<int>(brep.faces.size())) return {};
    TopTools_IndexedMapOfShape solids;
    TopExp::MapShapes(t.shape, TopAbs_SOLID, solids);
    if (solids.Extent() != static_cast<int>(brep.solids.size())) solids.Clear();
    const ShapeIndices face_index(t.faces, 0), solid_index(solids, 0);
    std::vector<AssemblyLayer> out;
    for (const CadLayer& l : s.layers) {
        AssemblyLayer layer = named(l);
        for (const CadLayerItem& item : l.items)
            add_shape(item.shape.IsNull() ? s.parts[item.part].shape : item.shape, face_index,
                      solid_index, layer);
        finish(layer);
        out.push_back(std::move(layer));
    }
    return out;
}

std::vector<AssemblyLayer> tree_layers(const CadStructure& s,
                                       const std::vector<TopTools_IndexedMapOfShape>& faces,
                                       const std::vector<TopTools_IndexedMapOfShape>& solids) {
    const std::vector<PartRange> ranges = part_ranges(s.assembly);
    std::vector<std::unique_ptr<ShapeIndices>> face_index, solid_index;
    for (size_t k = 0; k < ranges.size(); ++k) {
        face_index.push_back(std::make_unique<ShapeIndices>(faces[k], ranges[k].first_face));
        solid_index.push_back(std::make_unique<ShapeIndices>(solids[k], ranges[k].first_solid));
    }
    std::vector<AssemblyLayer> out;
    for (const CadLayer& l : s.layers) {
        AssemblyLayer layer = named(l);
        for (const CadLayerItem& item : l.items)
            if (item.shape.IsNull())
                layer.parts.push_back(item.part);
            else
                add_shape(item.shape, *face_index[item.part], *solid_index[item.part], layer);
        finish(layer);
        out.push_back(std::move(layer));
    }
    return out;
}

} // namespace seamless::step_iges
