// SPDX-License-Identifier: MIT
// Micro-benchmarks of the neighbour search: one full list build (cells, search, CSR) for N
// random spheres at a 40 % volume fraction, monodisperse and with a size ratio of 10, and one
// force evaluation of a dense scene (pair loop, walls, fields) through the force field.
#include <cmath>
#include <numbers>
#include <random>

#include <benchmark/benchmark.h>

#include "dem/neighbors/neighbor_list.hpp"
#include "dem/simulation/simulation.hpp"

namespace {

struct Scene {
  std::vector<dem::PackedSphere> spheres;
  std::vector<std::uint8_t> still;
  dem::SizeClasses classes;
};

/// n spheres (radius 1, or log-uniform over [1, ratio]) at 40 % volume fraction in a cube.
Scene random_scene(std::size_t n, double ratio) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> radii(n);
  double volume = 0.0;
  for (double& r : radii) {
    r = std::pow(ratio, unit(rng));
    volume += 4.0 / 3.0 * std::numbers::pi * r * r * r;
  }
  const double side = std::cbrt(volume / 0.4);
  Scene s;
  for (const double r : radii) {
    s.spheres.push_back({side * unit(rng), side * unit(rng), side * unit(rng), r});
    s.still.push_back(0);
  }
  s.classes = dem::size_classes(radii);
  return s;
}

void ListBuild(benchmark::State& state, double ratio) {
  const Scene s = random_scene(static_cast<std::size_t>(state.range(0)), ratio);
  const dem::PeriodicBox box;
  dem::NeighborList list;
  for (auto _ : state) {
    list.build({s.spheres, s.still, s.classes.of, s.classes.max_half_reach, &box, 0.1, 1, false});
    benchmark::DoNotOptimize(list.partners().data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
  state.counters["pairs_per_sphere"] = static_cast<double>(list.size()) / static_cast<double>(state.range(0));
}

void ListBuildMonodisperse(benchmark::State& state) { ListBuild(state, 1.0); }
void ListBuildRatio10(benchmark::State& state) { ListBuild(state, 10.0); }

/// One committed force evaluation of 2,000+ spheres pressed together on a lattice.
void ForceEvaluation(benchmark::State& state) {
  dem::SimulationSetup setup;
  dem::MaterialProperties m;
  m.name = "grain";
  m.density = 1.0;
  m.normal_stiffness = 2e5;
  m.damping_rate = 50.0;
  m.tangential_stiffness = 2e5 * 2.0 / 7.0;
  m.tangential_damping_ratio = 0.0;
  m.friction = 0.5;
  setup.materials = {m};
  setup.model.damping = "lammps_mass_velocity";
  setup.model.tangential = "spring_coulomb";
  const int side = static_cast<int>(state.range(0));
  for (int k = 0; k < side * side * side; ++k) {
    const dem::Vec3 x(k % side, k / side % side, k / (side * side));
    setup.particles.push_back({0.5, 0.5, 1.0, 0, x * 0.99, dem::Vec3(0.01, 0, 0), dem::Vec3::Zero(), false});
  }
  setup.timestep = 1e-4;
  dem::Simulation sim(setup);
  dem::Accelerations acc;
  for (auto _ : state) {
    sim.force_field().commit(sim.state(), 1e-4, acc);
    benchmark::DoNotOptimize(acc.linear.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * side * side * side);
}

}  // namespace

BENCHMARK(ListBuildMonodisperse)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(ListBuildRatio10)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(ForceEvaluation)->Arg(13)->Arg(30)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
