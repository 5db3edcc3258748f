// SPDX-License-Identifier: MIT
#pragma once

#include <string_view>

#include "cases/scene.hpp"

namespace reference {

/// A copy of `scene` that the in-house core runs to reproduce the numerics of the reference engine
/// `engine` (docs/engines.md, "Native and matched comparisons"), so that a comparison of the two
/// isolates the force model down to round-off:
/// - "lammps": velocity Verlet as `fix nve/sphere` performs it (half kick, drift, forces with
///   the half-step velocities, half kick; dem/integrators/verlet_schemes.cpp), with the time step
///   pinned to the one the original scene resolves to. Damping, m* against fixed partners and
///   the δ > 0 contact onset already agree (the driver feeds LAMMPS the core's η per type pair).
/// - "yade": leapfrog with half-step velocities as YADE's NewtonIntegrator performs it, the given
///   velocities taken as v(−Δt/2) (LeapfrogStart::given_is_half_step; the YADE driver then gives
///   them to YADE unchanged), with the time step pinned. The linear spring, m* against fixed
///   partners and the trace sampling agree; YADE's restitution dashpot scales the normal
///   velocity by (r_p + r_q)/(r_p + r_q − δ), which the core does not (see the driver's warning).
/// Throws std::invalid_argument for an engine without a matched variant.
cases::Scene matched_scene(const cases::Scene& scene, std::string_view engine);

}  // namespace reference
