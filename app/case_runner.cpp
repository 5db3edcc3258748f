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
#include "compare/time_step_refinement.hpp"
#include "store/scene_json.hpp"
#include "reference/registry.hpp"

namespace app {
namespace {

/// The source revision of reference code `name`'s driver (part of its cache key); throws for a
/// name that is no reference code (a new driver must get its own revision).
const char* driver_revision(std::string_view name) {
  if (name == "lammps") return kLammpsDriverRevision;
  if (name == "liggghts") return kLiggghtsDriverRevision;
  if (name == "yade") return kYadeDriverRevision;
  throw std::logic_error("no driver revision for reference code '" + std::string(name) + "'");
}

/// Why a reference code's result is taken from its committed baseline.
enum class BaselineUse {
  not_installed,  ///< the code is missing here
  fast_tier,      ///< a `full` case in the fast tier: the in-house side runs, the reference is stored
};

/// The command that renews the committed baseline of `scene`.
std::string refresh_command(const cases::Scene& scene) {
  return fmt::format("demwb refresh {} --write-baselines",
                     scene.source_path.empty() ? scene.name + ".toml" : scene.source_path);
}

/// The committed baseline result of `engine` for the prepared scene. Empty when there is none and the code
/// is merely not installed (the run stays `missing`); an `error` naming the refresh command when
/// the baseline is unreadable, absent in the fast tier, or stale: made from another version of
/// the case, or from another input than the driver writes for it now.
std::optional<cases::RunResult> baseline_result(const reference::PreparedScene& prepared, const reference::Engine& engine,
                                                const std::filesystem::path& dir, BaselineUse use) {
  const cases::Scene& scene = prepared.scene();
  const std::string name(engine.name());
  const auto file = dir / (scene.name + ".json");
  const std::string why = use == BaselineUse::not_installed
                              ? fmt::format("{} is not installed", name)
                              : fmt::format("case '{}' is in the full tier and this is a fast-tier run", scene.name);
  cases::RunResult r;
  r.engine = name;
  r.source = "baseline";
  r.status = cases::RunStatus::error;
  if (!std::filesystem::exists(file)) {
    if (use == BaselineUse::not_installed) return std::nullopt;
    r.reason = fmt::format("{}, and there is no committed baseline {}; run `{}` where {} is installed", why,
                           file.string(), refresh_command(scene), name);
    return r;
  }
  store::Baseline b;
  try {
    b = store::read_baseline(file);
  } catch (const std::exception& e) {
    r.reason = fmt::format("{}, and its committed baseline cannot be used: {}", why, e.what());
    return r;
  }
  const auto it = b.references.find(name);
  if (it == b.references.end()) {
    if (use == BaselineUse::not_installed) return std::nullopt;
    r.reason = fmt::format("{}, and the committed baseline {} holds no result of {}; run `{}` where {} is installed",
                           why, file.string(), name, refresh_command(scene), name);
    return r;
  }
  std::string stale;
  if (b.fingerprint != store::scene_fingerprint(scene)) {
    stale = "was made for another version of this case";
  } else if (const auto input = b.inputs.find(name); input == b.inputs.end()) {
    stale = fmt::format("does not record the input {} was given", name);
  } else if (input->second != engine.input_fingerprint(prepared)) {
    stale = fmt::format("was made from another {} than the driver writes now", name == "yade" ? "script" : "input deck");
  }
  if (!stale.empty()) {
    r.reason = fmt::format("{}, and the committed baseline {} {}; run `{}` where {} is installed", why,
                           file.string(), stale, refresh_command(scene), name);
    return r;
  }
  r = it->second;
  r.source = "baseline";
  r.warnings.push_back(use == BaselineUse::not_installed
                           ? fmt::format("{} is not installed here: using its committed baseline {} (made with {})",
                                         name, file.string(), r.version)
                           : fmt::format("{} not run (case '{}' is in the full tier, this run is in the fast tier): "
                                         "using its committed baseline {} (made with {})",
                                         name, scene.name, file.string(), r.version));
  r.conventions["result source"] = "committed baseline " + file.string();
  return r;
}

/// Runs one engine on the prepared scene, through the cache and baselines when it is a reference
/// code.
cases::RunResult run_one(const reference::PreparedScene& prepared, const std::string& name, const RunContext& ctx) {
  const cases::Scene& scene = prepared.scene();
  const auto engine = reference::make_engine(name, ctx.programs);
  if (!engine) throw std::invalid_argument("unknown engine '" + name + "'");
  reference::RunOptions o = ctx.options;
  o.work_dir = ctx.options.work_dir / name;
  const bool reference_code = cases::is_reference_code(name);
  // A full-tier case in the fast tier: the in-house side runs, the reference result is the
  // committed one (a code that cannot express the case still answers n/a at once).
  if (reference_code && ctx.tier == cases::Tier::fast && scene.tier == cases::Tier::full &&
      engine->supports(prepared).supported()) {
    if (!ctx.baselines) {
      cases::RunResult r;
      r.engine = name;
      r.status = cases::RunStatus::error;
      r.reason = fmt::format("case '{}' is in the full tier and this is a fast-tier run, but no baselines directory "
                             "is known; give --baselines DIR or run with --tier full",
                             scene.name);
      return r;
    }
    return *baseline_result(prepared, *engine, *ctx.baselines, BaselineUse::fast_tier);
  }
  // The cache key's version: the code's own and its driver's source revision, so that results
  // made by another driver are never reused.
  std::optional<std::string> key;
  if (reference_code && ctx.cache) {
    if (const auto version = engine->version()) {
      key = fmt::format("{} | driver {}", *version, driver_revision(name));
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
  cases::RunResult result = reference::run_engine(*engine, prepared, o);
  if (key && result.status == cases::RunStatus::ok) ctx.cache->store(scene, result, *key);
  if (!distrusted.empty()) {
    result.warnings.push_back(fmt::format("cache entry not trusted, {} ran again{}: {}", name,
                                          result.status == cases::RunStatus::ok ? " and replaced it" : "",
                                          distrusted));
  }
  if (reference_code && result.status == cases::RunStatus::missing && ctx.baselines) {
    if (auto b = baseline_result(prepared, *engine, *ctx.baselines, BaselineUse::not_installed)) return *b;
  }
  return result;
}

/// Most particles of a case whose reference runs get the time-step check: the two- and three-body
/// cases that closed forms decide. A many-body case is chaotic and compared as an ensemble over
/// seeds, where one run's Δt error is not the question (and a run at Δt/64 would be very long).
constexpr std::size_t kMaxCheckedParticles = 3;

/// Checks the time step of every native reference-code run that was made here (not a baseline)
/// of a deterministic case (at most kMaxCheckedParticles spheres, no preparation stages): the
/// refined runs go through run_one (cache, scratch directory <engine>-dt<2^k>).
void refine_reference_runs(const cases::Scene& scene, std::vector<cases::RunResult>& runs, const RunContext& context) {
  if (scene.particles.size() > kMaxCheckedParticles || !scene.stage_log.empty() || !scene.stages.empty()) return;
  const cases::RunResult* analytic = nullptr;
  for (const auto& r : runs) {
    if (r.engine == "analytic" && r.status == cases::RunStatus::ok) analytic = &r;
  }
  for (auto& r : runs) {
    if (!cases::is_reference_code(r.engine) || r.status != cases::RunStatus::ok || r.source == "baseline") continue;
    if (scene.compare.metrics.empty()) continue;
    int level = 0;
    const auto runner = [&](const cases::Scene& finer) {
      ++level;
      RunContext ctx = context;
      ctx.options.work_dir = context.options.work_dir / fmt::format("{}-dt{}", r.engine, 1 << level);
      return run_one(reference::PreparedScene(finer), r.engine, ctx);
    };
    r.refinement = comparison::refine_time_step(scene, r, runner, analytic);
    const auto& f = *r.refinement;
    r.conventions["time step check"] = fmt::format(
        "metrics at Δt = {:.6g} s ({} halving{} of the case's Δt; runs down to Δt/{}); each error estimated as "
        "2|m(Δt) − m(Δt/2)|{}{}",
        f.timestep, f.halvings, f.halvings == 1 ? "" : "s", 1 << std::min(f.halvings + 1, f.limit),
        f.limit_reached ? "; the limit was reached with an estimate above a tenth of a tolerance" : "",
        f.problem.empty() ? "" : "; stopped: " + f.problem);
  }
}

/// Each reference code not among `engines`, with what its driver says of the prepared scene.
std::vector<comparison::UnlistedCode> unlisted_codes(const reference::PreparedScene& prepared,
                                                     const std::vector<std::string>& engines,
                                                     const reference::ExternalPrograms& programs) {
  std::vector<comparison::UnlistedCode> out;
  for (const std::string_view code : cases::reference_codes()) {
    if (std::find(engines.begin(), engines.end(), code) != engines.end()) continue;
    // A driver that cannot answer is reported as such: the case's runs are already made.
    try {
      const auto engine = reference::make_engine(code, programs);
      out.push_back({std::string(code), engine ? engine->supports(prepared).explain() : "the code has no driver"});
    } catch (const std::exception& e) {
      out.push_back({std::string(code), fmt::format("its driver could not judge the scene: {}", e.what())});
    }
  }
  return out;
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
  // One pair table (and whatever else the engines derive from the scene) for every engine.
  const reference::PreparedScene prepared(scene);
  for (const auto& name : engines) {
    runs.push_back(run_one(prepared, name, context));
    if (context.on_engine_done) context.on_engine_done(scene, runs.back());
  }
  if (context.refine_time_step) refine_reference_runs(scene, runs, context);
  comparison::CaseOutcome outcome = comparison::evaluate_runs(scene, std::move(runs));
  if (context.survey_unlisted) outcome.unlisted = unlisted_codes(prepared, engines, context.programs);
  return outcome;
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
