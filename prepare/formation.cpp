// SPDX-License-Identifier: MIT
#include "prepare/formation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/SVD>
#include <fmt/format.h>

#include "cases/formation_model.hpp"
#include "dem/fields/central_pull.hpp"
#include "dem/simulation/simulation.hpp"
#include "prepare/core_run.hpp"
#include "reference/common/core_setup.hpp"

namespace prepare {
namespace {

/// The rigid-body motion of the mobile spheres: centre of mass, its velocity, and the angular
/// velocity Ω that best carries the orbital angular momentum about it (Ω = J⁻¹ L with J the
/// point-mass inertia tensor; least squares, so a line of spheres gets no spin about its axis).
struct RigidMotion {
  dem::Vec3 centre = dem::Vec3::Zero();
  dem::Vec3 velocity = dem::Vec3::Zero();
  dem::Vec3 angular_velocity = dem::Vec3::Zero();

  /// Velocity of the rigid motion at x [m/s].
  [[nodiscard]] dem::Vec3 at(const dem::Vec3& x) const { return velocity + angular_velocity.cross(x - centre); }
};

RigidMotion rigid_motion(const dem::Simulation& sim) {
  const dem::ParticleProperties& props = sim.particles();
  const dem::KinematicState& s = sim.state();
  const auto n = static_cast<Eigen::Index>(props.size());
  double mass = 0.0;
  RigidMotion m;
  dem::Vec3 moment = dem::Vec3::Zero();
  dem::Vec3 momentum = dem::Vec3::Zero();
  for (Eigen::Index i = 0; i < n; ++i) {
    if (props.fixed[static_cast<std::size_t>(i)] != 0) continue;
    mass += props.mass[i];
    moment += props.mass[i] * s.position.col(i);
    momentum += props.mass[i] * s.velocity.col(i);
  }
  if (!(mass > 0.0)) return m;
  m.centre = moment / mass;
  m.velocity = momentum / mass;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  dem::Vec3 angular_momentum = dem::Vec3::Zero();
  for (Eigen::Index i = 0; i < n; ++i) {
    if (props.fixed[static_cast<std::size_t>(i)] != 0) continue;
    const dem::Vec3 r = s.position.col(i) - m.centre;
    inertia += props.mass[i] * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
    angular_momentum += props.mass[i] * r.cross(s.velocity.col(i) - m.velocity);
  }
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(inertia, Eigen::ComputeFullU | Eigen::ComputeFullV);
  svd.setThreshold(1e-12);
  m.angular_velocity = svd.solve(angular_momentum);
  return m;
}

/// Kinetic energy of the mobile spheres relative to the agglomerate's rigid motion (translation
/// and rotation as a whole) plus their spins [J]: what is left of the gathering. An uneven grid
/// feels a net pull, so the agglomerate may drift and, its angular momentum about the pull centre
/// being zero, turn as a whole; no contact damps either.
double internal_kinetic_energy(const dem::Simulation& sim) {
  const dem::ParticleProperties& props = sim.particles();
  const RigidMotion rigid = rigid_motion(sim);
  double e = 0.0;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(props.size()); ++i) {
    if (props.fixed[static_cast<std::size_t>(i)] != 0) continue;
    e += 0.5 * props.mass[i] * (sim.state().velocity.col(i) - rigid.at(sim.state().position.col(i))).squaredNorm() +
         0.5 * props.inertia[i] * sim.state().angular_velocity.col(i).squaredNorm();
  }
  return e;
}

}  // namespace

cases::Scene formation_scene(const cases::Scene& scene, const cases::FormationStageSpec& stage) {
  cases::Scene s = stage_run_scene(scene);
  s.materials = cases::formation_materials(std::move(s.materials), stage);
  s.model = cases::formation_model(std::move(s.model), stage);
  if (!stage.walls) s.walls.clear();
  s.gravity = stage.gravity;
  return s;
}

Formation form_agglomerate(const cases::Scene& scene, const cases::FormationStageSpec& stage, int threads) {
  const cases::Scene formed = formation_scene(scene, stage);
  reference::CoreSetup core = reference::core_setup(reference::PreparedScene(formed), threads);
  dem::SimulationSetup& setup = core.simulation;
  setup.track_energy = false;

  // The pull's centre: the middle of the mobile spheres' bounding box (the grid's centre).
  dem::Vec3 lo = dem::Vec3::Constant(std::numeric_limits<double>::infinity());
  dem::Vec3 hi = -lo;
  double radius_sum = 0.0;
  std::size_t mobile = 0;
  for (const dem::ParticleInit& p : setup.particles) {
    if (p.fixed) continue;
    lo = lo.cwiseMin(p.position);
    hi = hi.cwiseMax(p.position);
    radius_sum += p.radius;
    ++mobile;
  }
  if (mobile == 0) throw std::runtime_error("a formation stage needs mobile spheres");
  setup.fields.pull = dem::CentralPull{0.5 * (lo + hi), stage.pull, stage.pull_time,
                                       radius_sum / static_cast<double>(mobile)};

  dem::Simulation sim(setup);
  const double dt = sim.timestep();
  const SettleCriterion criterion{static_cast<std::uint64_t>(std::ceil(stage.pull_time / dt)),
                                  static_cast<std::uint64_t>(std::ceil(stage.max_duration / dt)), stage.kinetic_energy,
                                  stage.max_duration};
  const double energy = run_until_settled(sim, criterion, internal_kinetic_energy, "formation");

  // The formed agglomerate at rest as a whole: its rigid motion is taken out of every mobile sphere.
  const RigidMotion rigid = rigid_motion(sim);
  Formation out;
  out.particles = particles_at(sim, scene.particles);
  for (std::uint32_t id = 0; id < out.particles.size(); ++id) {
    const auto c = static_cast<Eigen::Index>(sim.slot(id));
    cases::ParticleSpec& p = out.particles[id];
    if (!p.fixed) {
      const dem::Vec3 v = sim.state().velocity.col(c) - rigid.at(sim.state().position.col(c));
      p.velocity = {v[0], v[1], v[2]};
    }
  }
  out.time = sim.time();
  out.steps = sim.steps();
  out.timestep = dt;
  out.kinetic_energy = energy;
  out.drift_speed = rigid.velocity.norm();
  out.turn_rate = rigid.angular_velocity.norm();
  return out;
}

}  // namespace prepare
