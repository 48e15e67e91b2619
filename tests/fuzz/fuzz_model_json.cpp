// SPDX-License-Identifier: MIT
// libFuzzer harness: the JSON model reader (versions 1 and 2), then knot
// insertion of what it accepts (a model it passes must be usable) and its
// JSON text, which must read back to the same text.
#include "fuzz_common.h"

#include <seamless/model/model.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    seamless::Model m;
    bool accepted = false;
    seamless::fuzz::expect_clean("fuzz.json", [&] {
        m = seamless::parse_model_json(seamless::fuzz::bytes(data, size), "fuzz.json");
        (void)seamless::bezier_patches(m);
        accepted = true;
    });
    if (accepted) {
        // Outside expect_clean: an InputError here is a finding.
        const std::string text = seamless::to_json(m);
        if (seamless::to_json(seamless::parse_model_json(text, "again.json")) != text)
            __builtin_trap();
    }
    return 0;
}
