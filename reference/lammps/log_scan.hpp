// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace reference::lammps {

/// Version from the banner a LAMMPS log starts with: "LAMMPS (29 Sep 2021 - Update 2)" →
/// "LAMMPS 29 Sep 2021 - Update 2"; empty when the text has no banner.
std::optional<std::string> banner_version(std::string_view log_text);

}  // namespace reference::lammps
