// SPDX-License-Identifier: MIT
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "cases/scene.hpp"
#include "cases/trace.hpp"

namespace cases {

/// Outcome of asking one engine to run one scene (DESIGN.md step 2 and 4).
enum class RunStatus {
  ok,              ///< ran; traces are valid
  error,           ///< crashed, timed out, produced NaN or unparsable output
  missing,         ///< the engine is not installed
  not_applicable,  ///< the engine cannot express this scene (reason given)
};

/// Name used in results.json and tables: "ok", "error", "missing", "n/a".
std::string_view to_string(RunStatus status) noexcept;

/// State of every particle at one instant.
struct Snapshot {
  double time = 0.0;
  std::vector<Vector3> position;
  std::vector<Vector3> velocity;
  std::vector<Vector3> angular_velocity;
};

/// What an engine returns. Metrics are computed from `trace` by compare/, the same way for
/// every engine; `exact_metrics` holds closed-form values an analytic engine knows exactly.
struct RunResult {
  std::string engine;
  RunStatus status = RunStatus::error;
  std::string reason;                          ///< why error / missing / n/a
  std::string version;
  std::string source = "run";                  ///< "run", "cache" or "baseline"
  double wall_time_s = 0.0;
  std::string log_tail;                        ///< last lines of the engine's log on error
  Trace trace;
  Trace energy;                                ///< energy ledger over time, when the case asks
  std::vector<Snapshot> snapshots;
  std::map<std::string, double> exact_metrics;
  std::map<std::string, std::string> conventions;  ///< conventions this engine used
  std::vector<std::string> warnings;
};

}  // namespace cases
