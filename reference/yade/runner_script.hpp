// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>

namespace reference::yade {

/// The Python wrapper that runs a YADE script by importing yade as a module from `module_dir`
/// (same output as through the launcher): no `yade` launcher, hence no TCP prompt and no XMLRPC
/// server. Usage: `python3.11 runner.py script.py [args…]`; the script sees sys.argv =
/// [script.py, args…] and the names a `yade -x` script sees (O, utils, the class names, Vector3,
/// math). Sets OMP_NUM_THREADS=1 and HOME (to the working directory) when unset, before yade is
/// loaded. Pure.
std::string yade_runner_script(const std::filesystem::path& module_dir);

}  // namespace reference::yade
