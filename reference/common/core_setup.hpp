// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "cases/run_result.hpp"
#include "cases/scene.hpp"
#include "dem/particles/particles.hpp"
#include "dem/simulation/simulation.hpp"
#include "dem/timestep/timestep_control.hpp"
#include "reference/common/prepared_scene.hpp"

namespace reference {

/// The core's set-up for a scene, with the time step resolved (fixed or automatic).
struct CoreSetup {
  dem::SimulationSetup simulation;
  dem::TimestepLimits limits;
  std::vector<std::string> warnings;  ///< time-step warnings, naming integration.timestep
};

/// Translates the prepared scene into the core's terms, run with `threads` OpenMP threads, sharing
/// its pair table. Throws dem::ModelError on an incomplete model.
CoreSetup core_setup(const PreparedScene& prepared, int threads = 1);

/// The time grid every engine samples a scene on: the core's resolved Δt, the step count, the
/// trace interval in steps and the end time steps·Δt.
struct SampleGrid {
  double dt;
  std::uint64_t steps;
  std::uint64_t every;
  double t_end;
};

/// The sample grid of the prepared scene (resolves the time step like core_setup).
SampleGrid sample_grid(const PreparedScene& prepared);

/// Converts an exact snapshot into the core's state (orientations at identity).
dem::KinematicState to_state(const cases::Snapshot& snapshot);

}  // namespace reference
