// SPDX-License-Identifier: MIT
// Output files are written to a temporary name beside the target and renamed
// into place, so a failure never leaves a partial file behind.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace seamless {

// Calls write(tmp_path) and, if it returns normally, renames tmp_path to `path`.
// On an exception the temporary file is removed and the exception propagates.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path&)>& write);

// Convenience: atomically write a string as the whole content of `path`.
void write_text_atomically(const std::filesystem::path& path, const std::string& text);

} // namespace seamless
