// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <string_view>

namespace support {

/// `text` as valid UTF-8: every byte that does not begin or continue a well-formed sequence
/// (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF) becomes U+FFFD, and
/// control characters other than tab and newline become U+FFFD too. For text an external program
/// wrote (logs, error messages), before it reaches JSON, markdown or a terminal.
std::string printable_utf8(std::string_view text);

}  // namespace support
