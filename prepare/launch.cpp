// SPDX-License-Identifier: MIT
#include "prepare/launch.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "dem/core/vector.hpp"
#include "dem/particles/particles.hpp"

namespace prepare {
namespace {

dem::Vec3 to_vec(const cases::Vector3& v) { return {v[0], v[1], v[2]}; }
cases::Vector3 to_array(const dem::Vec3& v) { return {v[0], v[1], v[2]}; }

}  // namespace

LaunchFigures launch(std::vector<cases::ParticleSpec>& particles, const std::vector<double>& density,
                     const cases::WallSpec& wall, const cases::LaunchStageSpec& spec) {
  // Centre of mass of the mobile spheres.
  double mass = 0.0;
  dem::Vec3 moment = dem::Vec3::Zero();
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (particles[i].fixed) continue;
    const double m = density[i] * dem::sphere_volume(particles[i].radius);
    mass += m;
    moment += m * to_vec(particles[i].position);
  }
  if (!(mass > 0.0)) throw std::invalid_argument("a launch needs at least one mobile sphere");
  const dem::Vec3 centre = moment / mass;
  // L_A: twice the largest distance from the centre of mass to a sphere's far side.
  double reach = 0.0;
  for (const cases::ParticleSpec& p : particles) {
    if (!p.fixed) reach = std::max(reach, (to_vec(p.position) - centre).norm() + p.radius);
  }
  LaunchFigures out;
  out.enclosing_diameter = 2.0 * reach;
  const dem::Vec3 n = to_vec(wall.normal);
  const dem::Vec3 t = to_vec(spec.direction);
  const dem::Vec3 target = to_vec(wall.point) + spec.height * out.enclosing_diameter * n;
  const dem::Vec3 shift = target - centre;
  const double theta = spec.angle * std::numbers::pi / 180.0;
  const dem::Vec3 u = spec.speed * (std::cos(theta) * t - std::sin(theta) * n);
  for (cases::ParticleSpec& p : particles) {
    if (p.fixed) continue;
    p.position = to_array(to_vec(p.position) + shift);
    p.velocity = to_array(u);
    p.angular_velocity = {0.0, 0.0, 0.0};
  }
  out.duration = 4.0 * out.enclosing_diameter / (spec.speed * std::sin(theta));
  out.centre_of_mass = to_array(target);
  return out;
}

}  // namespace prepare
