// SPDX-License-Identifier: MIT
#include "reference/common/deck_comment.hpp"

namespace reference {

std::string deck_comment_text(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    const auto u = static_cast<unsigned char>(c);
    if (u > 0x7e || u < 0x20) c = '?';
    if (c == '"') c = '\'';
  }
  return out;
}

}  // namespace reference
