// SPDX-License-Identifier: MIT
#include "reference/yade/yade_installation.hpp"

#include <unistd.h>

#include <exception>

#include "support/text_file.hpp"

namespace reference::yade {

YadeInstallation default_yade_installation() {
  return {"/usr/bin/python3.11", "/usr/lib/x86_64-linux-gnu/yade-double/py"};
}

std::optional<std::string> parse_config_version(std::string_view text) {
  constexpr std::string_view kKey = "version=";
  std::size_t at = text.starts_with(kKey) ? 0 : text.find("\n" + std::string(kKey));
  if (at == std::string_view::npos) return std::nullopt;
  if (at != 0) ++at;  // skip the newline
  std::string_view rest = text.substr(at + kKey.size());
  if (rest.empty() || (rest.front() != '\'' && rest.front() != '"')) return std::nullopt;
  const char quote = rest.front();
  rest.remove_prefix(1);
  const auto end = rest.find(quote);
  if (end == std::string_view::npos || end == 0) return std::nullopt;
  if (rest.substr(0, end).find('\n') != std::string_view::npos) return std::nullopt;
  return std::string(rest.substr(0, end));
}

std::optional<std::string> detect_yade_version(const YadeInstallation& install) {
  if (install.python.empty() || ::access(install.python.c_str(), X_OK) != 0) return std::nullopt;
  const auto config = install.module_dir / "yade" / "config.py";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(config, ec)) return std::nullopt;
  std::string text;
  try {
    text = support::read_file(config);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  const auto version = parse_config_version(text);
  if (!version) return std::nullopt;
  return "YADE " + *version;
}

}  // namespace reference::yade
