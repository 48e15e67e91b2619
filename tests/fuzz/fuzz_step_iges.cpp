// SPDX-License-Identifier: MIT
// libFuzzer harness: STEP and IGES as a user reads them, through the reader's
// process (read_step_iges: the reader's server forks a worker that runs
// OpenCASCADE and hands the model back), then knot insertion of what it
// accepts. OpenCASCADE reads files only, so each input goes to a scratch
// file: `.step` when it starts like a STEP exchange file ("ISO-10303-21"),
// `.igs` otherwise. A crash, a time-out or a sanitizer report in the worker
// is a clean result (one InputError naming the file; the report is in the
// log); one in this process is a finding (docs/fuzzing.md).
#include "fuzz_common.h"

#include <seamless/model/step_iges.h>

#include <cstring>
#include <filesystem>
#include <fstream>

namespace {

std::filesystem::path folder;
seamless::ModelLoadOptions options;

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    folder = seamless::fuzz::scratch_folder("step-iges");
    // Below libFuzzer's -timeout (10 s in scripts/test.sh): OpenCASCADE's
    // slow paths under ASan end as a clean time-out of the worker.
    options.reader_time_limit = 5;
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
        const seamless::Model m = seamless::read_step_iges(file, options);
        (void)seamless::bezier_patches(m);
    });
    return 0;
}
