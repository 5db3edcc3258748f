// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "cases/scene.hpp"

namespace reference::lammps {

/// Displacement from the start of piecewise-constant-velocity `motion` along `axis` as a LAMMPS
/// equal-style formula of `time`: Σ_k v_k·clamp(time − t_k, 0, d_k), the last stretch
/// unbounded (dem::PrescribedMotion::position).
std::string motion_displacement_formula(const std::vector<cases::MotionSegmentSpec>& motion,
                                        int axis);

/// Velocity of `motion` along `axis` at `time` (the stretch t_k ≤ time < t_k + d_k).
std::string motion_velocity_formula(const std::vector<cases::MotionSegmentSpec>& motion, int axis);

/// The commands that drive every particle with a prescribed motion: per particle i a group
/// `tr_driven_i`, six equal-style variables and `fix tr_move_i tr_driven_i move variable …`
/// (fix move sets x = x(0) + d(time) and v = v(time) each step; the atom is frozen for forces).
std::vector<std::string> motion_commands(const cases::Scene& scene);

}  // namespace reference::lammps
