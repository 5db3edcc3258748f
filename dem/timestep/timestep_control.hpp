// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dem/contact/pair_table.hpp"
#include "dem/particles/particles.hpp"

namespace dem {

/// Time-step limits of a scene (docs/physics.md, "Time-step control"). Each limit is +∞ when no
/// contact can occur.
struct TimestepLimits {
  double cundall_strack;         ///< √(m/k) (thesis eq 4.6) [s]
  double osullivan_bray;         ///< 0.22√(m/k) with rotation, 0.34√(m/k) without (eq 4.7) [s]
  double collision_duration;     ///< shortest contact duration t_c of any possible pair [s]
  double collision_resolution;   ///< t_c / a (eq 4.9) [s]
  double steps_per_collision;    ///< a
  bool rotation;                 ///< which O'Sullivan–Bray factor applies
};

/// Limits for the spheres `props` in `state` under the pair laws `table` and gravity. m is the
/// smallest mobile mass and k the stiffest pair it can meet; t_c uses the smallest reduced mass
/// of each material pair that can actually touch (mobile–mobile, or mobile–fixed with m* = m).
/// Stiffness that grows with overlap (Hertz) is taken at the overlap of an impact at twice the
/// fastest initial speed, or of a fall through the largest diameter (docs/physics.md).
/// Plane walls of the materials `wall_materials` are infinite-mass partners with R* = r, m* = m.
TimestepLimits timestep_limits(const ParticleProperties& props, const KinematicState& state,
                               const PairTable& table, const Vec3& gravity, bool rotation,
                               double steps_per_collision,
                               const std::vector<std::uint32_t>& wall_materials = {});

/// Automatic time step: the smaller of the O'Sullivan–Bray limit and t_c / a.
[[nodiscard]] double automatic_timestep(const TimestepLimits& limits) noexcept;

/// Warnings for a user-fixed time step that violates a limit (empty when it satisfies both).
std::vector<std::string> timestep_warnings(double dt, const TimestepLimits& limits);

}  // namespace dem
