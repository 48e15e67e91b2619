// SPDX-License-Identifier: MIT
// What the library (step_iges_server.h, step_iges_loader.cpp) and the
// STEP/IGES reader's server (seamless-step-iges, lib/model/step_iges/
// reader_main.cpp) agree on. The library runs
//   seamless-step-iges --server
// with one end of a SOCK_SEQPACKET socket as descriptor kServerFd, stdin and
// stdout on /dev/null and stderr its own. Each request is one datagram: the
// options (encode_options), a zero byte and the file's name, with the write
// ends of two pipes (SCM_RIGHTS). The server forks a worker for it and
// writes the worker's pid on the status pipe (a pid_t), then, when the worker
// has ended, its wait status (an int). The worker answers on the answer pipe
// with kModelAnswer, the model's size (a uint64_t) and the model
// (model_exchange.h), or encode_error's 'E' and the InputError it met, and
// exits 0; or exits kOutOfMemory. Anything else (a
// signal, another status, a malformed answer) is a failure of the reader,
// which the library reports as one InputError naming the file.
#pragma once

#include <seamless/base/error.h>
#include <seamless/model/model.h>

#include <string>
#include <string_view>

namespace seamless::step_iges_process {

inline constexpr const char* kExecutable = "seamless-step-iges";
inline constexpr const char* kServerArgument = "--server";
inline constexpr int kServerFd = 3;
inline constexpr int kOutOfMemory = 3; // exit status: an allocation failed
inline constexpr int kUsage = 64;      // exit status: not run by the library
inline constexpr char kModelAnswer = 'M';
// The answer pipe's size: a large model is tens of MB, and a pipe of 1 MiB
// (Linux's limit for a user) takes it in fewer turns of the worker and the
// caller than one of 64 KiB.
inline constexpr int kAnswerPipeBytes = 1 << 20;

// The options as one argument (every field, doubles exactly) and back;
// decode_options returns false on any defect.
std::string encode_options(const ModelLoadOptions& options);
bool decode_options(std::string_view text, ModelLoadOptions& options);

// 'E' and the error's file, field and message (each its length and bytes),
// and back: nullopt-like false on a malformed answer.
std::string encode_error(const InputError& e);
bool decode_error(std::string_view answer, std::string& file, std::string& field,
                  std::string& message);

} // namespace seamless::step_iges_process
