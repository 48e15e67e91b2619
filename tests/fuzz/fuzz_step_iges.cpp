// SPDX-License-Identifier: MIT
// libFuzzer harness: the STEP/IGES reader (OpenCASCADE), then knot insertion
// of what it accepts. OpenCASCADE reads files only, so each input goes to a
// scratch file: `.step` when it starts like a STEP exchange file
// ("ISO-10303-21"), `.igs` otherwise. OpenCASCADE is not instrumented (its
// own code gets neither coverage nor sanitizer checks; docs/fuzzing.md).
#include "fuzz_common.h"

#include <seamless/model/step_iges.h>

#include <cstring>
#include <filesystem>
#include <fstream>

namespace {

std::filesystem::path folder;

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    folder = seamless::fuzz::scratch_folder("step-iges");
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const char step_magic[] = "ISO-10303-21";
    const bool step =
        size >= sizeof step_magic - 1 && std::memcmp(data, step_magic, sizeof step_magic - 1) == 0;
    const std::filesystem::path file = folder / (step ? "fuzz.step" : "fuzz.igs");
    {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
        if (!out) __builtin_trap(); // the scratch folder must take the input
    }
    seamless::fuzz::expect_clean(file.string(), [&] {
        const seamless::Model m = seamless::read_step_iges(file);
        (void)seamless::bezier_patches(m);
    });
    return 0;
}
