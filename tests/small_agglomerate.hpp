// SPDX-License-Identifier: MIT
#pragma once

#include <string>

#include <fmt/format.h>

namespace test_support {

/// A small version of the linear agglomerate benchmark (thesis table 5.1 material): `count`
/// spheres (radius 5 ± 1 mm) on a cubic grid of pitch 20 mm, formed and launched at a floor at
/// 3 m/s, 45°. `formation` replaces the formation stage's keys.
inline std::string small_agglomerate(int count = 8, int seed = 1,
                                     const std::string& formation =
                                         "pull = 2.0\npull_time = 0.3\nrestitution = 0.1\n"
                                         "kinetic_energy = 1.0e-8\nmax_duration = 3.0") {
  return fmt::format(R"(
[case]
name = "small_agglomerate"
[model]
normal = "linear"
damping = "restitution"
cohesion = "linear"
tangential = "spring_coulomb"
[materials.m]
density = 8000.0
normal_stiffness = 1.0e5
cohesive_stiffness = 1.0e2
interaction_ratio = 1.5
restitution = 0.8
tangential_stiffness = 1.0e6
friction = 0.2
tangential_damping_ratio = 0.0
[[populations]]
material = "m"
seed = {}
arrangement = "simple_cubic"
count = {}
spacing = 0.02
region = {{ shape = "box", min = [-0.05, -0.05, 0.0], max = [0.05, 0.05, 0.1] }}
size = {{ distribution = "gaussian", mean = 0.005, std_dev = 0.001, max = 0.007 }}
[[walls]]
type = "plane"
name = "floor"
point = [0.0, 0.0, -0.5]
normal = [0.0, 0.0, 1.0]
material = "m"
[[stages]]
kind = "formation"
{}
[[stages]]
kind = "launch"
wall = "floor"
speed = 3.0
angle = 45.0
direction = [1.0, 0.0, 0.0]
[integration]
scheme = "velocity_verlet"
timestep = 2.0e-5
duration = "launch"
[compare]
engines = ["inhouse"]
metrics = ["kappa_vol", "kappa_damage", "fragments", "coordination_before", "coordination_after"]
)",
                     seed, count, formation);
}

}  // namespace test_support
