// SPDX-License-Identifier: MIT
#include "app/case_runner.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include <fmt/format.h>

#include "app/driver_revisions.hpp"
#include "cases/case_library.hpp"
#include "cases/catalogue.hpp"
#include "cases/output_budget.hpp"
#include "store/scene_json.hpp"

namespace app {
namespace {

/// The committed baseline result of `engine` for `scene`, if one exists and fits the scene.
std::optional<cases::RunResult> baseline_result(const cases::Scene& scene, const std::string& engine,
                                                const std::filesystem::path& dir) {
  const auto file = dir / (scene.name + ".json");
  if (!std::filesystem::exists(file)) return std::nullopt;
  store::Baseline b;
  try {
    b = store::read_baseline(file);
  } catch (const std::exception& e) {
    cases::RunResult r;
    r.engine = engine;
    r.status = cases::RunStatus::error;
    r.source = "baseline";
    r.reason = fmt::format("{} is not installed and its committed baseline cannot be used: {}", engine, e.what());
    return r;
  }
  const auto it = b.references.find(engine);
  if (it == b.references.end()) return std::nullopt;
  cases::RunResult r = it->second;
  r.source = "baseline";
  if (b.fingerprint != store::scene_fingerprint(scene)) {
    r.status = cases::RunStatus::error;
    r.reason = fmt::format("{} is not installed and the committed baseline {} was made for another "
                           "version of this case; run `demwb refresh --write-baselines` where it is "
                           "installed",
                           engine, file.string());
    return r;
  }
  r.warnings.push_back(fmt::format("{} is not installed here: using its committed baseline {} "
                                   "(made with {})",
                                   engine, file.string(), r.version));
  r.conventions["result source"] = "committed baseline " + file.string();
  return r;
}

/// Runs one engine, through the cache and baselines when it is a reference code.
cases::RunResult run_one(const cases::Scene& scene, const std::string& name, const RunContext& ctx) {
  const auto engine = reference::make_engine(name, ctx.programs);
  if (!engine) throw std::invalid_argument("unknown engine '" + name + "'");
  reference::RunOptions o = ctx.options;
  o.work_dir = ctx.options.work_dir / name;
  const bool reference_code = cases::is_reference_code(name);
  // The cache key's version: the code's own and its driver's source revision, so that results
  // made by another driver are never reused.
  std::optional<std::string> key;
  if (reference_code && ctx.cache) {
    if (const auto version = engine->version()) {
      key = fmt::format("{} | driver {}", *version, name == "lammps" ? kLammpsDriverRevision : kYadeDriverRevision);
    }
  }
  std::string distrusted;  // a cache entry that failed its checks: run again and overwrite it
  if (key && !ctx.refresh) {
    const auto start = std::chrono::steady_clock::now();
    store::ResultCache::Lookup found = ctx.cache->find(scene, name, *key);
    if (found.hit) {
      cases::RunResult& hit = *found.hit;
      hit.conventions["original wall time"] = fmt::format("{:.3f} s", hit.wall_time_s);
      hit.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return hit;
    }
    distrusted = found.problem;
  }
  cases::RunResult result = reference::run_engine(*engine, scene, o);
  if (key && result.status == cases::RunStatus::ok) ctx.cache->store(scene, result, *key);
  if (!distrusted.empty()) {
    result.warnings.push_back(fmt::format("cache entry not trusted, {} ran again{}: {}", name,
                                          result.status == cases::RunStatus::ok ? " and replaced it" : "",
                                          distrusted));
  }
  if (reference_code && result.status == cases::RunStatus::missing && ctx.baselines) {
    if (auto b = baseline_result(scene, name, *ctx.baselines)) return *b;
  }
  return result;
}

}  // namespace

comparison::CaseOutcome run_case(const cases::Scene& input, const std::vector<std::string>& engines,
                                 const RunContext& context) {
  std::vector<cases::RunResult> runs;
  cases::Scene scene;
  try {
    scene = prepare::prepare_scene(input, context.prepare);
    // A launched run's duration is known only now: the output budget is checked again.
    if (context.load.max_output_bytes) {
      cases::check_output_budget(scene, *context.load.max_output_bytes, scene.source_path);
    }
  } catch (const std::exception& e) {
    for (const auto& name : engines) {
      cases::RunResult r;
      r.engine = name;
      r.status = cases::RunStatus::error;
      r.reason = fmt::format("the case's preparation failed: {}", e.what());
      runs.push_back(r);
      if (context.on_engine_done) context.on_engine_done(input, runs.back());
    }
    return comparison::evaluate_runs(input, std::move(runs));
  }
  for (const auto& name : engines) {
    runs.push_back(run_one(scene, name, context));
    if (context.on_engine_done) context.on_engine_done(scene, runs.back());
  }
  return comparison::evaluate_runs(scene, std::move(runs));
}

std::vector<std::string> engines_to_run(const cases::Scene& scene, std::vector<std::string> requested) {
  if (requested.empty()) requested = scene.compare.engines;
  const auto add = [&](const std::string& e) {
    if (std::find(requested.begin(), requested.end(), e) == requested.end()) requested.push_back(e);
  };
  for (const auto& code : scene.compare.matched) {
    add(code);
    add(cases::matched_engine_name(code));
  }
  return requested;
}

std::optional<std::filesystem::path> default_baselines() {
  try {
    return cases::resolve_suite("baselines");
  } catch (const std::runtime_error&) {
    return std::nullopt;
  }
}

}  // namespace app
