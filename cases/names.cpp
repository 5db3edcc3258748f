// SPDX-License-Identifier: MIT
#include "cases/names.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "cases/excerpt.hpp"

namespace cases {

namespace {

/// 1 to kMaxNameLength characters, each accepted by `allowed`.
template <class Allowed>
bool made_of(std::string_view text, Allowed allowed) noexcept {
  return !text.empty() && text.size() <= kMaxNameLength && std::all_of(text.begin(), text.end(), allowed);
}

/// A digit, '_' or a lowercase letter.
bool lower_word_char(char c) noexcept { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; }

}  // namespace

bool is_name(std::string_view text) noexcept {
  return made_of(text, [](char c) { return lower_word_char(c) || (c >= 'A' && c <= 'Z') || c == '-' || c == '.'; });
}

bool is_identifier(std::string_view text, bool upper) noexcept {
  return made_of(text, [upper](char c) { return lower_word_char(c) || (upper && c >= 'A' && c <= 'Z'); });
}

std::string read_name(const loader::Value& value) {
  std::string text = value.string();
  if (!is_name(text)) {
    value.fail(fmt::format("'{}' is not a name: 1 to {} characters from A-Z, a-z, 0-9, '_', '-' and '.'",
                           excerpt(text, kMaxNameLength), kMaxNameLength));
  }
  return text;
}

}  // namespace cases
