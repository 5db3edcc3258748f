// SPDX-License-Identifier: MIT
#include "reference/common/log_lines.hpp"

#include "support/text_tokens.hpp"

namespace reference {
namespace {

bool starts_with(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

}  // namespace

std::string first_error(std::string_view log_text) {
  const std::vector<std::string_view> lines = support::split_lines(log_text);
  for (std::size_t k = 0; k < lines.size(); ++k) {
    if (!starts_with(lines[k], "ERROR")) continue;
    std::string out(lines[k]);
    if (k + 1 < lines.size() && starts_with(lines[k + 1], "Last command:")) {
      out += " (" + std::string(lines[k + 1]) + ")";
    }
    return out;
  }
  return "";
}

std::vector<std::string> warning_lines(std::string_view log_text) {
  std::vector<std::string> out;
  for (const std::string_view line : support::split_lines(log_text)) {
    if (starts_with(line, "WARNING")) out.emplace_back(line);
  }
  return out;
}

}  // namespace reference
