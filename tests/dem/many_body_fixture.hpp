// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "dem/neighbors/packed_sphere.hpp"
#include "dem/simulation/simulation.hpp"

namespace test_support {

/// True in a build with AddressSanitizer (CI's sanitizer phase runs the unit tests ten to twenty
/// times slower there).
inline constexpr bool kSanitized =
#if defined(__SANITIZE_ADDRESS__)
    true;
#else
    false;
#endif

/// `full` in a plain build, `reduced` under the sanitizers: the heaviest many-body tests keep
/// their full size where they are fast and still walk every code path, at a smaller size, under
/// the sanitizers.
template <typename T>
constexpr T full_or_sanitized(T full, T reduced) noexcept {
  return kSanitized ? reduced : full;
}

/// `n` spheres at uniformly random centres in [lo, hi], radii log-uniform in [r_min, r_max]
/// (size ratio r_max/r_min), every fifth one still, for neighbour-search tests (overlaps allowed).
struct RandomSpheres {
  std::vector<dem::PackedSphere> spheres;
  std::vector<std::uint8_t> still;
};

inline RandomSpheres random_spheres(std::uint32_t seed, std::size_t n, const dem::Vec3& lo,
                                    const dem::Vec3& hi, double r_min, double r_max) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  RandomSpheres out;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = r_min * std::pow(r_max / r_min, unit(rng));
    out.spheres.push_back({lo[0] + (hi[0] - lo[0]) * unit(rng), lo[1] + (hi[1] - lo[1]) * unit(rng),
                           lo[2] + (hi[2] - lo[2]) * unit(rng), r});
    out.still.push_back(unit(rng) < 0.2 ? 1 : 0);
  }
  return out;
}

/// A material for many-body runs: linear spring k_e, restitution 0.5, spring–Coulomb friction.
inline dem::MaterialProperties grain(double stiffness = 1e3) {
  dem::MaterialProperties m;
  m.name = "grain";
  m.density = 2500.0;
  m.normal_stiffness = stiffness;
  m.restitution = 0.5;
  m.tangential_stiffness = 2.0 / 7.0 * stiffness;
  m.friction = 0.5;
  m.tangential_damping_ratio = 0.0;
  return m;
}

/// `n` spheres of radius r·(1 ± spread) on a jittered cubic lattice of pitch pitch·r·(1 + spread)
/// in a walled box, falling under gravity with random velocities and spins: a dense,
/// frictional, many-contact scene (pitch < 2 starts with every lattice neighbour touching).
inline dem::SimulationSetup settling_box(std::uint32_t seed, std::size_t n, double r = 1e-3,
                                         double spread = 0.3, int threads = 1, double pitch_factor = 2.1) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  dem::SimulationSetup s;
  s.materials = {grain()};
  s.model.damping = "restitution";
  s.model.tangential = "spring_coulomb";
  const auto side = static_cast<std::size_t>(std::ceil(std::cbrt(static_cast<double>(n))));
  const double pitch = pitch_factor * r * (1.0 + spread);
  for (std::size_t k = 0; k < n; ++k) {
    const double radius = r * (1.0 + spread * unit(rng));
    const dem::Vec3 x((static_cast<double>(k % side) + 0.5) * pitch + 0.02 * r * unit(rng),
                      (static_cast<double>(k / side % side) + 0.5) * pitch + 0.02 * r * unit(rng),
                      (static_cast<double>(k / (side * side)) + 0.5) * pitch);
    s.particles.push_back({radius, radius, 2500.0, 0, x,
                           dem::Vec3(unit(rng), unit(rng), unit(rng)) * 0.2,
                           dem::Vec3(unit(rng), unit(rng), unit(rng)) * 10.0, false});
  }
  const double width = static_cast<double>(side) * pitch;
  s.walls = {{dem::Vec3(0, 0, 0), dem::Vec3(0, 0, 1)},     {dem::Vec3(0, 0, 0), dem::Vec3(1, 0, 0)},
             {dem::Vec3(width, 0, 0), dem::Vec3(-1, 0, 0)}, {dem::Vec3(0, 0, 0), dem::Vec3(0, 1, 0)},
             {dem::Vec3(0, width, 0), dem::Vec3(0, -1, 0)}};
  s.fields.gravity = dem::Vec3(0, 0, -9.81);
  s.scheme = dem::SchemeId::velocity_verlet;
  s.timestep = 1e-5;  // 0.1 √(m/k) of the lightest sphere
  s.threads = threads;
  return s;
}

}  // namespace test_support
