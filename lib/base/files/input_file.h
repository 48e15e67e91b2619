// SPDX-License-Identifier: MIT
// Reading a user's input file whole, refusing what is not a regular file
// (a directory, /dev/zero, a FIFO) or is larger than a limit, before reading.
#pragma once

#include <seamless/base/error.h>

#include <cstdint>
#include <filesystem>
#include <new>
#include <string>

namespace seamless {

// The whole content of `path`. `kind` names the file's role in messages
// ("model", "scene", "mesh"). Throws InputError naming the file when it is
// missing, unreadable, a directory, not a regular file, larger than
// `max_bytes`, or does not fit in memory.
std::string read_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes,
                            const std::string& kind);

// Runs f(); an std::bad_alloc from it becomes an InputError naming `file`, so
// that running out of memory on a hostile file says which file it was.
template <class F> auto naming_file_on_oom(const std::string& file, F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const std::bad_alloc&) {
        throw InputError(file, "", "out of memory while reading it");
    }
}

} // namespace seamless
