// SPDX-License-Identifier: MIT
// A STEP or IGES file read and transferred by OpenCASCADE's readers, with the
// file's own length unit kept and unreadable geometry refused first.
// Internal to the STEP/IGES module (libseamless_step_iges.so): it exposes
// OpenCASCADE's types.
#pragma once

#include <Interface_InterfaceModel.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Shape.hxx>
#include <XSControl_Reader.hxx>
#include <XSControl_TransferReader.hxx>

#include <filesystem>
#include <memory>
#include <string>

namespace seamless::step_iges {

struct TransferredFile {
    std::unique_ptr<XSControl_Reader> reader;
    bool iges = false;
    TopoDS_Shape shape;               // everything transferred
    TopTools_IndexedMapOfShape faces; // every face (or bare surface), at least one
    Handle(XSControl_TransferReader) transfer;
    Handle(Interface_InterfaceModel) model;
};

// Reads the file (STEP or IGES by its extension) and transfers its roots.
// Throws InputError naming the file when it is not readable as its format,
// holds unreadable geometry or no faces. OpenCASCADE's settings are global:
// one call at a time.
TransferredFile transfer_file(const std::filesystem::path& path);

// "#55" for STEP, "DE9" for IGES (the names the shipped JSON conversions use).
std::string entity_label(const Handle(XSControl_TransferReader) & tr,
                         const Handle(Interface_InterfaceModel) & model, const TopoDS_Shape& shape,
                         bool iges);

} // namespace seamless::step_iges
