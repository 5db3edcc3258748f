// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "cases/scene.hpp"
#include "reference/common/prepared_scene.hpp"
#include "reference/yade/model_mapping.hpp"
#include "reference/yade/restitution_calibration.hpp"

namespace reference::yade {

/// Everything a YADE script needs besides the scene: the resolved numerics (the in-house core's
/// time step and step count, so that trace rows fall on the same time points), the velocities
/// YADE starts from, and the contact-model mapping.
struct YadeRunPlan {
  double timestep = 0.0;                          ///< O.dt [s]
  std::uint64_t steps = 0;                        ///< steps the in-house engine takes
  std::vector<std::uint64_t> snapshot_iterations; ///< O.iter of each snapshot, ascending
  std::vector<cases::Vector3> start_velocities;   ///< State.vel per particle, taken as v(−Δt/2)
  std::vector<std::string> trace_columns;         ///< exactly the in-house engine's columns
  YadeModelMapping model;
  std::optional<YadeCalibrationPlan> calibration;  ///< betan calibration run first, if any
  std::vector<std::string> warnings;              ///< time step, start velocity, mapping
  std::map<std::string, std::string> conventions; ///< for RunResult::conventions
  /// Metrics YADE cannot give this case by design, with the reason (RunResult::inexpressible_metrics).
  std::map<std::string, std::string> inexpressible_metrics;
};

/// Builds the plan. Throws dem::ModelError when the core cannot resolve the time step.
YadeRunPlan make_run_plan(const PreparedScene& prepared);

/// The trace columns of the scene, in the in-house engine's order (cases::trace_layout): time;
/// per traced particle x y z vx vy vz wx wy wz fx fy fz; per traced pair and per traced
/// particle–wall contact overlap, fn.
std::vector<std::string> trace_columns(const cases::Scene& scene);

/// Iterations at which the in-house engine takes the snapshots at `times` with step dt over
/// `steps` steps: for each time t (ascending) the first n ≥ the previous one with n·Δt ≥ t − Δt/2.
/// Times after the last step get none, as in the in-house engine.
std::vector<std::uint64_t> snapshot_iterations(std::vector<double> times, double dt,
                                               std::uint64_t steps);

/// The velocity each particle is given in YADE, whose NewtonIntegrator takes it as v(−Δt/2), and
/// the notes on how it was chosen.
struct StartVelocities {
  std::vector<cases::Vector3> velocity;
  std::string convention;
  std::vector<std::string> warnings;
};

/// Start velocities: the scene's own when it declares them half-step velocities (leapfrog with
/// leapfrog_start = "given_is_half_step", the matched set-up); otherwise v(−Δt/2) = v(0) − Δt/2·a(0)
/// for every mobile particle whose a(0) is known, i.e. that starts free of contacts (a(0) = g;
/// phase 1 has no long-range forces); a particle that starts in contact keeps v(0) (first-order
/// start, warned).
StartVelocities start_velocities(const cases::Scene& scene, double dt);

}  // namespace reference::yade
