// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
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

/// What one material contributes to the limits: how many mobile and fixed spheres, the lightest
/// mobile one's mass and the smallest radius.
struct MaterialCensus {
  std::size_t mobile = 0;
  std::size_t fixed = 0;
  double lightest_mobile = std::numeric_limits<double>::infinity();
  double smallest_radius = std::numeric_limits<double>::infinity();
};

/// Counts one sphere of mass `mass` and radius `radius` into its material's census.
void add_to_census(MaterialCensus& census, double mass, double radius, bool fixed) noexcept;

/// Largest normal approach speed to expect (docs/physics.md, "Time-step control"): twice the
/// fastest sphere's speed, or a fall through the largest diameter under gravity `g` [m/s²].
[[nodiscard]] double expected_impact_speed(double fastest_speed, double largest_diameter, double g) noexcept;

/// One collision the time-step control weighs: the lightest mobile sphere of material `a` meeting
/// the smallest sphere of material `b`, or a plane wall of material `b`.
struct WeighedCollision {
  std::size_t a = 0;
  std::size_t b = 0;
  std::optional<std::size_t> wall;       ///< index into the wall materials when the partner is a wall
  CollisionScale scale;                  ///< m* = m_a: a fixed partner or a wall, and the stiffness √(m/k)
  bool fixed_partner = false;            ///< material b has a fixed sphere (or the partner is a wall)
  std::optional<CollisionScale> mobile;  ///< m* of the two lightest mobile spheres, when b has one
};

/// Calls `visit` for every collision of `census` the limits weigh, at the impact speed `speed`:
/// each material pair that can touch (mobile–mobile, or mobile–fixed), then each wall.
void for_each_weighed_collision(const std::vector<MaterialCensus>& census, double speed,
                                const std::vector<std::uint32_t>& wall_materials,
                                const std::function<void(const WeighedCollision&)>& visit);

/// The limits of a scene summarised by its per-material `census` and expected impact `speed`
/// (what timestep_limits below computes from the spheres).
TimestepLimits timestep_limits(const std::vector<MaterialCensus>& census, double speed, const PairTable& table,
                               bool rotation, double steps_per_collision,
                               const std::vector<std::uint32_t>& wall_materials = {});

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
