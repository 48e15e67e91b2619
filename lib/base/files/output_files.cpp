// SPDX-License-Identifier: MIT
#include <seamless/base/error.h>
#include <seamless/base/files/output_files.h>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace seamless {

namespace fs = std::filesystem;

namespace {

bool same_file(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    return fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec) && !ec;
}

} // namespace

OutputFiles::OutputFiles(std::vector<fs::path> outputs, const std::vector<fs::path>& inputs)
    : outputs_(std::move(outputs)) {
    for (size_t k = 0; k < outputs_.size(); ++k) {
        const fs::path& out = outputs_[k];
        const std::string file = out.string();
        if (out.empty()) throw InputError("", "output", "empty file name");
        std::error_code ec;
        if (fs::is_directory(out, ec)) throw InputError(file, "", "is a directory, not a file");
        const fs::path folder = out.has_parent_path() ? out.parent_path() : fs::path(".");
        if (!fs::is_directory(folder, ec))
            throw InputError(file, "",
                             "cannot write: folder " + folder.string() + " does not exist");
        for (const fs::path& in : inputs)
            if (same_file(out, in))
                throw InputError(
                    file, "", "is also an input (" + in.string() + "): refusing to overwrite it");
        for (size_t j = 0; j < k; ++j)
            if (same_file(out, outputs_[j]) ||
                fs::weakly_canonical(out, ec) == fs::weakly_canonical(outputs_[j], ec))
                throw InputError(file, "", "given twice as an output");
    }
    // Creating the staging files proves the folders are writable (access()
    // would not: it says yes to root on a read-only mount's sibling, and the
    // answer can change before the write).
    for (const fs::path& out : outputs_) {
        fs::path tmp = out;
        // Appended piece by piece: "." + string trips gcc 12's -Wrestrict.
        std::string name(1, '.');
        name.append(out.stem().string()).append(".part").append(std::to_string(::getpid()));
        name.append(out.extension().string());
        tmp.replace_filename(name);
        const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
        if (fd < 0) {
            const int err = errno;
            for (const fs::path& s : staging_) ::unlink(s.c_str());
            staging_.clear();
            throw InputError(out.string(), "",
                             "cannot write (" + std::string(std::strerror(err)) + ")");
        }
        ::close(fd);
        staging_.push_back(tmp);
    }
}

OutputFiles::~OutputFiles() {
    if (committed_) return;
    for (const fs::path& s : staging_) ::unlink(s.c_str());
}

void OutputFiles::refuse_inputs(const std::vector<fs::path>& inputs) const {
    for (const fs::path& out : outputs_)
        for (const fs::path& in : inputs)
            if (same_file(out, in))
                throw InputError(out.string(), "",
                                 "is also an input (" + in.string() +
                                     "): refusing to overwrite it");
}

void OutputFiles::commit() {
    for (size_t k = 0; k < outputs_.size(); ++k) {
        std::error_code ec;
        fs::rename(staging_[k], outputs_[k], ec);
        if (ec) throw InputError(outputs_[k].string(), "", "cannot write: " + ec.message());
    }
    committed_ = true;
}

} // namespace seamless
