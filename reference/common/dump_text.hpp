// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace reference {

/// One snapshot of a LAMMPS-family (LAMMPS, LIGGGHTS) text `dump custom` file.
struct DumpFrame {
  std::uint64_t step = 0;
  std::vector<std::string> columns;         ///< names after "ITEM: ATOMS"
  std::vector<std::vector<double>> rows;    ///< one row per atom, one value per column
};

/// Parses a text `dump custom` file (ITEM: TIMESTEP / NUMBER OF ATOMS / BOX BOUNDS / ATOMS
/// blocks). Throws std::runtime_error naming `file_name` and the 1-based line number when the
/// layout or a value is not what LAMMPS and LIGGGHTS write.
std::vector<DumpFrame> parse_dump(std::string_view text, std::string_view file_name);

}  // namespace reference
