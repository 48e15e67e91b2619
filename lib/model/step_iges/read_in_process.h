// SPDX-License-Identifier: MIT
// The STEP/IGES reader itself, in the calling process: the entry of the
// reader's executable (reader_main.cpp) and of the benchmark that measures
// the process boundary (bench/step_iges_boundary.cpp). Everything else reads
// through read_step_iges (step_iges.h), in a process of its own.
#pragma once

#include <seamless/model/model.h>

#include <filesystem>

namespace seamless::step_iges {

// As read_step_iges (step_iges.h), but here; one reader at a time (OpenCASCADE
// keeps its settings in globals). An allocation that fails in OpenCASCADE
// throws std::bad_alloc.
Model read_step_iges_in_process(const std::filesystem::path& path, const ModelLoadOptions& options);

// What every read needs done once: OpenCASCADE's printers off, its STEP and
// IGES readers' tables built (the reader's server does it before forking its
// workers, so that no read pays it).
void prepare_reader();

} // namespace seamless::step_iges
