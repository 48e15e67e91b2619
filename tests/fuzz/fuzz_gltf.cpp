// SPDX-License-Identifier: MIT
// libFuzzer harness: the .gltf mesh reader (parse_mesh, from memory; external
// buffers resolve against an empty base folder).
#include "fuzz_common.h"

#include <seamless/mesh/io/mesh_io.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    seamless::fuzz::expect_clean("fuzz.gltf", [&] {
        (void)seamless::parse_mesh(seamless::fuzz::bytes(data, size), ".gltf", "fuzz.gltf");
    });
    return 0;
}
