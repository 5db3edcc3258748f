// SPDX-License-Identifier: MIT
#include "reference/lammps/lammps_runner.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <map>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

#include "reference/common/banner_probe.hpp"
#include "reference/common/log_lines.hpp"
#include "reference/common/run_directory.hpp"
#include "reference/lammps/log_scan.hpp"
#include "support/interrupts.hpp"
#include "support/process.hpp"
#include "support/text_file.hpp"
#include "support/utf8.hpp"

namespace reference::lammps {
namespace {

/// Lines of the log and of stderr kept for reports.
constexpr std::size_t kLogTailLines = 30;
constexpr std::size_t kStderrTailLines = 10;

/// The last lines of log.lammps and of stderr, each under a title.
std::string tail_of(const std::filesystem::path& dir) {
  std::string out;
  const std::string log = support::file_tail(dir / kLogFile, kLogTailLines);
  out += log.empty() ? std::string("(log.lammps is empty or missing)\n")
                     : fmt::format("log.lammps (last {} lines):\n{}", kLogTailLines, log);
  const std::string err = support::file_tail(dir / kStderrFile, kStderrTailLines);
  if (!err.empty()) out += fmt::format("stderr (last {} lines):\n{}", kStderrTailLines, err);
  return out;
}

}  // namespace

std::filesystem::path make_run_directory(const std::filesystem::path& parent) {
  return reference::make_run_directory(parent, "lammps");
}

LammpsProbe probe_lammps(const std::string& program, double timeout_s) {
  return probe_banner(program, timeout_s, "LAMMPS", &banner_version);
}

std::optional<std::string> lammps_version(const std::string& program, double timeout_s) {
  return probe_lammps(program, timeout_s).version;
}

LammpsRunOutcome run_lammps(const std::string& program, const std::filesystem::path& dir,
                            double timeout_s) {
  support::ProcessSpec spec;
  spec.argv = {program, "-in", kDeckFile, "-log", kLogFile, "-screen", "none"};
  spec.working_directory = dir;
  spec.stdout_file = dir / kStdoutFile;
  spec.stderr_file = dir / kStderrFile;
  spec.environment = mpi_singleton_environment(dir);
  spec.timeout_s = timeout_s;
  const support::ProcessResult r = support::run_process(spec);

  LammpsRunOutcome out;
  const std::string log = support::read_file_or_empty(dir / kLogFile);
  out.log_tail = tail_of(dir);
  out.warnings = warning_lines(log);
  out.version = banner_version(log);
  const std::string error = first_error(log);
  const std::string detail = error.empty() ? "" : ": " + error;
  if (!r.started) {
    out.reason = fmt::format("LAMMPS could not be started: {}", r.error);
  } else if (r.timed_out) {
    out.reason = fmt::format("LAMMPS timed out after {:.3g} s and was killed", timeout_s);
  } else if (r.signal) {
    out.reason = fmt::format("LAMMPS was killed by signal {} ({}){}", *r.signal,
                             strsignal(*r.signal), detail);
  } else if (r.exit_code != 0) {
    out.reason = fmt::format("LAMMPS exited with status {}{}", r.exit_code,
                             error.empty() ? " and no ERROR line in its log" : detail);
  } else {
    out.ok = true;
  }
  return out;
}

}  // namespace reference::lammps
