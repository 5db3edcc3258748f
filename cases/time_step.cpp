// SPDX-License-Identifier: MIT
#include "cases/time_step.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <variant>
#include <vector>

#include "dem/particles/particles.hpp"

namespace cases {
namespace {

/// What decides a scene's time-step limits besides its spheres.
struct LimitInputs {
  const std::vector<dem::MaterialProperties>& materials;
  const std::vector<WallSpec>& walls;
  const Vector3& gravity;
  bool rotation;
  double steps_per_collision;
};

/// Makes `best` the index of larger `score` of `best` and `i` (`i` when `best` is unset, SIZE_MAX).
template <class Score>
void keep_best(std::size_t& best, std::size_t i, Score score) {
  if (best == SIZE_MAX || score(i) > score(best)) best = i;
}

/// The few spheres whose values decide dem::timestep_limits, each listed once: per material the
/// lightest mobile sphere and a second mobile one (the limits ask whether there are two), the one
/// of smallest radius and a fixed one; and the fastest and the largest sphere of the scene.
std::vector<std::size_t> deciding_spheres(const std::vector<ParticleSpec>& particles,
                                          const std::vector<dem::MaterialProperties>& materials) {
  struct PerMaterial {
    std::size_t lightest = SIZE_MAX;
    std::size_t second = SIZE_MAX;
    std::size_t smallest = SIZE_MAX;
    std::size_t fixed = SIZE_MAX;
  };
  std::vector<PerMaterial> per(materials.size());
  std::size_t fastest = SIZE_MAX;
  std::size_t largest = SIZE_MAX;
  const auto mass = [&](std::size_t i) {
    return dem::sphere_mass(materials[particles[i].material].density, particles[i].radius);
  };
  const auto speed2 = [&](std::size_t i) {
    const Vector3& v = particles[i].velocity;
    return v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  };
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const ParticleSpec& p = particles[i];
    PerMaterial& m = per[p.material];
    keep_best(fastest, i, speed2);
    keep_best(largest, i, [&](std::size_t k) { return particles[k].radius; });
    keep_best(m.smallest, i, [&](std::size_t k) { return -particles[k].radius; });
    if (p.fixed) {
      if (m.fixed == SIZE_MAX) m.fixed = i;
      continue;
    }
    if (m.lightest == SIZE_MAX || mass(i) < mass(m.lightest)) {
      m.second = m.lightest;
      m.lightest = i;
    } else if (m.second == SIZE_MAX) {
      m.second = i;
    }
  }
  std::vector<std::size_t> out{fastest, largest};
  for (const PerMaterial& m : per) out.insert(out.end(), {m.lightest, m.second, m.smallest, m.fixed});
  std::erase(out, SIZE_MAX);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

/// dem::timestep_limits over the deciding spheres of `particles`.
dem::TimestepLimits limits_of(const std::vector<ParticleSpec>& particles, const LimitInputs& in,
                              const dem::PairTable& table) {
  std::vector<dem::ParticleInit> inits;
  for (const std::size_t i : deciding_spheres(particles, in.materials)) {
    const ParticleSpec& p = particles[i];
    inits.push_back(dem::ParticleInit{p.radius, p.effect_radius, in.materials[p.material].density,
                                      static_cast<std::uint32_t>(p.material),
                                      dem::Vec3(p.position[0], p.position[1], p.position[2]),
                                      dem::Vec3(p.velocity[0], p.velocity[1], p.velocity[2]),
                                      dem::Vec3(p.angular_velocity[0], p.angular_velocity[1], p.angular_velocity[2]),
                                      p.fixed, p.charge});
  }
  dem::ParticleProperties props;
  dem::KinematicState state;
  dem::build_particles(inits, props, state);
  std::vector<std::uint32_t> wall_materials;
  for (const WallSpec& w : in.walls) wall_materials.push_back(static_cast<std::uint32_t>(w.material));
  return dem::timestep_limits(props, state, table, dem::Vec3(in.gravity[0], in.gravity[1], in.gravity[2]),
                              in.rotation, in.steps_per_collision, wall_materials);
}

}  // namespace

dem::TimestepLimits scene_timestep_limits(const Scene& scene, const dem::PairTable& table) {
  return limits_of(scene.particles,
                   {scene.materials, scene.walls, scene.gravity, scene.integration.rotation,
                    scene.integration.steps_per_collision},
                   table);
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
  // L_A: the diameter of the smallest sphere about the centre of mass enclosing every mobile one.
  double mass = 0.0;
  Vector3 centre{};
  for (const ParticleSpec& p : scene.particles) {
    if (p.fixed) continue;
    const double m = dem::sphere_mass(scene.materials[p.material].density, p.radius);
    mass += m;
    for (std::size_t k = 0; k < 3; ++k) centre[k] += m * p.position[k];
  }
  if (!(mass > 0.0)) return scene.integration.duration;
  for (double& c : centre) c /= mass;
  double reach = 0.0;
  for (const ParticleSpec& p : scene.particles) {
    if (p.fixed) continue;
    const double d = std::hypot(p.position[0] - centre[0], p.position[1] - centre[1], p.position[2] - centre[2]);
    reach = std::max(reach, d + p.radius);
  }
  constexpr double kDegree = std::numbers::pi / 180.0;
  return 4.0 * (2.0 * reach) / (launch->speed * std::sin(launch->angle * kDegree));
}

double formation_timestep(const Scene& scene, const FormationStageSpec& stage) {
  if (scene.integration.timestep) return *scene.integration.timestep;
  std::vector<dem::MaterialProperties> materials = scene.materials;
  for (dem::MaterialProperties& m : materials) m.restitution = stage.restitution;
  dem::ModelChoice model = scene.model;
  if (!stage.friction) {
    model.tangential = "none";
    model.rolling = "none";
  }
  const std::vector<WallSpec> none;
  const dem::PairTable table(materials, scene.mixing, scene.pair_overrides, model);
  return dem::automatic_timestep(limits_of(
      scene.particles,
      {materials, stage.walls ? scene.walls : none, stage.gravity, scene.integration.rotation,
       scene.integration.steps_per_collision},
      table));
}

}  // namespace cases
