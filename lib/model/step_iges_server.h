// SPDX-License-Identifier: MIT
// The library's side of the STEP/IGES reader's server (step_iges_process.h):
// one seamless-step-iges process per calling process, started on the first
// STEP or IGES read, which has loaded OpenCASCADE once and forks a fresh
// worker for each read. A worker's crash ends that worker only; the server
// itself never reads a file. Started with posix_spawn (the caller may have
// threads); it ends when every process holding its socket has ended.
#pragma once

#include <seamless/model/model.h>

#include <string>

namespace seamless::step_iges_process {

// The read ends of one request's two pipes: the worker's answer, and its
// status (its pid, then its wait status once it has ended; step_iges_process.h).
struct RequestPipes {
    int answer = -1;
    int status = -1;
};

// Hands the read of `file` to the server (starting it when needed). Throws
// InputError naming the file when the server cannot be started.
RequestPipes request_read(const std::string& file, const ModelLoadOptions& options);

} // namespace seamless::step_iges_process
