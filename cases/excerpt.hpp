// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace cases {

/// Longest part of a value from a case file that a message quotes [bytes].
inline constexpr std::size_t kMaxEchoedValue = 80;
/// Longest dotted key a message shows [bytes] (keys hold names taken from the file).
inline constexpr std::size_t kMaxEchoedKey = 160;
/// Longest problem text a message shows [bytes]: a safety net behind the per-value excerpts.
inline constexpr std::size_t kMaxEchoedProblem = 4096;

/// `text` made fit to quote in a one-line message: every control character (and DEL) written as
/// `\xNN`, and, when `text` is longer than `limit` bytes, only its first `limit` bytes (cut at a
/// UTF-8 character boundary) followed by "…(N bytes)", N the length of the whole text. A case
/// file is untrusted: a 3 MB string or one holding line breaks must not reach stderr whole.
[[nodiscard]] std::string excerpt(std::string_view text, std::size_t limit = kMaxEchoedValue);

}  // namespace cases
