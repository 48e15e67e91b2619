// SPDX-License-Identifier: MIT
// A STEP or IGES file read and transferred by OpenCASCADE's readers, with the
// file's own length unit kept and unreadable geometry refused first.
// Internal to the STEP/IGES module (libseamless_step_iges.so): it exposes
// OpenCASCADE's types.
#pragma once

#include <Interface_InterfaceModel.hxx>
#include <TDocStd_Document.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Shape.hxx>
#include <XSControl_Reader.hxx>
#include <XSControl_TransferReader.hxx>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace seamless::step_iges {

struct TransferredFile {
    std::shared_ptr<void> readers; // OpenCASCADE's reader(s), alive while their results are used
    bool iges = false;
    TopoDS_Shape shape;               // everything transferred
    TopTools_IndexedMapOfShape faces; // every face (or bare surface), at least one
    Handle(XSControl_TransferReader) transfer;
    Handle(Interface_InterfaceModel) model;
    // The file's XCAF document (assembly, names, colours) when transferred
    // with transfer_document; null otherwise.
    Handle(TDocStd_Document) document;
};

// Reads the file (STEP or IGES by its extension) and transfers its roots
// through OpenCASCADE's XCAF readers (STEPCAFControl_Reader,
// IGESCAFControl_Reader): t.shape is every root, flattened (an instanced
// face once per placement), and t.document the file's products, their
// instances and placements, names and colours. Throws InputError naming the
// file when it is not readable as its format, holds unreadable geometry or
// no faces. OpenCASCADE's settings are global: one call at a time.
TransferredFile transfer_document(const std::filesystem::path& path);

// "#55" for STEP, "DE9" for IGES (the names the shipped JSON conversions use).
std::string entity_label(const Handle(XSControl_TransferReader) & tr,
                         const Handle(Interface_InterfaceModel) & model, const TopoDS_Shape& shape,
                         bool iges);

// The names of t's faces: the file's entities ("#55", "DE9"), made unique
// ("#55.2" for a second use), "face-<k>" where there is none.
std::vector<std::string> face_names(const TransferredFile& t);

} // namespace seamless::step_iges
