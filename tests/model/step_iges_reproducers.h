// SPDX-License-Identifier: MIT
// The STEP and IGES files on which OpenCASCADE crashes: those of
// ../shared/reproducers and the ones the fuzzer has found since, which the
// repository keeps as fuzz_step_iges's seeds (tests/fuzz/corpus/step_iges/
// occ-*-segv.*; docs/fuzzing.md), each file name once.
#pragma once

#include "test_util.h"

#include <seamless/model/step_iges.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace seamless::test {

inline std::vector<std::filesystem::path> step_iges_reproducers() {
    const std::filesystem::path seeds =
        std::filesystem::path(SEAMLESS_SOURCE_DIR) / "tests" / "fuzz" / "corpus" / "step_iges";
    std::map<std::string, std::filesystem::path> by_name; // sorted, the shared copy first
    for (const auto& dir : {shared_dir() / "reproducers", seeds})
        for (const auto& e : std::filesystem::directory_iterator(dir)) {
            const std::string name = e.path().filename().string();
            if (!is_step_iges_extension(e.path().extension().string())) continue;
            if (dir == seeds && (name.rfind("occ-", 0) != 0 || name.find("-segv.") == name.npos))
                continue;
            by_name.emplace(name, e.path());
        }
    std::vector<std::filesystem::path> files;
    for (const auto& [name, path] : by_name) files.push_back(path);
    return files;
}

} // namespace seamless::test
