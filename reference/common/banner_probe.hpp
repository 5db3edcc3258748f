// SPDX-License-Identifier: MIT
#pragma once
// Asking a LAMMPS-family binary (LAMMPS, LIGGGHTS) for its version: an empty run, whose log opens
// with the code's banner.

#include <optional>
#include <string>
#include <string_view>

namespace reference {

/// What the version probe of a binary found.
struct BannerProbe {
  std::optional<std::string> version;  ///< empty when the program is not found
  bool timed_out = false;              ///< the binary did not finish the empty run in time
  double seconds = 0.0;                ///< how long the probe took
};

/// Reads the version from a log's banner; empty when the text has none.
using BannerReader = std::optional<std::string> (*)(std::string_view log_text);

/// Runs `program -in /dev/null -log <tmp>/log -screen none` (killed after `timeout_s`) and reads
/// its banner with `read`. A binary that runs but prints no banner, hangs or cannot start gives
/// "<code> (version unknown: …)" with the reason.
BannerProbe probe_banner(const std::string& program, double timeout_s, std::string_view code, BannerReader read);

}  // namespace reference
