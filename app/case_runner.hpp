// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cases/case_loader.hpp"
#include "compare/case_outcome.hpp"
#include "prepare/prepare_scene.hpp"
#include "reference/common/engine.hpp"
#include "store/result_cache.hpp"

namespace app {

/// How engines are run for one command.
struct RunContext {
  reference::RunOptions options;
  reference::ExternalPrograms programs;           ///< the LAMMPS and YADE binaries to drive
  cases::LoadOptions load;                        ///< limits (--max-memory), checked again once a case is prepared
  prepare::PrepareOptions prepare;                ///< how a case's [[stages]] run (and are cached)
  std::optional<store::ResultCache> cache;        ///< reference-code results; none: always run
  bool refresh = false;                           ///< run reference codes even on a cache hit
  /// Which cases run their reference codes: `full` runs everything; `fast` (suite and gate by
  /// default) takes a `full` case's reference results from the committed baselines.
  cases::Tier tier = cases::Tier::full;
  std::optional<std::filesystem::path> baselines; ///< directory of committed baselines
  bool wall_times = true;                         ///< false: results.json without wall times and scratch directories
  /// Check each native reference-code run's time step by halving it (docs/metrics.md,
  /// "Reference discretisation error"); sweeps, whose ensembles are statistics, turn it off.
  bool refine_time_step = true;
  /// Ask every reference code that is not among a case's engines whether it can express the
  /// prepared scene (its driver's mappings alone; nothing runs), so that the report says what
  /// each code makes of every case (suite, gate and compare). A case whose preparation failed has
  /// no prepared scene to ask about: its engines are errors and no code is asked.
  bool survey_unlisted = false;
  /// Called after each engine of a case finished (progress lines); may be called from several
  /// threads at once when cases run concurrently.
  std::function<void(const cases::Scene&, const cases::RunResult&)> on_engine_done;
};

/// Runs `scene` on each named engine (in order) and evaluates metrics and comparisons. A scene
/// with [[stages]] is prepared first (prepare::prepare_scene); the outcome holds the prepared
/// scene, and when preparation fails every engine is an `error` with the reason. Reference
/// codes (LAMMPS, YADE) are read from the cache when their result for this scene and version is
/// there, stored after a successful run, and replaced by the committed baseline (with a warning)
/// when not installed. Each native reference-code run that ran (or came from the cache) then has
/// its time step checked by halving (comparison::refine_time_step) when `refine_time_step` is set.
/// With `survey_unlisted` the outcome also holds each unlisted reference code's verdict.
/// Unknown engine names must have been rejected by the caller.
comparison::CaseOutcome run_case(const cases::Scene& scene, const std::vector<std::string>& engines,
                                 const RunContext& context);

/// The engines a case runs: `requested` (or the case's compare.engines when empty), plus each
/// reference code named in compare.matched and its matched core "inhouse@<code>".
std::vector<std::string> engines_to_run(const cases::Scene& scene, std::vector<std::string> requested);

/// The committed baselines directory next to the canonical suite, if there is one.
std::optional<std::filesystem::path> default_baselines();

}  // namespace app
