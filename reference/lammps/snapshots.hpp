// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "cases/run_result.hpp"
#include "reference/lammps/dump_parser.hpp"

namespace reference::lammps {

/// The snapshots at `steps` (as cases::snapshot_steps returns them, repeats allowed) from the parsed
/// `dump custom … id x y z vx vy vz omegax omegay omegaz` frames; time = n·Δt. Throws
/// std::runtime_error when a step, a column or an atom id 1 … `particles` is missing.
std::vector<cases::Snapshot> snapshots_from_dump(const std::vector<DumpFrame>& frames,
                                                 const std::vector<std::uint64_t>& steps,
                                                 double dt, std::size_t particles);

}  // namespace reference::lammps
