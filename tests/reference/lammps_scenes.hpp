// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cases/case_loader.hpp"
#include "cases/scene.hpp"

// Scenes and text helpers for the LAMMPS driver's unit tests (no LAMMPS needed).
namespace demwb_lammps_unit {

/// A material with a linear spring and restitution damping.
inline dem::MaterialProperties material(const std::string& name, double density, double stiffness,
                                        double restitution) {
  dem::MaterialProperties m;
  m.name = name;
  m.density = density;
  m.normal_stiffness = stiffness;
  m.restitution = restitution;
  return m;
}

/// A sphere of material `material`.
inline cases::ParticleSpec sphere(std::size_t material, double radius, cases::Vector3 position,
                                  cases::Vector3 velocity, bool fixed) {
  cases::ParticleSpec p;
  p.material = material;
  p.radius = radius;
  p.effect_radius = radius;
  p.position = position;
  p.velocity = velocity;
  p.fixed = fixed;
  return p;
}

/// Two materials, five spheres in four (material, radius, fixed) classes, damping, gravity:
/// type 1 = glass r 0.01 mobile (particles 0 and 1), type 2 = steel r 0.02 mobile (2),
/// type 3 = glass r 0.1 fixed (3), type 4 = steel r 0.1 fixed (4).
inline cases::Scene mixed_scene() {
  cases::Scene s;
  s.name = "mixed";
  s.materials = {material("glass", 2500.0, 1e5, 0.5), material("steel", 7800.0, 2e5, 0.8)};
  s.model.normal = "linear";
  s.model.damping = "restitution";
  s.particles = {sphere(0, 0.01, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, false),
                 sphere(0, 0.01, {0.05, 0.0, 0.0}, {0.0, 0.5, 0.0}, false),
                 sphere(1, 0.02, {0.0, 0.1, 0.0}, {0.0, 0.0, -2.0}, false),
                 sphere(0, 0.1, {0.3, 0.0, 0.0}, {0.0, 0.0, 0.0}, true),
                 sphere(1, 0.1, {-0.3, 0.0, 0.0}, {0.0, 0.0, 0.0}, true)};
  s.particles[2].angular_velocity = {0.0, 3.0, 0.0};
  s.gravity = {0.0, 0.0, -9.81};
  s.integration.timestep = 1e-5;
  s.integration.duration = 2e-4;
  s.integration.rotation = true;
  s.output.trace_every = 2;
  s.output.trace_particles = {0, 3};
  s.output.trace_pairs = {{0, 3}};
  s.output.snapshot_times = {0.0, 1e-4};
  return s;
}

/// A test data file of tests/data/lammps.
inline std::filesystem::path data_file(const std::string& name) {
  return std::filesystem::path(DEMWB_TEST_DATA_DIR) / "lammps" / name;
}

/// A scene stored with the captured LAMMPS output it produced.
inline cases::Scene data_scene(const std::string& name) {
  return cases::load_case(data_file(name + ".toml"));
}

/// Lines of a deck whose first word is `command`.
inline std::vector<std::string> lines_of(const std::string& deck, const std::string& command) {
  std::vector<std::string> out;
  std::istringstream in(deck);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string first;
    words >> first;
    if (first == command) out.push_back(line);
  }
  return out;
}

/// Whitespace-separated words of a line.
inline std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

/// Index of the first line of `deck` containing `text`, or npos.
inline std::size_t line_index(const std::string& deck, const std::string& text) {
  std::istringstream in(deck);
  std::string line;
  for (std::size_t k = 0; std::getline(in, line); ++k) {
    if (line.find(text) != std::string::npos) return k;
  }
  return std::string::npos;
}

}  // namespace demwb_lammps_unit
