// SPDX-License-Identifier: MIT
#include "reference/lammps/simulation_box.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "reference/lammps/wall_mapping.hpp"

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
  for (std::size_t k = 0; k < 3; ++k) {
    const double margin = 2.0 * fastest * duration + std::abs(scene.gravity[k]) * duration * duration + 2.0 * largest;
    box.low[k] -= margin;
    box.high[k] += margin;
  }
  // The spheres stay inside the planes that bound them (the loader refuses a start overlapping a
  // wall by more than 1 % of r): a plane sets its side of the box, however fast the spheres get.
  for (const cases::WallSpec& w : scene.walls) {
    if (!wall_in_run(w) || w.velocity != cases::Vector3{0.0, 0.0, 0.0}) continue;
    const std::optional<WallPlane> plane = wall_plane(w);
    if (!plane) continue;
    const auto k = static_cast<std::size_t>(plane->axis);
    if (plane->lower) {
      box.low[k] = plane->position - 2.0 * largest;
    } else {
      box.high[k] = plane->position + 2.0 * largest;
    }
  }
  return box;
}

double neighbour_skin(const cases::Scene& scene) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const cases::ParticleSpec& p : scene.particles) smallest = std::min(smallest, p.radius);
  return 0.2 * smallest;
}

}  // namespace reference::lammps
