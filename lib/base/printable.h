// SPDX-License-Identifier: MIT
// Text from a user's file made safe to print on one terminal line: error
// messages quote names and tokens from hostile input, which may hold binary
// bytes, newlines or terminal escape sequences.
#pragma once

#include <string>
#include <string_view>

namespace seamless {

// Valid UTF-8 is kept, except control characters (C0, DEL and the C1 range
// U+0080..U+009F, so that no ESC or CSI sequence reaches the terminal), which
// become \n, \r, \t, \e or \xNN, as do the bytes of invalid UTF-8 sequences.
std::string printable(std::string_view text);

} // namespace seamless
