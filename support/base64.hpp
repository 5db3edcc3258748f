// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace support {

/// `bytes` in the standard Base64 alphabet with '=' padding (RFC 4648, section 4), for binary
/// data kept inside JSON text.
std::string base64_encode(std::string_view bytes);

/// The bytes a canonical RFC 4648 Base64 text stands for; nullopt when `text` is not one (a
/// character outside the alphabet, a wrong length, misplaced or non-canonical padding).
std::optional<std::string> base64_decode(std::string_view text);

}  // namespace support
