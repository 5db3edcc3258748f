// SPDX-License-Identifier: MIT
#include "reference/lammps/simulation_box.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace reference::lammps {
namespace {

double norm(const cases::Vector3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

}  // namespace

Box simulation_box(const cases::Scene& scene, double duration) {
  Box box;
  box.low.fill(std::numeric_limits<double>::infinity());
  box.high.fill(-std::numeric_limits<double>::infinity());
  double fastest = 0.0;
  double largest = 0.0;
  for (const cases::ParticleSpec& p : scene.particles) {
    for (std::size_t k = 0; k < 3; ++k) {
      box.low[k] = std::min(box.low[k], p.position[k] - p.radius);
      box.high[k] = std::max(box.high[k], p.position[k] + p.radius);
    }
    if (!p.fixed) fastest = std::max(fastest, norm(p.velocity));
    largest = std::max(largest, p.radius);
  }
  const double margin =
      2.0 * fastest * duration + norm(scene.gravity) * duration * duration + 2.0 * largest;
  for (std::size_t k = 0; k < 3; ++k) {
    box.low[k] -= margin;
    box.high[k] += margin;
  }
  return box;
}

double neighbour_skin(const cases::Scene& scene) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const cases::ParticleSpec& p : scene.particles) smallest = std::min(smallest, p.radius);
  return 0.2 * smallest;
}

}  // namespace reference::lammps
