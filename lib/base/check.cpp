// SPDX-License-Identifier: MIT
#include <seamless/base/check.h>

#include <cstdio>
#include <cstdlib>

namespace seamless {

void check_failed(const char* file, int line, const char* cond, const char* msg) {
    std::fprintf(stderr, "seamless: internal error at %s:%d: %s (%s)\n", file, line, cond, msg);
    std::fflush(stderr);
    std::abort();
}

} // namespace seamless
