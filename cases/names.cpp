// SPDX-License-Identifier: MIT
#include "cases/names.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace cases {

bool is_name(std::string_view text) noexcept {
  const auto allowed = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-' || c == '.';
  };
  return !text.empty() && text.size() <= kMaxNameLength && std::all_of(text.begin(), text.end(), allowed);
}

std::string read_name(const loader::Value& value) {
  std::string text = value.string();
  if (!is_name(text)) {
    std::string shown;
    for (const char c : text.substr(0, kMaxNameLength)) {
      const auto u = static_cast<unsigned char>(c);
      shown += u < 0x20 || u == 0x7f ? fmt::format("\\x{:02x}", u) : std::string(1, c);
    }
    value.fail(fmt::format("'{}'{} is not a name: 1 to {} characters from A-Z, a-z, 0-9, '_', '-' and '.'",
                           shown, text.size() > kMaxNameLength ? "…" : "", kMaxNameLength));
  }
  return text;
}

}  // namespace cases
