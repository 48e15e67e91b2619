// SPDX-License-Identifier: MIT
// libFuzzer harness: the .ply mesh reader (parse_mesh, from memory).
#include "fuzz_common.h"

#include <seamless/mesh/io/mesh_io.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    seamless::fuzz::expect_clean("fuzz.ply", [&] {
        (void)seamless::parse_mesh(seamless::fuzz::bytes(data, size), ".ply", "fuzz.ply");
    });
    return 0;
}
