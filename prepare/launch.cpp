// SPDX-License-Identifier: MIT
#include "prepare/launch.hpp"

#include <cmath>
#include <stdexcept>

#include "cases/core_vector.hpp"
#include "cases/launch_extent.hpp"
#include "dem/core/vector.hpp"

namespace prepare {

LaunchFigures launch(std::vector<cases::ParticleSpec>& particles, const std::vector<double>& density,
                     const cases::WallSpec& wall, const cases::LaunchStageSpec& spec) {
  const auto extent = cases::mobile_extent(particles, [&](std::size_t i) { return density[i]; });
  if (!extent) throw std::invalid_argument("a launch needs at least one mobile sphere");
  LaunchFigures out;
  out.enclosing_diameter = extent->enclosing_diameter;
  const dem::Vec3 n = cases::core_vec(wall.normal);
  const dem::Vec3 t = cases::core_vec(spec.direction);
  const dem::Vec3 target = cases::core_vec(wall.point) + spec.height * out.enclosing_diameter * n;
  const dem::Vec3 shift = target - extent->centre;
  const double theta = cases::launch_angle(spec);
  const dem::Vec3 u = spec.speed * (std::cos(theta) * t - std::sin(theta) * n);
  for (cases::ParticleSpec& p : particles) {
    if (p.fixed) continue;
    p.position = cases::case_vec(cases::core_vec(p.position) + shift);
    p.velocity = cases::case_vec(u);
    p.angular_velocity = {0.0, 0.0, 0.0};
  }
  out.duration = cases::launch_duration(out.enclosing_diameter, spec);
  out.centre_of_mass = cases::case_vec(target);
  return out;
}

}  // namespace prepare
