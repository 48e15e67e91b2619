// SPDX-License-Identifier: MIT
// Shared by the libFuzzer harnesses: a reader may reject its input only with
// InputError (one line naming the file); anything else escapes and libFuzzer
// reports it, as it reports crashes, sanitizer findings, leaks and timeouts.
#pragma once

#include <seamless/base/error.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

namespace seamless::fuzz {

inline std::string bytes(const uint8_t* data, size_t size) {
    return std::string(reinterpret_cast<const char*>(data), size);
}

// Runs f(); an InputError is the expected answer to bad input. Its message
// must be one printable line that names the file (`file`, or for a reader
// that opens other files, such as a scene its models, any file: file empty).
template <class F> void expect_clean(const std::string& file, F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        const std::string what = e.what();
        if (what.empty() || what.rfind(file, 0) != 0) __builtin_trap();
        for (char c : what)
            if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) __builtin_trap();
    }
}

// A scratch folder of this process for harnesses whose readers open files
// (`seamless-fuzz-<name>-<pid>` in the temp directory), removed at exit.
inline std::filesystem::path scratch_folder(const std::string& name) {
    static std::filesystem::path folder;
    folder = std::filesystem::temp_directory_path() /
             ("seamless-fuzz-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    std::atexit([] {
        std::error_code ec;
        std::filesystem::remove_all(folder, ec);
    });
    return folder;
}

} // namespace seamless::fuzz
