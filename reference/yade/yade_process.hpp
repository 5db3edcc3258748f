// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "reference/yade/yade_installation.hpp"
#include "support/process.hpp"

namespace reference::yade {

/// How one YADE process ended and where its files are.
struct YadeProcessOutcome {
  std::filesystem::path directory;  ///< this run's own working directory
  support::ProcessResult process;
  std::string failure;   ///< empty when the process exited with code 0; else why not
  std::string log_tail;  ///< last lines of stderr and stdout (Python traceback included)
};

/// Creates a fresh directory under `work_root` (unique, so concurrent runs never collide),
/// writes runner.py (runner_script.hpp) and script.py into it, and runs
/// `<python> runner.py script.py` there with OMP_NUM_THREADS=1, stdout/stderr to files, killed
/// after `timeout_s`. Throws std::runtime_error only when the directory or files cannot be
/// created; a failing or missing interpreter is reported in `failure`.
YadeProcessOutcome run_yade_script(const YadeInstallation& install, std::string_view script,
                                   const std::filesystem::path& work_root, double timeout_s);

/// A reason for a failed process: exit code or signal or timeout, plus the last line of stderr
/// (a Python exception's message). Empty when it exited with code 0. Pure.
std::string process_failure(const support::ProcessResult& process, std::string_view stderr_tail);

}  // namespace reference::yade
