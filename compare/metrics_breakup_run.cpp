// SPDX-License-Identifier: MIT
#include "compare/metrics_breakup_run.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "cases/core_vector.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/conversion/appendix_e.hpp"

namespace comparison {
namespace {

constexpr std::array<std::string_view, 5> kBreakupMetrics{"kappa_vol", "kappa_damage", "fragments",
                                                          "coordination_before", "coordination_after"};

/// A material property the cohesive work needs; throws naming it when the material lacks it.
double property(const std::optional<double>& value, const dem::MaterialProperties& m, const char* key) {
  if (!value) throw std::invalid_argument(fmt::format("material '{}' has no {}", m.name, key));
  return *value;
}

}  // namespace

CohesionMetric cohesive_work(const cases::Scene& scene) {
  double radius = 0.0;
  double effect = 0.0;
  std::size_t count = 0;
  std::optional<std::size_t> material;
  for (const cases::ParticleSpec& p : scene.particles) {
    if (p.fixed) continue;
    if (material && *material != p.material) {
      return {std::nullopt, "the mobile spheres are of more than one material; cohesive work is defined for one"};
    }
    material = p.material;
    radius += p.radius;
    effect += p.effect_radius;
    ++count;
  }
  if (count == 0) return {std::nullopt, "the scene has no mobile spheres"};
  if (!scene.pair_overrides.empty()) {
    return {std::nullopt, "[[pairs]] overrides the material's own properties; cohesive work reads the material"};
  }
  radius /= static_cast<double>(count);
  effect /= static_cast<double>(count);
  const dem::MaterialProperties& m = scene.materials.at(*material);
  try {
    if (scene.model.cohesion == "linear" && scene.model.normal == "linear") {
      const dem::conversion::LinearModel linear{property(m.normal_stiffness, m, "normal_stiffness"),
                                                property(m.cohesive_stiffness, m, "cohesive_stiffness")};
      return {dem::conversion::linear_cohesive_work(linear, radius, effect), ""};
    }
    if (scene.model.cohesion == "jkr") {
      const double modulus = dem::conversion::formula_modulus(property(m.youngs_modulus, m, "youngs_modulus"),
                                                              property(m.poisson_ratio, m, "poisson_ratio"),
                                                              dem::conversion::Convention::workbench);
      const dem::laws::JkrParameters p{modulus, 0.5 * radius, property(m.surface_energy, m, "surface_energy")};
      return {dem::conversion::jkr_cohesive_work(p, scene.model.jkr_rupture), ""};
    }
  } catch (const std::invalid_argument& e) {
    return {std::nullopt, e.what()};
  }
  return {std::nullopt, fmt::format("cohesive work is defined for linear cohesion on a linear spring and for JKR, "
                                    "not for normal = {}, cohesion = {}",
                                    scene.model.normal, scene.model.cohesion)};
}

breakup::BondRule scene_bond_rule(const cases::Scene& scene, const std::vector<std::size_t>& mobile) {
  const auto table = std::make_shared<dem::PairTable>(scene.materials, scene.mixing, scene.pair_overrides, scene.model);
  std::vector<bool> used(scene.materials.size(), false);
  for (const std::size_t i : mobile) used[scene.particles[i].material] = true;
  breakup::BondRule rule;
  // Half reach of sphere i: half the range of the pair (i, i) with the largest partner material.
  // A pair's range grows with the radii and R* ≤ min(r_i, r_j) ≤ each, so the sum of the two
  // half reaches bounds it (a sphere's self extent uses R* = r, its largest).
  for (const std::size_t i : mobile) {
    const cases::ParticleSpec& p = scene.particles[i];
    const dem::PairExtent self{2.0 * p.radius, 2.0 * p.effect_radius, p.radius};
    double reach = std::max(p.radius, p.effect_radius);
    for (std::size_t b = 0; b < scene.materials.size(); ++b) {
      if (used[b]) reach = std::max(reach, 0.5 * dem::interaction_range(table->law(p.material, b), self));
    }
    rule.half_reach.push_back(reach);
  }
  rule.bonded = [table, &scene, mobile](std::uint32_t a, std::uint32_t b, double distance) {
    const cases::ParticleSpec& p = scene.particles[mobile[a]];
    const cases::ParticleSpec& q = scene.particles[mobile[b]];
    const dem::PairExtent e{p.radius + q.radius, p.effect_radius + q.effect_radius,
                            p.radius * q.radius / (p.radius + q.radius)};
    return distance < dem::interaction_range(table->law(p.material, q.material), e);
  };
  return rule;
}

std::optional<CohesionMetric> breakup_metric(const std::string& name, const cases::Scene& scene,
                                             const cases::RunResult& run) {
  if (name == "cohesive_work") return cohesive_work(scene);
  if (std::find(kBreakupMetrics.begin(), kBreakupMetrics.end(), name) == kBreakupMetrics.end()) return std::nullopt;
  std::vector<std::size_t> mobile;
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    if (!scene.particles[i].fixed) mobile.push_back(i);
  }
  // Engines take each requested snapshot at the step nearest its time, so the snapshot asked for
  // at the end may fall half a step before it; it is the last of as many as were asked for.
  const double end = scene.integration.duration;
  const bool all_taken = !scene.output.snapshot_times.empty() && run.snapshots.size() == scene.output.snapshot_times.size();
  if (run.snapshots.empty() || !(all_taken || run.snapshots.back().time >= end * (1.0 - 1e-6))) {
    return CohesionMetric{std::nullopt, fmt::format("no snapshot at the end of the run (t = {} s)", end)};
  }
  const cases::Snapshot& last = run.snapshots.back();
  if (last.position.size() != scene.particles.size()) {
    return CohesionMetric{std::nullopt, fmt::format("the final snapshot holds {} spheres, the scene {}",
                                                    last.position.size(), scene.particles.size())};
  }
  std::vector<breakup::SnapshotSphere> before;
  std::vector<breakup::SnapshotSphere> after;
  for (const std::size_t i : mobile) {
    before.push_back({cases::core_vec(scene.particles[i].position), scene.particles[i].radius});
    after.push_back({cases::core_vec(last.position[i]), scene.particles[i].radius});
  }
  try {
    const breakup::BreakupMetrics m = breakup::breakup_metrics(before, after, scene_bond_rule(scene, mobile));
    double value = 0.0;
    if (name == "kappa_vol") value = m.kappa_vol;
    if (name == "kappa_damage") value = m.kappa_damage;
    if (name == "fragments") value = m.fragments;
    if (name == "coordination_before") value = m.coordination_before;
    if (name == "coordination_after") value = m.coordination_after;
    return CohesionMetric{value, ""};
  } catch (const std::exception& e) {
    return CohesionMetric{std::nullopt, e.what()};
  }
}

}  // namespace comparison
