// SPDX-License-Identifier: MIT
#include <seamless/base/error.h>
#include <seamless/base/files/atomic_file.h>

#include <fstream>
#include <unistd.h>

namespace seamless {

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path&)>& write) {
    namespace fs = std::filesystem;
    fs::path tmp = path;
    // Keep the extension last: writers (OpenMesh, tinygltf) pick the format from it.
    std::string name(".");
    name += path.stem().string();
    name += ".tmp" + std::to_string(::getpid());
    name += path.extension().string();
    tmp.replace_filename(name);
    try {
        write(tmp);
        std::error_code ec;
        fs::rename(tmp, path, ec);
        if (ec) throw InputError(path.string(), "", "cannot write: " + ec.message());
    } catch (...) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw;
    }
}

void write_text_atomically(const std::filesystem::path& path, const std::string& text) {
    write_atomically(path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) throw InputError(path.string(), "", "cannot open for writing");
        out << text;
        out.close();
        if (!out) throw InputError(path.string(), "", "write failed");
    });
}

} // namespace seamless
