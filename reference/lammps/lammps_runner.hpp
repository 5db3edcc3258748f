// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "reference/common/banner_probe.hpp"

namespace reference::lammps {

/// File names inside a run directory.
inline constexpr const char* kDeckFile = "deck.in";
inline constexpr const char* kLogFile = "log.lammps";
inline constexpr const char* kStdoutFile = "stdout.txt";
inline constexpr const char* kStderrFile = "stderr.txt";

/// Seconds the version probe may take by default: an empty run prints its banner in well under
/// one second, so a binary that has not answered in ten is hung.
inline constexpr double kProbeTimeout = 10.0;

/// What asking a LAMMPS binary for its version found.
using LammpsProbe = BannerProbe;

/// Runs `program` on an empty input (`-in /dev/null -log … -screen none`, killed after
/// `timeout_s`) and reads the version from its log banner ("LAMMPS 29 Sep 2021 - Update 2").
/// A binary that runs but prints no banner gives "LAMMPS (version unknown: …)".
LammpsProbe probe_lammps(const std::string& program, double timeout_s);

/// The version of probe_lammps(program, timeout_s), empty when `program` is not found.
std::optional<std::string> lammps_version(const std::string& program, double timeout_s = kProbeTimeout);

/// How one LAMMPS run ended.
struct LammpsRunOutcome {
  bool ok = false;                    ///< exited with status 0
  std::string reason;                 ///< why not, with the first ERROR line of the log
  std::string log_tail;               ///< last lines of log.lammps and stderr (always filled)
  std::vector<std::string> warnings;  ///< WARNING lines of the log
  std::optional<std::string> version; ///< banner version from the log
};

/// Runs `program -in deck.in -log log.lammps -screen none` in `dir` (which holds deck.in) with
/// OMP_NUM_THREADS=1, stdout/stderr to files, killed after `timeout_s`.
LammpsRunOutcome run_lammps(const std::string& program, const std::filesystem::path& dir,
                            double timeout_s);

/// A new, empty directory "<parent>/lammps-run-XXXXXX", as an absolute path (parent created if
/// needed; the system temporary directory when `parent` is empty). Throws std::runtime_error
/// when it cannot.
std::filesystem::path make_run_directory(const std::filesystem::path& parent);

}  // namespace reference::lammps
