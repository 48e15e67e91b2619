// SPDX-License-Identifier: MIT
// libFuzzer harness: the binary model form in which the STEP/IGES reader's
// process answers the library (model_exchange.h), then knot insertion of what
// it accepts. Seeds: the answers for the small CAD files of the step_iges
// corpus (with and without a B-rep).
#include "fuzz_common.h"

#include <seamless/model/model_exchange.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    seamless::fuzz::expect_clean("answer.bin", [&] {
        const seamless::Model m =
            seamless::read_model_exchange(seamless::fuzz::bytes(data, size), "answer.bin");
        (void)seamless::bezier_patches(m);
    });
    return 0;
}
