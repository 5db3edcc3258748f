// SPDX-License-Identifier: MIT
#include "cases/excerpt.hpp"

#include <fmt/format.h>

namespace cases {
namespace {

/// True for a byte that continues a UTF-8 sequence (10xxxxxx).
bool continuation_byte(char c) noexcept { return (static_cast<unsigned char>(c) & 0xC0U) == 0x80U; }

}  // namespace

std::string excerpt(std::string_view text, std::size_t limit) {
  std::size_t end = text.size();
  if (end > limit) {
    end = limit;
    while (end > 0 && continuation_byte(text[end])) --end;  // do not split a character
  }
  std::string out;
  out.reserve(end + 24);
  for (std::size_t i = 0; i < end; ++i) {
    const auto u = static_cast<unsigned char>(text[i]);
    if (u < 0x20U || u == 0x7FU) {
      out += fmt::format("\\x{:02x}", u);
    } else {
      out += text[i];
    }
  }
  if (end < text.size()) out += fmt::format("…({} bytes)", text.size());
  return out;
}

}  // namespace cases
