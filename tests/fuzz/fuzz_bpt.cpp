// SPDX-License-Identifier: MIT
// libFuzzer harness: the Newell Bezier patch (.bpt) reader, then knot
// insertion of what it accepts.
#include "fuzz_common.h"

#include <seamless/model/model.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    seamless::fuzz::expect_clean("fuzz.bpt", [&] {
        const seamless::Model m =
            seamless::parse_bpt(seamless::fuzz::bytes(data, size), "fuzz.bpt");
        (void)seamless::bezier_patches(m);
    });
    return 0;
}
