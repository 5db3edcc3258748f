// SPDX-License-Identifier: MIT
#include "bench/box_scene.hpp"

#include <cmath>

#include <fmt/format.h>

#include "cases/generators/population.hpp"

namespace bench {

cases::Scene box_scene(std::size_t n, std::uint64_t steps, std::uint64_t seed) {
  constexpr double kRadius = 1e-3;
  constexpr double kTimestep = 5e-6;
  cases::Scene scene;
  scene.name = fmt::format("bench_box_{}", n);
  scene.description = fmt::format("{} Hertz–Mindlin spheres settling in a box", n);
  dem::MaterialProperties grain;
  grain.name = "grain";
  grain.density = 2500.0;
  grain.youngs_modulus = 1e7;
  grain.poisson_ratio = 0.3;
  grain.restitution = 0.5;
  grain.tangential_damping_ratio = 0.0;
  grain.friction = 0.5;
  scene.materials = {grain};
  // The law all three timed codes express: LAMMPS `hertz/material … damping tsuji tangential
  // mindlin`, LIGGGHTS `model hertz tangential history` (tangential_damping off).
  scene.model.normal = "hertz";
  scene.model.damping = "tsuji";
  scene.model.tangential = "mindlin_8g";
  scene.model.mindlin_form = dem::MindlinForm::total;
  scene.model.friction_limit = dem::FrictionLimit::elastic_damping;

  // A square column of sites: w × w per layer, as many layers as needed (about w), generated at
  // pitch 2r and then pressed together by 0.4 % (the generator itself never overlaps spheres).
  constexpr double kSqueeze = 0.996;
  const auto w = static_cast<std::size_t>(std::ceil(std::cbrt(static_cast<double>(n))));
  const std::size_t layers = (n + w * w - 1) / (w * w);
  const double side = static_cast<double>(w) * 2.0 * kRadius;
  cases::PopulationSpec p;
  p.arrangement = cases::Arrangement::simple_cubic;
  p.size.radius = kRadius;
  p.count = n;
  p.seed = seed;
  p.velocity_jitter = 0.05;
  p.region.min = {0.0, 0.0, 0.0};
  p.region.max = {side, side, static_cast<double>(layers) * 2.0 * kRadius};
  scene.particles = cases::generate_population(p, {}, 1.0);
  for (cases::ParticleSpec& s : scene.particles) {
    for (double& x : s.position) x *= kSqueeze;
  }
  scene.population_first = {0};
  const double width = side * kSqueeze;

  const auto wall = [&scene](const char* name, cases::Vector3 point, cases::Vector3 normal) {
    cases::WallSpec spec;
    spec.name = name;
    spec.point = point;
    spec.normal = normal;
    scene.walls.push_back(spec);
  };
  wall("floor", {0, 0, 0}, {0, 0, 1});
  wall("x_min", {0, 0, 0}, {1, 0, 0});
  wall("x_max", {width, 0, 0}, {-1, 0, 0});
  wall("y_min", {0, 0, 0}, {0, 1, 0});
  wall("y_max", {0, width, 0}, {0, -1, 0});
  scene.gravity = {0.0, 0.0, -9.81};
  scene.integration.scheme = dem::SchemeId::velocity_verlet;
  scene.integration.timestep = kTimestep;
  scene.integration.duration = static_cast<double>(steps) * kTimestep;
  scene.output.trace_every = std::max<std::uint64_t>(steps, 1);
  scene.output.trace_particles = {0};
  return scene;
}

}  // namespace bench
