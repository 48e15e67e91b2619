// SPDX-License-Identifier: MIT
// libFuzzer harness: the .obj mesh reader (parse_mesh, from memory).
#include "fuzz_common.h"

#include <seamless/mesh/io/mesh_io.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    seamless::fuzz::expect_clean("fuzz.obj", [&] {
        (void)seamless::parse_mesh(seamless::fuzz::bytes(data, size), ".obj", "fuzz.obj");
    });
    return 0;
}
