// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace reference::yade {

/// Where YADE's Python modules live and which interpreter they were built for. YADE is driven
/// by importing it as a module under that interpreter, never through the `yade` launcher (which
/// opens a TCP prompt (port 9000+) and an XMLRPC server (21000+) on all interfaces).
struct YadeInstallation {
  std::filesystem::path python;      ///< interpreter of YADE's Boost.Python modules
  std::filesystem::path module_dir;  ///< directory that holds the `yade` package
};

/// The Debian 2023.02a layout: /usr/bin/python3.11 and the double-precision build's modules.
YadeInstallation default_yade_installation();

/// The value of `version='…'` in the text of yade/config.py, or empty. Pure.
std::optional<std::string> parse_config_version(std::string_view config_text);

/// "YADE <version>" when the interpreter is executable and <module_dir>/yade/config.py names a
/// version; empty otherwise. Reads one file and starts no process.
std::optional<std::string> detect_yade_version(const YadeInstallation& install);

}  // namespace reference::yade
