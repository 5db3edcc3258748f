// SPDX-License-Identifier: MIT
#include "reference/lammps/log_scan.hpp"

#include "support/text_tokens.hpp"

namespace reference::lammps {

using support::split_lines;
namespace {

bool starts_with(std::string_view text, std::string_view prefix) {
  return text.substr(0, prefix.size()) == prefix;
}

}  // namespace

std::optional<std::string> banner_version(std::string_view log_text) {
  constexpr std::string_view kBanner = "LAMMPS (";
  for (const std::string_view line : split_lines(log_text)) {
    if (!starts_with(line, kBanner)) continue;
    const auto close = line.rfind(')');
    if (close == std::string_view::npos || close <= kBanner.size()) continue;
    return "LAMMPS " + std::string(line.substr(kBanner.size(), close - kBanner.size()));
  }
  return std::nullopt;
}

}  // namespace reference::lammps
