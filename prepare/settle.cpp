// SPDX-License-Identifier: MIT
#include "prepare/settle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "cases/case_loader.hpp"
#include "cases/formation_model.hpp"
#include "dem/simulation/simulation.hpp"
#include "prepare/core_run.hpp"
#include "reference/common/core_setup.hpp"

namespace prepare {
namespace {

/// Kinetic energy of the mobile spheres [J]: translation, plus spin when `with_spin`.
double mobile_kinetic_energy(const dem::Simulation& sim, bool with_spin) {
  const dem::ParticleProperties& props = sim.particles();
  double e = 0.0;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(props.size()); ++i) {
    if (props.fixed[static_cast<std::size_t>(i)] != 0) continue;
    const SphereKineticEnergy k = sphere_kinetic_energy(sim, i);
    e += with_spin ? k.translation + k.spin : k.translation;
  }
  return e;
}

/// The new index of old particle `i` under `renumber` (kRemoved when it was removed); throws
/// naming `what` when the case refers to a removed sphere.
constexpr std::size_t kRemoved = std::numeric_limits<std::size_t>::max();

std::size_t renumbered(const std::vector<std::size_t>& renumber, std::size_t i, const cases::Scene& scene,
                       const std::string& key, std::string_view what) {
  const std::size_t to = i < renumber.size() ? renumber[i] : kRemoved;
  if (to == kRemoved) {
    throw cases::CaseError(scene.source_path, key,
                           fmt::format("the stage removes particle {}, which {} refers to; refer to a particle "
                                       "that stays below remove_above",
                                       i, what));
  }
  return to;
}

}  // namespace

cases::Scene settle_scene(const cases::Scene& scene, const cases::SettleStageSpec& stage) {
  cases::Scene s = stage_run_scene(scene);
  s.materials = cases::settle_materials(std::move(s.materials), stage);
  return s;
}

Settled settle(const cases::Scene& scene, const cases::SettleStageSpec& stage, int threads) {
  const cases::Scene settling = settle_scene(scene, stage);
  reference::CoreSetup core = reference::core_setup(reference::PreparedScene(settling), threads);
  core.simulation.track_energy = false;
  dem::Simulation sim(core.simulation);
  const double dt = sim.timestep();
  const SettleCriterion criterion{static_cast<std::uint64_t>(std::ceil(stage.min_duration / dt)),
                                  static_cast<std::uint64_t>(std::ceil(stage.max_duration / dt)), stage.kinetic_energy,
                                  stage.max_duration, stage.count_spin};
  Settled out;
  out.kinetic_energy = run_until_settled(
      sim, criterion, [&](const dem::Simulation& at) { return mobile_kinetic_energy(at, stage.count_spin); }, "settle");
  out.particles = particles_at(sim, scene.particles);
  out.time = sim.time();
  out.steps = sim.steps();
  out.timestep = dt;
  return out;
}

std::size_t remove_above(cases::Scene& scene, double height, bool by_top, const std::string& key) {
  std::vector<std::size_t> renumber(scene.particles.size(), kRemoved);
  std::vector<cases::ParticleSpec> kept;
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const cases::ParticleSpec& p = scene.particles[i];
    if (!p.fixed && p.position[2] + (by_top ? p.radius : 0.0) > height) continue;
    renumber[i] = kept.size();
    kept.push_back(p);
  }
  const std::size_t removed = scene.particles.size() - kept.size();
  if (removed == 0) return 0;
  if (kept.empty() || std::none_of(kept.begin(), kept.end(), [](const auto& p) { return !p.fixed; })) {
    throw cases::CaseError(scene.source_path, key,
                           fmt::format("remove_above = {} m removes every mobile sphere (all {} lie above it)",
                                       height, removed));
  }
  cases::OutputSpec& out = scene.output;
  std::vector<std::size_t> mobile;
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    if (!scene.particles[i].fixed) mobile.push_back(i);
  }
  if (!out.trace_particles.empty() && out.trace_particles == mobile) {
    // The default (or a list of) every moving particle: every moving particle that stays.
    out.trace_particles.clear();
    for (std::size_t i = 0; i < kept.size(); ++i) {
      if (!kept[i].fixed) out.trace_particles.push_back(i);
    }
  } else {
    for (std::size_t& i : out.trace_particles) i = renumbered(renumber, i, scene, key, "output.trace_particles");
  }
  for (auto& [a, b] : out.trace_pairs) {
    a = renumbered(renumber, a, scene, key, "output.trace_pairs");
    b = renumbered(renumber, b, scene, key, "output.trace_pairs");
  }
  cases::CompareSpec& c = scene.compare;
  if (c.subject) c.subject = renumbered(renumber, *c.subject, scene, key, "compare.subject");
  if (c.pair) {
    c.pair = cases::ParticlePair{renumbered(renumber, c.pair->first, scene, key, "compare.pair"),
                                 renumbered(renumber, c.pair->second, scene, key, "compare.pair")};
  }
  if (c.wall_contact) {
    c.wall_contact->first = renumbered(renumber, c.wall_contact->first, scene, key, "compare.wall_contact");
  }
  // A population's first sphere is the first of its own that stayed (or where it would be).
  for (std::size_t& first : scene.population_first) {
    std::size_t moved = kept.size();
    for (std::size_t i = first; i < renumber.size(); ++i) {
      if (renumber[i] != kRemoved) {
        moved = renumber[i];
        break;
      }
    }
    first = moved;
  }
  scene.particles = std::move(kept);
  return removed;
}

}  // namespace prepare
