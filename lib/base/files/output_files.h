// SPDX-License-Identifier: MIT
// The output files of one command, checked before the work and written
// together after it: an output that cannot be written is reported before any
// time is spent, an output that is also an input is refused (compared by
// device and inode, not by spelling), and either every output appears or none.
#pragma once

#include <filesystem>
#include <vector>

namespace seamless {

class OutputFiles {
  public:
    // Checks every output: a non-empty path, not a directory, in an existing
    // folder where a file can be created (a staging file beside it is created
    // now and removed again unless committed), not the same file as any input
    // or another output. Throws InputError naming the output on failure.
    OutputFiles(std::vector<std::filesystem::path> outputs,
                const std::vector<std::filesystem::path>& inputs);
    ~OutputFiles();
    OutputFiles(const OutputFiles&) = delete;
    OutputFiles& operator=(const OutputFiles&) = delete;

    // Refuses (InputError) an output that is the same file as one of `inputs`;
    // for inputs known only after loading, e.g. the models a scene names.
    void refuse_inputs(const std::vector<std::filesystem::path>& inputs) const;

    // Where to write output `k` (a file beside it with the same extension, so
    // writers that choose the format by extension still do).
    const std::filesystem::path& staging(size_t k) const { return staging_[k]; }

    // Renames every staged file onto its output.
    void commit();

  private:
    std::vector<std::filesystem::path> outputs_, staging_;
    bool committed_ = false;
};

} // namespace seamless
