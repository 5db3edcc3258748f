// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string_view>
#include <vector>

namespace support {

/// Lines of `text` without their line terminators ("\n" or "\r\n"); a final line without a
/// terminator is kept.
std::vector<std::string_view> split_lines(std::string_view text);

/// Whitespace-separated words of `line`.
std::vector<std::string_view> split_words(std::string_view line);

/// The whole token as a double ("1e-5", "-0", "nan", "-nan", "inf"), or empty.
std::optional<double> parse_number(std::string_view token);

}  // namespace support
