// SPDX-License-Identifier: MIT
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cases/scene.hpp"
#include "cases/trace.hpp"

namespace cases {

/// Outcome of asking one engine to run one scene (docs/architecture.md, "The flow of one
/// comparison", step 3).
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

/// How an engine's damping input was calibrated so that its two-body rebound gives the case's
/// restitution (docs/engines.md, "Restitution calibration"): the engine's own runs, input against
/// measured restitution.
struct Calibration {
  std::string parameter;                           ///< e.g. "LAMMPS tsuji e_in (pair 0–0)"
  double target = 0.0;                             ///< restitution the case asks for
  double chosen = 0.0;                             ///< input fed to the engine
  std::vector<std::pair<double, double>> samples;  ///< (input, restitution measured) runs
  std::string method;                              ///< how `chosen` was found, and any cache use
};

/// A reference code's native run repeated at halved time steps to measure its own
/// discretisation error (docs/metrics.md, "Reference discretisation error"). With m_k the
/// metric at Δt/2^k, the error of m_k is estimated as 2 |m_k − m_{k+1}| (Richardson with an
/// assumed order p = 1, an upper bound for any order p ≥ 1); the first level whose every
/// estimate is within a fraction of its tolerance is kept.
struct TimeStepRefinement {
  double timestep = 0.0;                   ///< Δt of `metrics` [s] (the case's Δt / 2^halvings)
  int halvings = 0;                        ///< 0: the case's own Δt sufficed
  int limit = 0;                           ///< most halvings allowed
  bool limit_reached = false;              ///< an estimate was still too large at the limit
  std::map<std::string, double> metrics;   ///< metric values at `timestep`
  std::map<std::string, double> estimates; ///< estimated |error| of each of those values
  std::string problem;                     ///< why the refinement stopped early (a run failed), else empty
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
  /// Where the engine's input and output files were kept (machine-local: report.md shows it,
  /// results.json leaves it out under --reproducible); empty when nothing was kept.
  std::string scratch_dir;
  Trace trace;
  Trace energy;                                ///< energy ledger over time, when the case asks
  std::vector<Snapshot> snapshots;
  std::map<std::string, double> exact_metrics;
  std::map<std::string, std::string> conventions;  ///< conventions this engine used
  /// Metrics this engine cannot produce in this scene, with the reason (compared as n/a), e.g.
  /// a rupture point that the code places elsewhere by design.
  std::map<std::string, std::string> inexpressible_metrics;
  std::vector<Calibration> calibrations;
  /// Set on a reference code's native run once its time step was checked by halving.
  std::optional<TimeStepRefinement> refinement;
  std::vector<std::string> warnings;
  /// Matched runs: the trace of the same run started one ulp away (every nonzero initial
  /// velocity component moved to the next double away from zero). How fast it drifts from
  /// `trace` is the scene's own round-off sensitivity (docs/metrics.md, "Round-off horizon").
  std::optional<Trace> roundoff_twin;
};

}  // namespace cases
