// SPDX-License-Identifier: MIT
// libFuzzer harness: the scene reader. Scenes name model files; a scratch
// folder holds three small ones that the corpus refers to: m.json, m.bpt and
// c.json, an assembly in colour (the objects naming it show its colours).
#include "../model/brep_test_models.h"
#include "fuzz_common.h"

#include <seamless/render/scene/scene.h>

#include <filesystem>
#include <fstream>

namespace {

std::filesystem::path folder;

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    folder = seamless::fuzz::scratch_folder("scene");
    std::ofstream(folder / "m.json")
        << R"({"version": 1, "surfaces": [{"degree": [1, 1], "size": [2, 2],
               "knots_u": [0, 0, 1, 1], "knots_v": [0, 0, 1, 1],
               "control_points": [[0, 0, 0], [0, 1, 0], [1, 0, 0], [1, 1, 1]]}]})";
    std::ofstream(folder / "m.bpt") << "1\n1 1\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n";
    std::ofstream(folder / "c.json") << seamless::to_json(seamless::test::small_assembly());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    // Errors in the models a scene names name those files, not the scene.
    seamless::fuzz::expect_clean("", [&] {
        (void)seamless::parse_scene(seamless::fuzz::bytes(data, size), "fuzz-scene.json", folder);
    });
    return 0;
}
