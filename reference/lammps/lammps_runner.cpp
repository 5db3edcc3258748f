// SPDX-License-Identifier: MIT
#include "reference/lammps/lammps_runner.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <map>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

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

/// Text of a file, or "" when it cannot be read.
std::string read_or_empty(const std::filesystem::path& path) {
  try {
    return support::read_file(path);
  } catch (const std::exception&) {
    return "";
  }
}

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
  // Absolute, because the child process changes into it before opening its output files.
  const std::filesystem::path base = std::filesystem::absolute(
      parent.empty() ? std::filesystem::temp_directory_path() : parent);
  std::error_code ec;
  std::filesystem::create_directories(base, ec);
  if (ec) {
    throw std::runtime_error(
        fmt::format("cannot create directory {}: {}", base.string(), ec.message()));
  }
  std::string pattern = (base / "lammps-run-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    throw std::runtime_error(fmt::format("cannot create a run directory in {}: {}", base.string(),
                                         std::strerror(errno)));
  }
  return pattern;
}

namespace {

/// The environment of one LAMMPS process: one OpenMP thread, and Open MPI's session directory
/// inside the run's own directory. Debian's lmp is an MPI program: started as a singleton it
/// creates /tmp/ompi.<host>.<uid>, and two runs starting at the same instant (fuzz-matched -j 2)
/// race on that mkdir and one exits with status 1 ("File exists") before LAMMPS starts.
std::map<std::string, std::string> lammps_environment(const std::filesystem::path& dir) {
  return {{"OMP_NUM_THREADS", "1"}, {"OMPI_MCA_orte_tmpdir_base", dir.string()}};
}

}  // namespace

LammpsProbe probe_lammps(const std::string& program, double timeout_s) {
  LammpsProbe probe;
  if (!support::find_program(program)) return probe;
  std::filesystem::path dir;
  try {
    dir = make_run_directory({});
  } catch (const std::exception& e) {
    probe.version = fmt::format("LAMMPS (version unknown: {})", e.what());
    return probe;
  }
  const support::OwnedPathGuard partial(dir);
  support::ProcessSpec spec;
  spec.argv = {program, "-in", "/dev/null", "-log", (dir / kLogFile).string(), "-screen", "none"};
  spec.environment = lammps_environment(dir);
  spec.timeout_s = timeout_s;
  const support::ProcessResult r = support::run_process(spec);
  probe.seconds = r.wall_time_s;
  probe.timed_out = r.timed_out;
  const std::optional<std::string> banner = banner_version(read_or_empty(dir / kLogFile));
  std::error_code ignored;
  std::filesystem::remove_all(dir, ignored);
  if (r.timed_out) {
    probe.version = fmt::format("LAMMPS (version unknown: {} did not finish an empty run within {:.3g} s)",
                                program, timeout_s);
  } else if (banner) {
    probe.version = support::printable_utf8(*banner);
  } else if (!r.started) {
    probe.version = fmt::format("LAMMPS (version unknown: {})", r.error);
  } else {
    probe.version = fmt::format("LAMMPS (version unknown: {} wrote no banner, exit status {})", program,
                                r.exit_code);
  }
  return probe;
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
  spec.environment = lammps_environment(dir);
  spec.timeout_s = timeout_s;
  const support::ProcessResult r = support::run_process(spec);

  LammpsRunOutcome out;
  const std::string log = read_or_empty(dir / kLogFile);
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
