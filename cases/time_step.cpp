// SPDX-License-Identifier: MIT
#include "cases/time_step.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include "cases/core_vector.hpp"
#include "cases/formation_model.hpp"
#include "cases/launch_extent.hpp"
#include "dem/core/vector.hpp"
#include "dem/particles/particles.hpp"

namespace cases {
namespace {

/// dem::timestep_limits of spheres `particles` of `materials` under `gravity`, walls of
/// `walls`, with the pair laws `table`.
dem::TimestepLimits limits_of(const std::vector<ParticleSpec>& particles,
                              const std::vector<dem::MaterialProperties>& materials, const std::vector<WallSpec>& walls,
                              const Vector3& gravity, const IntegrationSpec& integration, const dem::PairTable& table) {
  const SphereCensus census = sphere_census(particles, materials, gravity);
  return dem::timestep_limits(census.materials, census.impact_speed, table, integration.rotation,
                              integration.steps_per_collision, wall_materials(walls));
}

}  // namespace

SphereCensus sphere_census(const std::vector<ParticleSpec>& particles,
                           const std::vector<dem::MaterialProperties>& materials, const Vector3& gravity) {
  SphereCensus out;
  out.materials.resize(materials.size());
  double fastest = 0.0;
  double largest = 0.0;
  for (const ParticleSpec& p : particles) {
    dem::add_to_census(out.materials[p.material], dem::sphere_mass(materials[p.material].density, p.radius), p.radius,
                       p.fixed);
    fastest = std::max(fastest, core_vec(p.velocity).norm());
    largest = std::max(largest, 2.0 * p.radius);
  }
  out.impact_speed = dem::expected_impact_speed(fastest, largest, core_vec(gravity).norm());
  return out;
}

std::vector<std::uint32_t> wall_materials(const std::vector<WallSpec>& walls) {
  std::vector<std::uint32_t> out;
  for (const WallSpec& w : walls) out.push_back(static_cast<std::uint32_t>(w.material));
  return out;
}

dem::TimestepLimits scene_timestep_limits(const Scene& scene, const dem::PairTable& table) {
  return limits_of(scene.particles, scene.materials, scene.walls, scene.gravity, scene.integration, table);
}

double run_timestep(const Scene& scene, const dem::PairTable& table) {
  if (scene.integration.timestep) return *scene.integration.timestep;
  return dem::automatic_timestep(scene_timestep_limits(scene, table));
}

double run_timestep(const Scene& scene) {
  if (scene.integration.timestep) return *scene.integration.timestep;
  const dem::PairTable table(scene.materials, scene.mixing, scene.pair_overrides, scene.model);
  return run_timestep(scene, table);
}

double run_duration(const Scene& scene) {
  if (!scene.duration_from_launch) return scene.integration.duration;
  const LaunchStageSpec* launch = nullptr;
  for (const StageSpec& stage : scene.stages) {
    if (const auto* l = std::get_if<LaunchStageSpec>(&stage.action)) launch = l;
  }
  if (launch == nullptr) return scene.integration.duration;
  const auto extent =
      mobile_extent(scene.particles, [&](std::size_t i) { return scene.materials[scene.particles[i].material].density; });
  if (!extent) return scene.integration.duration;
  return launch_duration(extent->enclosing_diameter, *launch);
}

double formation_timestep(const Scene& scene, const FormationStageSpec& stage) {
  if (scene.integration.timestep) return *scene.integration.timestep;
  const std::vector<dem::MaterialProperties> materials = formation_materials(scene.materials, stage);
  const dem::PairTable table(materials, scene.mixing, scene.pair_overrides, formation_model(scene.model, stage));
  return dem::automatic_timestep(limits_of(scene.particles, materials, stage.walls ? scene.walls : std::vector<WallSpec>{},
                                           stage.gravity, scene.integration, table));
}

double settle_timestep(const Scene& scene, const SettleStageSpec& stage) {
  if (scene.integration.timestep) return *scene.integration.timestep;
  const std::vector<dem::MaterialProperties> materials = settle_materials(scene.materials, stage);
  const dem::PairTable table(materials, scene.mixing, scene.pair_overrides, scene.model);
  return dem::automatic_timestep(
      limits_of(scene.particles, materials, scene.walls, scene.gravity, scene.integration, table));
}

std::uint64_t step_count(double duration, double dt) noexcept {
  const double n = std::ceil(duration / dt * (1.0 - 1e-12));
  if (std::isnan(n)) return 1;
  if (!(n < 1.8e19)) return UINT64_MAX;  // just below 2⁶⁴
  return std::max<std::uint64_t>(1, n > 0.0 ? static_cast<std::uint64_t>(n) : 0);
}

std::vector<std::uint64_t> snapshot_steps(std::vector<double> times, double dt, std::uint64_t steps) {
  std::sort(times.begin(), times.end());
  std::vector<std::uint64_t> out;
  const double last = static_cast<double>(steps) * dt;
  for (const double t : times) {
    const double threshold = t - 0.5 * dt;
    if (!(threshold <= last)) continue;  // past the end, or NaN
    // First guess from the division, then the exact predicate n·Δt ≥ t − Δt/2.
    const double guess = std::ceil(threshold / dt);
    std::uint64_t n = guess > 0.0 ? std::min(steps, static_cast<std::uint64_t>(guess)) : 0;
    while (n > 0 && static_cast<double>(n - 1) * dt >= threshold) --n;
    while (static_cast<double>(n) * dt < threshold) ++n;
    out.push_back(n);
  }
  return out;
}

}  // namespace cases
