// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "cases/run_result.hpp"
#include "reference/common/dump_text.hpp"

namespace reference {

/// The snapshots at `steps` (as cases::snapshot_steps returns them, repeats allowed) from the parsed
/// `dump custom … id x y z vx vy vz omegax omegay omegaz` frames; time = n·Δt. Throws
/// std::runtime_error, its message starting with `code` ("LAMMPS", "LIGGGHTS"), when a step, a
/// column or an atom id 1 … `particles` is missing.
std::vector<cases::Snapshot> snapshots_from_dump(const std::vector<DumpFrame>& frames,
                                                 const std::vector<std::uint64_t>& steps,
                                                 double dt, std::size_t particles, std::string_view code);

/// A run's snapshot steps as LAMMPS and LIGGGHTS take them: an equal-style formula of `step`
/// giving, at each step, the next snapshot step (`steps` + 1 past the last one), for `dump_modify
/// every v_name`; `first` when step 0 is itself a snapshot (`dump_modify first yes`). An empty
/// formula: no snapshots.
struct SnapshotSchedule {
  std::string next_step;
  bool first = false;
};

/// The schedule of the snapshots at `times` [s] of a run of `steps` steps of `dt`
/// (cases::snapshot_steps' rule).
SnapshotSchedule snapshot_schedule(const std::vector<double>& times, double dt, std::uint64_t steps);

}  // namespace reference
