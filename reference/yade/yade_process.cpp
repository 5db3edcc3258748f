// SPDX-License-Identifier: MIT
#include "reference/yade/yade_process.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "reference/yade/runner_script.hpp"
#include "support/interrupts.hpp"
#include "support/text_file.hpp"

namespace reference::yade {
namespace {

/// A new, empty directory `<root>/yade-XXXXXX` (mkdtemp: unique even across processes).
std::filesystem::path unique_directory(const std::filesystem::path& root) {
  std::filesystem::create_directories(root);
  std::string pattern = (root / "yade-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    throw std::runtime_error(fmt::format("cannot create a work directory under {}: {}", root.string(),
                                         std::strerror(errno)));
  }
  return pattern;
}

/// Last non-empty line of `text`.
std::string_view last_line(std::string_view text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) {
    text.remove_suffix(1);
  }
  const auto nl = text.rfind('\n');
  return nl == std::string_view::npos ? text : text.substr(nl + 1);
}

}  // namespace

std::string process_failure(const support::ProcessResult& p, std::string_view stderr_tail) {
  std::string reason;
  if (!p.started) {
    reason = fmt::format("cannot start the YADE interpreter: {}", p.error);
  } else if (p.timed_out) {
    reason = fmt::format("YADE run timed out after {:.0f} s and was killed", p.wall_time_s);
  } else if (p.signal) {
    reason = fmt::format("YADE run was killed by signal {}", *p.signal);
  } else if (p.exit_code != 0) {
    reason = fmt::format("YADE script failed with exit code {}", p.exit_code);
  } else {
    return "";
  }
  const std::string_view last = last_line(stderr_tail);
  if (!last.empty() && p.started && !p.timed_out) reason += fmt::format(": {}", last);
  return reason;
}

YadeProcessOutcome run_yade_script(const YadeInstallation& install, std::string_view script,
                                   const std::filesystem::path& work_root, double timeout_s) {
  YadeProcessOutcome out;
  const std::filesystem::path root = work_root.empty()
                                         ? std::filesystem::temp_directory_path() / "demwb-yade"
                                         : work_root;
  out.directory = unique_directory(std::filesystem::absolute(root));
  const support::OwnedPathGuard partial(out.directory);  // removed if interrupted mid-run
  support::write_file(out.directory / "runner.py", yade_runner_script(install.module_dir));
  support::write_file(out.directory / "script.py", script);

  support::ProcessSpec spec;
  spec.argv = {install.python.string(), "runner.py", "script.py"};
  spec.working_directory = out.directory;
  spec.stdout_file = out.directory / "stdout.txt";
  spec.stderr_file = out.directory / "stderr.txt";
  spec.environment = {{"OMP_NUM_THREADS", "1"}};
  spec.timeout_s = timeout_s;
  out.process = support::run_process(spec);

  const std::string err = support::file_tail(spec.stderr_file, 30);
  const std::string std_out = support::file_tail(spec.stdout_file, 10);
  out.failure = process_failure(out.process, err);
  if (!err.empty()) out.log_tail += "--- YADE stderr (last lines) ---\n" + err;
  if (!std_out.empty()) out.log_tail += "--- YADE stdout (last lines) ---\n" + std_out;
  return out;
}

}  // namespace reference::yade
