// SPDX-License-Identifier: MIT
#include "prepare/core_run.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace prepare {
namespace {

/// The mobile sphere holding the most kinetic energy (translation, plus spin when `count_spin`), as
/// a phrase for a not-settled message: its index among the spheres the run received, position, and
/// translational and spin energy — a sphere that keeps spinning about its one contact's normal (no
/// twisting resistance) shows as spin alone.
std::string most_energetic_sphere(const dem::Simulation& sim, bool count_spin) {
  const dem::ParticleProperties& props = sim.particles();
  const dem::KinematicState& s = sim.state();
  double best = -1.0;
  SphereKineticEnergy most;
  Eigen::Index at = -1;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(props.size()); ++i) {
    if (props.fixed[static_cast<std::size_t>(i)] != 0) continue;
    const SphereKineticEnergy e = sphere_kinetic_energy(sim, i);
    if (e.translation + (count_spin ? e.spin : 0.0) > best) {
      best = e.translation + (count_spin ? e.spin : 0.0);
      most = e;
      at = i;
    }
  }
  if (at < 0) return "";
  const Eigen::Vector3d x = s.position.col(at);
  return fmt::format("; the most energetic sphere is particle {} (of the spheres the run received) at ({:.4g}, {:.4g}, {:.4g}) m with {:.3g} J of "
                     "translation and {:.3g} J of spin (|ω| = {:.3g} rad/s)",
                     sim.id(static_cast<std::uint32_t>(at)), x[0], x[1], x[2], most.translation, most.spin,
                     s.angular_velocity.col(at).norm());
}

}  // namespace

SphereKineticEnergy sphere_kinetic_energy(const dem::Simulation& sim, Eigen::Index i) noexcept {
  const dem::ParticleProperties& props = sim.particles();
  const dem::KinematicState& s = sim.state();
  return {0.5 * props.mass[i] * s.velocity.col(i).squaredNorm(),
          0.5 * props.inertia[i] * s.angular_velocity.col(i).squaredNorm()};
}

cases::Scene stage_run_scene(cases::Scene scene) {
  scene.fluid.reset();
  scene.stages.clear();
  scene.output = cases::OutputSpec{};
  // remove_at counts in the run's time: through the preparation a wall removed later stands (a
  // shutter closed while the spheres are poured and settled).
  // A wall with in_preparation = false is placed only when the run starts: gone from the stage's
  // first step on.
  for (cases::WallSpec& w : scene.walls) {
    if (w.in_preparation) {
      w.removed_at.reset();
    } else {
      w.removed_at = 0.0;
    }
  }
  return scene;
}

double run_until_settled(dem::Simulation& sim, const SettleCriterion& criterion,
                         const std::function<double(const dem::Simulation&)>& energy, std::string_view run) {
  double e = energy(sim);
  while (sim.steps() < criterion.max_steps) {
    sim.step();
    if (sim.steps() < criterion.first_step) continue;
    e = energy(sim);
    if (!std::isfinite(e)) {
      throw std::runtime_error(fmt::format("the {} run blew up at t = {:.6g} s (kinetic energy {})", run, sim.time(), e));
    }
    if (e < criterion.threshold) return e;
  }
  throw std::runtime_error(fmt::format(
      "the spheres had not settled after max_duration = {} s: kinetic energy {:.6g} J, threshold "
      "kinetic_energy = {:.6g} J (raise max_duration, lower restitution, or raise the threshold){}",
      criterion.max_duration, e, criterion.threshold, most_energetic_sphere(sim, criterion.count_spin)));
}

std::vector<cases::ParticleSpec> particles_at(const dem::Simulation& sim, std::vector<cases::ParticleSpec> particles) {
  for (std::uint32_t id = 0; id < particles.size(); ++id) {
    const auto c = static_cast<Eigen::Index>(sim.slot(id));
    cases::ParticleSpec& p = particles[id];
    for (std::size_t k = 0; k < 3; ++k) {
      const auto a = static_cast<Eigen::Index>(k);
      p.position[k] = sim.state().position(a, c);
      p.velocity[k] = sim.state().velocity(a, c);
      p.angular_velocity[k] = sim.state().angular_velocity(a, c);
    }
  }
  return particles;
}

}  // namespace prepare
