// SPDX-License-Identifier: MIT
#include "prepare/prepare_scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cases/case_loader.hpp"
#include "cases/core_wall.hpp"
#include "cases/limits.hpp"
#include "prepare/formation.hpp"
#include "prepare/launch.hpp"
#include "prepare/settle.hpp"
#include "prepare/stage_cache.hpp"
#include "store/scene_json.hpp"
#include "support/sha256.hpp"

namespace prepare {
namespace {

/// Metrics read from a snapshot at the end of the run.
constexpr std::array<std::string_view, 5> kEndSnapshotMetrics{"kappa_vol", "kappa_damage", "fragments",
                                                              "coordination_before", "coordination_after"};

/// Dotted key of stage `index` in messages.
std::string stage_key_name(std::size_t index) { return fmt::format("stages[{}]", index); }

/// Throws when a launched mobile sphere starts inside a wall (more than 1 % of its radius).
void check_clear_of_walls(const cases::Scene& scene, std::size_t index) {
  const auto hit =
      cases::first_wall_overlap(scene, [](const cases::WallSpec&) { return true; }, cases::kMaxInitialOverlap);
  if (!hit) return;
  throw cases::CaseError(scene.source_path, stage_key_name(index),
                         fmt::format("after the launch particle {} overlaps wall '{}' by {:.6g} m; "
                                     "place the walls further apart or lower `height`",
                                     hit->particle, scene.walls[hit->wall].name, hit->overlap));
}

/// Throws when a prepared mobile sphere overlaps a wall that is placed only when the run starts
/// (in_preparation = false) by more than 1 % of its radius: the wall would start inside the bed.
void check_clear_of_placed_walls(const cases::Scene& scene) {
  const auto placed = [](const cases::WallSpec& w) { return !w.in_preparation; };
  const auto hit = cases::first_wall_overlap(scene, placed, cases::kMaxInitialOverlap);
  if (!hit) return;
  throw cases::CaseError(
      scene.source_path, "walls",
      fmt::format("wall '{}' (in_preparation = false) is placed when the run starts, but the prepared particle {} "
                  "overlaps it by {:.6g} m; remove the spheres that reach into it (a settle stage's remove_above "
                  "with remove_by = \"top\") or move the wall",
                  scene.walls[hit->wall].name, hit->particle, hit->overlap));
}

/// The result of stage `index`: read from the cache when it holds one for the stage's inputs
/// (and the run does not refresh), else computed by `run` and stored. Particle positions,
/// velocities and spins of `scene` are replaced by the result; `record` gets its figures.
template <class Run>
void run_cached_stage(cases::Scene& scene, std::size_t index, const PrepareOptions& options, cases::StageRecord& record,
                      Run run) {
  const std::string key = stage_key(scene, index, options.core_revision);
  if (options.cache_dir && !options.refresh) {
    if (auto hit = find_stage(*options.cache_dir, key, scene.particles.size())) {
      for (std::size_t i = 0; i < scene.particles.size(); ++i) {
        scene.particles[i].position = hit->particles[i].position;
        scene.particles[i].velocity = hit->particles[i].velocity;
        scene.particles[i].angular_velocity = hit->particles[i].angular_velocity;
      }
      record.figures = hit->figures;
      record.cached = true;
      return;
    }
  }
  StoredStage result;
  try {
    result = run();
  } catch (const std::runtime_error& e) {
    throw cases::CaseError(scene.source_path, stage_key_name(index),
                           fmt::format("{} stage '{}': {}", record.kind, scene.stages[index].name, e.what()));
  }
  scene.particles = result.particles;
  record.figures = result.figures;
  if (options.cache_dir) store_stage(*options.cache_dir, key, result);
}

/// Runs one formation stage (or reads it from the cache) and records it.
void run_formation(cases::Scene& scene, std::size_t index, const cases::FormationStageSpec& stage,
                   const PrepareOptions& options) {
  cases::StageRecord record{scene.stages[index].name, "formation", {}, false};
  run_cached_stage(scene, index, options, record, [&] {
    const Formation formed = form_agglomerate(scene, stage, options.threads);
    return StoredStage{formed.particles,
                       {{"time", formed.time},
                        {"steps", static_cast<double>(formed.steps)},
                        {"timestep", formed.timestep},
                        {"kinetic_energy", formed.kinetic_energy},
                        {"drift_speed", formed.drift_speed},
                        {"turn_rate", formed.turn_rate}}};
  });
  scene.stage_log.push_back(record);
}

/// Runs one settle stage (or reads the settled pour from the cache), removes the spheres above
/// its height, and records both.
void run_settle(cases::Scene& scene, std::size_t index, const cases::SettleStageSpec& stage,
                const PrepareOptions& options) {
  cases::StageRecord record{scene.stages[index].name, "settle", {}, false};
  run_cached_stage(scene, index, options, record, [&] {
    const Settled settled = settle(scene, stage, options.threads);
    return StoredStage{settled.particles,
                       {{"time", settled.time},
                        {"steps", static_cast<double>(settled.steps)},
                        {"timestep", settled.timestep},
                        {"kinetic_energy", settled.kinetic_energy}}};
  });
  if (stage.remove_above) {
    const std::size_t removed = remove_above(scene, *stage.remove_above, stage.remove_by_top, stage_key_name(index));
    record.figures.emplace_back("removed", static_cast<double>(removed));
    record.figures.emplace_back("remaining", static_cast<double>(scene.particles.size()));
  }
  scene.stage_log.push_back(record);
}

/// Runs the launch stage and records it; sets the duration when the case asks for eq 5.1's.
void run_launch(cases::Scene& scene, std::size_t index, const cases::LaunchStageSpec& stage) {
  std::vector<double> density;
  for (const cases::ParticleSpec& p : scene.particles) density.push_back(scene.materials.at(p.material).density);
  const LaunchFigures f = launch(scene.particles, density, scene.walls.at(stage.wall), stage);
  check_clear_of_walls(scene, index);
  if (scene.duration_from_launch) {
    scene.integration.duration = f.duration;
    scene.duration_from_launch = false;
  }
  scene.stage_log.push_back({scene.stages[index].name,
                             "launch",
                             {{"enclosing_diameter", f.enclosing_diameter},
                              {"t_max", f.duration},
                              {"speed", stage.speed},
                              {"angle", stage.angle}},
                             false});
}

/// Drops snapshot times past the (now known) end, and adds snapshots at 0 and at the end when a
/// listed metric reads them.
void settle_snapshot_times(cases::Scene& scene) {
  std::vector<double>& times = scene.output.snapshot_times;
  const double end = scene.integration.duration;
  for (const double t : times) {
    if (t > end) {
      throw cases::CaseError(scene.source_path, "output.snapshot_times",
                             fmt::format("{} s is after the end of the run ({} s, set by the launch stage)", t, end));
    }
  }
  const bool wants_end = std::any_of(scene.compare.metrics.begin(), scene.compare.metrics.end(), [](const auto& m) {
    return std::find(kEndSnapshotMetrics.begin(), kEndSnapshotMetrics.end(), m) != kEndSnapshotMetrics.end();
  });
  if (!wants_end) return;
  times.push_back(0.0);
  times.push_back(end);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
}

}  // namespace

std::string stage_key(const cases::Scene& scene, std::size_t index, const std::string& core_revision) {
  cases::Scene alone = scene;
  alone.stages = {scene.stages.at(index)};
  alone.stage_log.clear();
  alone.duration_from_launch = false;
  alone.integration.duration = 0.0;      // the impact's length does not change the formation
  alone.output = cases::OutputSpec{};    // nor what the impact records
  nlohmann::ordered_json j = store::scene_json(alone);
  j["core_revision"] = core_revision;
  return support::sha256_hex(j.dump());
}

cases::Scene prepare_scene(const cases::Scene& scene, const PrepareOptions& options) {
  cases::Scene out = scene;
  if (scene.stages.empty()) return out;
  for (std::size_t k = 0; k < scene.stages.size(); ++k) {
    if (const auto* f = std::get_if<cases::FormationStageSpec>(&scene.stages[k].action)) {
      run_formation(out, k, *f, options);
    } else if (const auto* settle = std::get_if<cases::SettleStageSpec>(&scene.stages[k].action)) {
      run_settle(out, k, *settle, options);
    } else {
      run_launch(out, k, std::get<cases::LaunchStageSpec>(scene.stages[k].action));
    }
  }
  out.stages.clear();
  check_clear_of_placed_walls(out);
  settle_snapshot_times(out);
  return out;
}

}  // namespace prepare
