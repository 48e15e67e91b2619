// SPDX-License-Identifier: MIT
// libFuzzer harness: the .stl mesh reader, ASCII and binary (parse_mesh, from
// memory; the reader tells them apart by the size a binary file must have).
#include "fuzz_common.h"

#include <seamless/mesh/io/mesh_io.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    seamless::fuzz::expect_clean("fuzz.stl", [&] {
        (void)seamless::parse_mesh(seamless::fuzz::bytes(data, size), ".stl", "fuzz.stl");
    });
    return 0;
}
