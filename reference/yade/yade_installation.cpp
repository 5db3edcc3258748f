// SPDX-License-Identifier: MIT
#include "reference/yade/yade_installation.hpp"

#include <unistd.h>

#include <exception>
#include <fstream>

#include <fmt/format.h>

#include "support/process.hpp"
#include "support/text_file.hpp"
#include "support/utf8.hpp"

namespace reference::yade {

YadeInstallation default_yade_installation() {
  return {"/usr/bin/python3.11", "/usr/lib/x86_64-linux-gnu/yade-double/py"};
}

std::optional<YadeInstallation> parse_yade_launcher(std::string_view text) {
  if (!text.starts_with("#!")) return std::nullopt;
  std::string_view shebang = text.substr(2, text.find('\n') == std::string_view::npos ? text.size() - 2 : text.find('\n') - 2);
  const auto trim = [](std::string_view v) {
    while (!v.empty() && (v.front() == ' ' || v.front() == '\t')) v.remove_prefix(1);
    while (!v.empty() && (v.back() == ' ' || v.back() == '\t' || v.back() == '\r')) v.remove_suffix(1);
    return v;
  };
  shebang = trim(shebang);
  std::string_view interpreter = shebang.substr(0, shebang.find_first_of(" \t"));
  if (interpreter.ends_with("/env")) {  // "#!/usr/bin/env python3": the name after env
    interpreter = trim(shebang.substr(interpreter.size()));
    interpreter = interpreter.substr(0, interpreter.find_first_of(" \t"));
  }
  if (interpreter.empty() || interpreter.find("python") == std::string_view::npos) return std::nullopt;
  constexpr std::string_view kInsert = "sys.path.insert(";
  const auto at = text.find(kInsert);
  if (at == std::string_view::npos) return std::nullopt;
  std::string_view rest = text.substr(at + kInsert.size());
  const auto quote = rest.find_first_of("'\"");
  const auto line_end = rest.find('\n');
  if (quote == std::string_view::npos || (line_end != std::string_view::npos && quote > line_end)) return std::nullopt;
  const char q = rest[quote];
  rest.remove_prefix(quote + 1);
  const auto close = rest.find(q);
  if (close == std::string_view::npos || close == 0) return std::nullopt;
  const std::string_view dir = rest.substr(0, close);
  if (dir.find('\n') != std::string_view::npos || dir.front() != '/') return std::nullopt;
  return YadeInstallation{std::string(interpreter), std::string(dir)};
}

LauncherLookup find_yade_installation(const std::string& program) {
  LauncherLookup out;
  const auto launcher = support::find_program(program);
  if (!launcher) {
    out.problem = fmt::format("'{}' not found (choose the launcher with --yade PATH or DEMWB_YADE)", program);
    return out;
  }
  out.launcher = *launcher;
  std::ifstream in(*launcher, std::ios::binary);
  std::string text(64 * 1024, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  auto install = parse_yade_launcher(text);
  if (!install) {
    out.problem = fmt::format("{} is not a YADE launcher script (no python #! line or no "
                              "sys.path.insert line naming its modules)",
                              launcher->string());
    return out;
  }
  if (install->python.string().find('/') == std::string::npos) {
    const auto python = support::find_program(install->python.string());
    if (!python) {
      out.problem = fmt::format("{}: its interpreter {} is not in PATH", launcher->string(), install->python.string());
      return out;
    }
    install->python = *python;
  }
  out.install = std::move(install);
  return out;
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
  return "YADE " + support::printable_utf8(*version);
}

}  // namespace reference::yade
