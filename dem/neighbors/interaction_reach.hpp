// SPDX-License-Identifier: MIT
#pragma once

#include "dem/contact/pair_table.hpp"
#include "dem/particles/particles.hpp"

namespace dem {

/// Each sphere's half reach h_i: a distance such that every pair law acting on i reaches no
/// further than h_i + h_j, the sum of the two spheres' "threshold distances" of a Verlet list
/// (thesis appendix B.2). h_i = ½ max_b range(law(a_i, b), i paired with a copy of itself) over
/// the partner materials b present, which bounds the pair's range for every law of the core:
/// contact and effect distances add, a constant cut-off c splits as c/2 + c/2, and the JKR
/// rupture gap grows as R*^{1/3}, which the mean of the two spheres' terms bounds (power-mean
/// inequality). For contact laws h_i = r_i exactly. [m]
[[nodiscard]] ScalarArray half_reaches(const ParticleProperties& props, const PairTable& table);

/// Largest distance from a plane wall at which a sphere of radius r and effect radius r̂ still
/// interacts with it under `law` (the wall is a partner of infinite radius: R* = r). [m]
[[nodiscard]] double wall_reach(const PairLaw& law, double radius, double effect_radius) noexcept;

}  // namespace dem
