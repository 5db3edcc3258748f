// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "reference/common/banner_probe.hpp"

namespace reference::liggghts {

/// File names inside a run directory.
inline constexpr const char* kDeckFile = "deck.in";
inline constexpr const char* kLogFile = "log.liggghts";
inline constexpr const char* kScreenFile = "screen.txt";
inline constexpr const char* kStderrFile = "stderr.txt";

/// Seconds the version probe may take by default (an empty run prints its banner at once).
inline constexpr double kProbeTimeout = 10.0;

/// What asking a LIGGGHTS binary for its version found.
using LiggghtsProbe = BannerProbe;

/// The version in a LIGGGHTS banner: "LIGGGHTS (Version LIGGGHTS-PUBLIC 3.8.0, compiled …)" →
/// "LIGGGHTS-PUBLIC 3.8.0"; empty when the text has no banner.
std::optional<std::string> banner_version(std::string_view log_text);

/// Runs `program` on an empty input (killed after `timeout_s`) and reads its banner.
LiggghtsProbe probe_liggghts(const std::string& program, double timeout_s);

/// How one LIGGGHTS run ended.
struct LiggghtsRunOutcome {
  bool ok = false;                     ///< exited with status 0
  std::string reason;                  ///< why not, with the first ERROR line found
  std::string log_tail;                ///< last lines of the log, the screen and stderr
  std::vector<std::string> warnings;   ///< WARNING lines of the log
  std::optional<std::string> version;  ///< banner version from the log
};

/// Runs `program -in deck.in -log log.liggghts` in `dir` (which holds deck.in), its screen
/// unbuffered into screen.txt (under `stdbuf -o0` when coreutils has it: LIGGGHTS writes some
/// errors to the screen alone and aborts without flushing), killed after `timeout_s`.
LiggghtsRunOutcome run_liggghts(const std::string& program, const std::filesystem::path& dir, double timeout_s);

/// A new, empty directory "<parent>/liggghts-run-XXXXXX" (absolute; the system temporary
/// directory when `parent` is empty). Throws std::runtime_error when it cannot.
std::filesystem::path make_run_directory(const std::filesystem::path& parent);

}  // namespace reference::liggghts
