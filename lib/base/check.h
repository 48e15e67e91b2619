// SPDX-License-Identifier: MIT
// Invariants, checked (pbrt-v4's CHECK and DCHECK). A failed check is a bug in
// seamless, never bad input (bad input is an InputError, error.h): it prints
// the condition, its file and line and a message to stderr and aborts, so a
// certified result is never built on a broken invariant.
//  - SEAMLESS_CHECK(cond, msg): always on, Release included. For what a
//    certificate rests on (an enclosure that must hold a point, a box that
//    must not be empty, an index in range) where the test costs little beside
//    the work around it.
//  - SEAMLESS_DCHECK(cond, msg): for costly checks inside hot loops; on when
//    NDEBUG is not defined (Debug and the sanitizer build of scripts/test.sh,
//    which runs the interval, spline, model, tessellate, mesh, render and CLI
//    tests), compiled out in Release. Its condition must have no side effect.
// msg is a string literal saying what broke, in the words of the code around.
#pragma once

namespace seamless {

// Prints "seamless: internal error at FILE:LINE: COND (MSG)" and aborts.
[[noreturn]] void check_failed(const char* file, int line, const char* cond, const char* msg);

} // namespace seamless

#define SEAMLESS_CHECK(cond, msg)                                                                  \
    do {                                                                                           \
        if (!(cond)) [[unlikely]]                                                                  \
            ::seamless::check_failed(__FILE__, __LINE__, #cond, msg);                              \
    } while (false)

#ifdef NDEBUG
// sizeof keeps the condition compiled (so it cannot rot) but never evaluated.
#define SEAMLESS_DCHECK(cond, msg)                                                                 \
    do {                                                                                           \
        (void)sizeof(!(cond));                                                                     \
    } while (false)
#else
#define SEAMLESS_DCHECK(cond, msg) SEAMLESS_CHECK(cond, msg)
#endif
