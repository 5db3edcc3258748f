// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "cases/scene.hpp"
#include "dem/particles/particles.hpp"

// Canonical scenes of thesis ch. 4 built directly in C++ (no case loader needed).
namespace demwb_test {

/// Table 4.2 (with the brief's Δt): r_p = 0.01 m, ρ = 1000 kg/m³, |u| = 4 m/s, r_q = 0.1 m
/// fixed, k_e = 1e5 N/m.
struct CollisionParameters {
  double radius_p = 0.01;
  double radius_q = 0.1;
  double density = 1000.0;
  double speed = 4.0;
  double stiffness = 1e5;
  double timestep = 5e-6;
  double free_motion_steps = 10.0;        ///< N_FM
  std::optional<double> restitution;      ///< empty: damping "none"
};

/// One material with the given stiffness and optional restitution.
inline dem::MaterialProperties test_material(double density, double stiffness,
                                             std::optional<double> restitution) {
  dem::MaterialProperties m;
  m.name = "test";
  m.density = density;
  m.normal_stiffness = stiffness;
  m.restitution = restitution;
  return m;
}

/// A sphere of the test material.
inline cases::ParticleSpec sphere(double radius, cases::Vector3 position, cases::Vector3 velocity,
                                  bool fixed) {
  cases::ParticleSpec p;
  p.radius = radius;
  p.effect_radius = radius;
  p.material = 0;
  p.position = position;
  p.velocity = velocity;
  p.fixed = fixed;
  return p;
}

/// Scene shell: one material, fixed Δt, linear model with optional restitution damping.
inline cases::Scene base_scene(const std::string& name, double density, double stiffness,
                               std::optional<double> restitution, double timestep,
                               double duration) {
  cases::Scene s;
  s.name = name;
  s.materials.push_back(test_material(density, stiffness, restitution));
  s.model.normal = "linear";
  s.model.damping = restitution ? "restitution" : "none";
  s.integration.timestep = timestep;
  s.integration.duration = duration;
  s.integration.rotation = false;
  s.output.trace_every = 1;
  return s;
}

/// The single-collision test case (thesis §4.3.1, fig. 4.1): p at the origin moving at +u
/// along x towards fixed q placed for N_FM steps of free motion: x_q = u N_FM Δt + r_p + r_q.
inline cases::Scene single_collision(const CollisionParameters& c = {}) {
  cases::Scene s = base_scene("single_collision", c.density, c.stiffness, c.restitution,
                              c.timestep, 8e-4);
  const double x_q = c.speed * c.free_motion_steps * c.timestep + (c.radius_p + c.radius_q);
  s.particles.push_back(sphere(c.radius_p, {0.0, 0.0, 0.0}, {c.speed, 0.0, 0.0}, false));
  s.particles.push_back(sphere(c.radius_q, {x_q, 0.0, 0.0}, {0.0, 0.0, 0.0}, true));
  s.output.trace_particles = {0, 1};
  s.output.trace_pairs = {{0, 1}};
  s.compare.pair = cases::ParticlePair{0, 1};
  s.compare.subject = 0;
  return s;
}

/// The sandwich (thesis fig. 4.15): p at the origin moving at +u, exactly touching fixed
/// neighbours 1 (left, −x) and 2 (right, +x), so it is always in contact with one of them.
inline cases::Scene sandwich(const CollisionParameters& c = {}, double duration = 3e-3) {
  cases::Scene s = base_scene("sandwich", c.density, c.stiffness, c.restitution, c.timestep,
                              duration);
  const double reach = c.radius_p + c.radius_q;
  s.particles.push_back(sphere(c.radius_p, {0.0, 0.0, 0.0}, {c.speed, 0.0, 0.0}, false));
  s.particles.push_back(sphere(c.radius_q, {-reach, 0.0, 0.0}, {0.0, 0.0, 0.0}, true));
  s.particles.push_back(sphere(c.radius_q, {reach, 0.0, 0.0}, {0.0, 0.0, 0.0}, true));
  s.output.trace_particles = {0};
  s.output.trace_pairs = {{0, 1}, {0, 2}};
  s.compare.pair = cases::ParticlePair{0, 2};
  s.compare.subject = 0;
  return s;
}

/// Two mobile spheres approaching head-on along x, separated by `gap` between surfaces.
inline cases::Scene head_on(double radius_a, double radius_b, double speed_a, double speed_b,
                            double gap, std::optional<double> restitution) {
  cases::Scene s = base_scene("head_on", 1000.0, 1e5, restitution, 5e-6, 8e-4);
  s.particles.push_back(sphere(radius_a, {0.0, 0.0, 0.0}, {speed_a, 0.0, 0.0}, false));
  s.particles.push_back(
      sphere(radius_b, {radius_a + radius_b + gap, 0.0, 0.0}, {speed_b, 0.0, 0.0}, false));
  s.output.trace_particles = {0, 1};
  s.output.trace_pairs = {{0, 1}};
  s.compare.pair = cases::ParticlePair{0, 1};
  return s;
}

/// Mass of the moving sphere of a collision scene.
inline double mobile_mass(const CollisionParameters& c) {
  return dem::sphere_mass(c.density, c.radius_p);
}

/// Value of column `name` at row r of a trace.
template <class Trace>
double at(const Trace& trace, const std::string& name, std::size_t r) {
  const auto* column = trace.column(name);
  if (column == nullptr) throw std::runtime_error("no column " + name);
  return column->at(r);
}

}  // namespace demwb_test
