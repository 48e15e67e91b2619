// SPDX-License-Identifier: MIT
#include <seamless/base/files/input_file.h>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace seamless {

std::string read_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes,
                            const std::string& kind) {
    namespace fs = std::filesystem;
    const std::string file = path.string();
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    if (st.type() == fs::file_type::not_found || (ec && !fs::exists(st)))
        throw InputError(file, "", "cannot open file (" + std::string(std::strerror(ENOENT)) + ")");
    if (st.type() == fs::file_type::directory)
        throw InputError(file, "", "is a directory, not a " + kind + " file");
    if (st.type() != fs::file_type::regular)
        throw InputError(file, "",
                         "not a regular file (a device, pipe or socket): " + kind +
                             " files must be regular files");
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) throw InputError(file, "", "cannot read file size (" + ec.message() + ")");
    if (size > max_bytes)
        throw InputError(file, "",
                         "file of " + std::to_string(size) + " bytes exceeds the " + kind +
                             " file limit of " + std::to_string(max_bytes) + " bytes");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(file, "", "cannot open file (" + std::string(std::strerror(errno)) + ")");
    return naming_file_on_oom(file, [&] {
        std::string text(static_cast<size_t>(size), '\0');
        in.read(text.data(), static_cast<std::streamsize>(size));
        if (in.bad()) throw InputError(file, "", "read error");
        text.resize(static_cast<size_t>(in.gcount()));
        // A file that grew since its size was taken is refused, not read past the limit.
        char extra;
        if (in.get(extra)) throw InputError(file, "", "file changed size while being read");
        return text;
    });
}

} // namespace seamless
