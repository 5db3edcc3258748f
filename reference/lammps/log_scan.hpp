// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace reference::lammps {

/// Version from the banner a LAMMPS log starts with: "LAMMPS (29 Sep 2021 - Update 2)" →
/// "LAMMPS 29 Sep 2021 - Update 2"; empty when the text has no banner.
std::optional<std::string> banner_version(std::string_view log_text);

/// The first "ERROR…" line of a log, followed by its "Last command: …" line when there is one;
/// empty when the log holds no error.
std::string first_error(std::string_view log_text);

/// Every "WARNING…" line of a log, in order.
std::vector<std::string> warning_lines(std::string_view log_text);

}  // namespace reference::lammps
