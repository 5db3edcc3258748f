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

/// What a `yade` launcher script says about its installation: the interpreter of its `#!` line
/// (with `/usr/bin/env NAME`, the bare NAME) and the module directory of its
/// `sys.path.insert(1,'…')` line. Empty when the text is not such a script. Pure.
std::optional<YadeInstallation> parse_yade_launcher(std::string_view launcher_text);

/// A YADE installation found from its launcher, or why not.
struct LauncherLookup {
  std::optional<YadeInstallation> install;
  std::filesystem::path launcher;  ///< full path of the launcher, when found
  std::string problem;             ///< why there is no installation (empty when found)
};

/// Finds the launcher `program` (a path, or a name searched in PATH), reads its first 64 KiB and
/// resolves its interpreter in PATH when the `#!` line names it through env.
LauncherLookup find_yade_installation(const std::string& program);

/// The value of `version='…'` in the text of yade/config.py, or empty. Pure.
std::optional<std::string> parse_config_version(std::string_view config_text);

/// "YADE <version>" when the interpreter is executable and <module_dir>/yade/config.py names a
/// version; empty otherwise. Reads one file and starts no process.
std::optional<std::string> detect_yade_version(const YadeInstallation& install);

}  // namespace reference::yade
