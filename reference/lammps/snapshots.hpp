// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "cases/run_result.hpp"
#include "reference/lammps/dump_parser.hpp"

namespace reference::lammps {

/// The step of each requested snapshot time, by the in-house engine's rule: the first step
/// n (0 ≤ n ≤ steps) with n·Δt ≥ t − Δt/2, in the order of the sorted times. Times past the
/// last step get none (the in-house engine takes none either).
std::vector<std::uint64_t> snapshot_steps(std::vector<double> times, double dt,
                                          std::uint64_t steps);

/// The snapshots at `steps` (as snapshot_steps returns them, repeats allowed) from the parsed
/// `dump custom … id x y z vx vy vz omegax omegay omegaz` frames; time = n·Δt. Throws
/// std::runtime_error when a step, a column or an atom id 1 … `particles` is missing.
std::vector<cases::Snapshot> snapshots_from_dump(const std::vector<DumpFrame>& frames,
                                                 const std::vector<std::uint64_t>& steps,
                                                 double dt, std::size_t particles);

}  // namespace reference::lammps
