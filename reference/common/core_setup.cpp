// SPDX-License-Identifier: MIT
#include "reference/common/core_setup.hpp"

#include <algorithm>
#include <cmath>

#include "cases/core_vector.hpp"
#include "cases/core_wall.hpp"
#include "cases/time_step.hpp"
#include "dem/contact/pair_table.hpp"

namespace reference {
namespace {

/// The core's fluid from the case's.
dem::Fluid to_fluid(const cases::FluidSpec& f) {
  dem::Fluid out;
  out.density = f.density;
  out.viscosity = f.viscosity;
  out.drag = f.drag;
  out.buoyancy = f.buoyancy;
  out.virtual_mass = f.virtual_mass;
  out.pressure_gradient = cases::core_vec(f.pressure_gradient);
  out.velocity.uniform = cases::core_vec(f.velocity);
  for (const auto& z : f.zones) {
    out.velocity.zones.push_back({cases::core_vec(z.min), cases::core_vec(z.max), cases::core_vec(z.direction)});
  }
  out.velocity.speed = f.plug_speed;
  out.velocity.ramp_time = f.ramp_time;
  return out;
}

/// Smallest body radius, the length scale of implicit-iteration tolerances.
double smallest_radius(const cases::Scene& scene) {
  double r = scene.particles.front().radius;
  for (const auto& p : scene.particles) r = std::min(r, p.radius);
  return r;
}

}  // namespace

CoreSetup core_setup(const PreparedScene& prepared, int threads) {
  const cases::Scene& scene = prepared.scene();
  CoreSetup out;
  dem::SimulationSetup& s = out.simulation;
  for (const auto& p : scene.particles) {
    s.particles.push_back(dem::ParticleInit{
        p.radius, p.effect_radius, scene.materials.at(p.material).density,
        static_cast<std::uint32_t>(p.material), cases::core_vec(p.position), cases::core_vec(p.velocity),
        cases::core_vec(p.angular_velocity), p.fixed, p.charge});
  }
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const auto& p = scene.particles[i];
    if (p.motion.empty()) continue;
    dem::PrescribedMotion m{static_cast<std::uint32_t>(i), cases::core_vec(p.position), {}};
    for (const auto& seg : p.motion) m.segments.push_back({seg.duration, cases::core_vec(seg.velocity)});
    s.motions.push_back(std::move(m));
  }
  for (const auto& w : scene.walls) {
    s.walls.push_back(cases::core_wall(w));
  }
  s.meshes = cases::core_meshes(scene, s.walls);
  s.fields.gravity = cases::core_vec(scene.gravity);
  for (std::size_t k = 0; k < 3; ++k) {
    const auto a = static_cast<Eigen::Index>(k);
    s.box.lo[a] = scene.domain.min[k];
    s.box.hi[a] = scene.domain.max[k];
    s.box.periodic[k] = scene.domain.periodic[k];
  }
  s.neighbors.skin = scene.neighbors.skin.value_or(0.0);  // 0: the core's default
  s.neighbors.sort_every = scene.neighbors.sort_every;
  s.threads = threads;
  s.track_energy = scene.output.trace_energy;
  if (scene.fluid) s.fields.fluid = to_fluid(*scene.fluid);
  s.materials = scene.materials;
  s.mixing = scene.mixing;
  s.pair_overrides = scene.pair_overrides;
  s.model = scene.model;
  const cases::IntegrationSpec& in = scene.integration;
  s.scheme = in.scheme;
  s.scheme_settings = dem::SchemeSettings{in.rotation,
                                          in.startup,
                                          in.startup_substeps,
                                          in.implicit_tolerance,
                                          in.implicit_max_iterations,
                                          smallest_radius(scene),
                                          in.leapfrog_start};
  // A sphere's orientation enters no force and no output of a run, so it is not turned (a
  // quaternion exponential per sphere and step). The implicit schemes keep it: their iteration
  // advances it with the rest of the state.
  s.scheme_settings.orientation = in.scheme == dem::SchemeId::bd1 || in.scheme == dem::SchemeId::bd2;

  dem::ParticleProperties props;
  dem::KinematicState initial;
  dem::build_particles(s.particles, props, initial);
  s.pair_table = prepared.shared_pair_table();
  const dem::PairTable& table = *s.pair_table;
  std::vector<std::uint32_t> wall_materials;
  for (const auto& w : s.walls) wall_materials.push_back(w.material);
  out.limits = dem::timestep_limits(props, initial, table, s.fields.gravity, in.rotation,
                                    in.steps_per_collision, wall_materials);
  if (in.timestep) {
    s.timestep = *in.timestep;
    for (const auto& w : dem::timestep_warnings(s.timestep, out.limits)) {
      out.warnings.push_back("integration.timestep: " + w);
    }
  } else {
    s.timestep = dem::automatic_timestep(out.limits);
    if (!std::isfinite(s.timestep)) {
      throw dem::ModelError("integration.timestep",
                            "timestep = \"auto\" needs at least one possible contact to size "
                            "the step; give a number instead");
    }
  }
  return out;
}

SampleGrid sample_grid(const PreparedScene& prepared) {
  const cases::Scene& scene = prepared.scene();
  const double dt = core_setup(prepared).simulation.timestep;
  const std::uint64_t steps = cases::step_count(scene.integration.duration, dt);
  return {dt, steps, std::max<std::uint64_t>(1, scene.output.trace_every), static_cast<double>(steps) * dt};
}

dem::KinematicState to_state(const cases::Snapshot& snapshot) {
  dem::KinematicState s;
  const auto n = static_cast<Eigen::Index>(snapshot.position.size());
  s.position.resize(3, n);
  s.velocity.resize(3, n);
  s.angular_velocity.resize(3, n);
  s.orientation.assign(snapshot.position.size(), dem::Quat::Identity());
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    s.position.col(i) = cases::core_vec(snapshot.position[k]);
    s.velocity.col(i) = cases::core_vec(snapshot.velocity[k]);
    s.angular_velocity.col(i) = cases::core_vec(snapshot.angular_velocity[k]);
  }
  return s;
}

}  // namespace reference
