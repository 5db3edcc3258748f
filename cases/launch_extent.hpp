// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "cases/scene.hpp"
#include "dem/core/vector.hpp"
#include "dem/particles/particles.hpp"

namespace cases {

/// Where the mobile spheres of an agglomerate are and how far they reach (thesis §5.2.2).
struct MobileExtent {
  dem::Vec3 centre;           ///< centre of mass of the mobile spheres [m]
  double enclosing_diameter;  ///< L_A: diameter of the smallest sphere about the centre enclosing every mobile one [m]
};

/// The extent of the mobile spheres of `particles`, with sphere masses from `density_of(i)`
/// [kg/m³]; empty when no sphere is mobile. The launch stage and the loader's estimate of a
/// launched run's duration both use it.
template <class DensityOf>
[[nodiscard]] std::optional<MobileExtent> mobile_extent(const std::vector<ParticleSpec>& particles, DensityOf density_of) {
  double mass = 0.0;
  dem::Vec3 moment = dem::Vec3::Zero();
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles[i].fixed) continue;
    const double m = density_of(i) * dem::sphere_volume(particles[i].radius);
    mass += m;
    moment += m * dem::Vec3(particles[i].position[0], particles[i].position[1], particles[i].position[2]);
  }
  if (!(mass > 0.0)) return std::nullopt;
  const dem::Vec3 centre = moment / mass;
  // L_A: twice the largest distance from the centre of mass to a sphere's far side.
  double reach = 0.0;
  for (const ParticleSpec& p : particles) {
    if (p.fixed) continue;
    reach = std::max(reach, (dem::Vec3(p.position[0], p.position[1], p.position[2]) - centre).norm() + p.radius);
  }
  return MobileExtent{centre, 2.0 * reach};
}

/// Impact angle θ of a launch in radians.
[[nodiscard]] inline double launch_angle(const LaunchStageSpec& spec) noexcept {
  return spec.angle * std::numbers::pi / 180.0;
}

/// Simulated time after a launch, thesis eq 5.1: t_max = 4 L_A / (|u| sin θ) [s].
[[nodiscard]] inline double launch_duration(double enclosing_diameter, const LaunchStageSpec& spec) noexcept {
  return 4.0 * enclosing_diameter / (spec.speed * std::sin(launch_angle(spec)));
}

}  // namespace cases
