// SPDX-License-Identifier: MIT
// libFuzzer harness: the version-1 JSON model reader, then knot insertion of
// what it accepts (a model it passes must be usable).
#include "fuzz_common.h"

#include <seamless/model/model.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    seamless::fuzz::expect_clean("fuzz.json", [&] {
        const seamless::Model m =
            seamless::parse_model_json(seamless::fuzz::bytes(data, size), "fuzz.json");
        (void)seamless::bezier_patches(m);
    });
    return 0;
}
