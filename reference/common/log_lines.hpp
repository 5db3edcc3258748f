// SPDX-License-Identifier: MIT
#pragma once
// ERROR and WARNING lines of a LAMMPS-family log (LAMMPS and LIGGGHTS write both the same way).

#include <string>
#include <string_view>
#include <vector>

namespace reference {

/// The first "ERROR…" line of a log, followed by its "Last command: …" line when there is one;
/// empty when the log holds no error.
std::string first_error(std::string_view log_text);

/// Every "WARNING…" line of a log, in order.
std::vector<std::string> warning_lines(std::string_view log_text);

}  // namespace reference
