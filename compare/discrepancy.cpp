// SPDX-License-Identifier: MIT
#include "compare/discrepancy.hpp"

#include <array>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "cases/catalogue.hpp"

namespace comparison {
namespace {

/// Default tolerances per metric kind (docs/metrics.md): relative for durations, lengths, forces,
/// decelerations, spins and works; absolute for the dimensionless restitutions and amplitude
/// error, and for the rebound angle (degrees, whose zero is not special); both for end-state
/// velocity components.
constexpr std::array<std::pair<std::string_view, cases::Tolerance>, 32> kDefaults{{
    {"contact_duration", {1e-3, 0.0}},
    {"restitution", {0.0, 1e-3}},
    {"max_overlap", {1e-3, 0.0}},
    {"max_force", {1e-3, 0.0}},
    {"max_position", {1e-3, 0.0}},
    {"amplitude_error", {0.0, 1e-3}},
    {"tangential_restitution", {0.0, 1e-3}},
    {"rebound_angle", {0.0, 0.05}},
    {"spin_after", {1e-3, 0.0}},
    {"deceleration", {1e-3, 0.0}},
    // A frictionless contact's reference is 0: the floor is a force far below any friction here.
    {"tangential_force_max", {1e-3, 1e-9}},
    // End-state components: relative, with a floor for a component whose reference is zero
    // (motion in a plane), 1 µm/s and 1e-4 rad/s, far below what the canonical impacts resolve.
    {"velocity_after_x", {1e-3, 1e-6}},
    {"velocity_after_y", {1e-3, 1e-6}},
    {"velocity_after_z", {1e-3, 1e-6}},
    {"angular_velocity_after_x", {1e-3, 1e-4}},
    {"angular_velocity_after_y", {1e-3, 1e-4}},
    {"angular_velocity_after_z", {1e-3, 1e-4}},
    {"pulloff_force", {1e-3, 0.0}},
    {"rupture_separation", {5e-3, 0.0}},
    {"force_at_rupture", {1e-3, 0.0}},
    {"separation_work", {1e-3, 0.0}},
    {"equilibrium_overlap", {1e-3, 0.0}},
    // Shares of a region (dimensionless, zero not special): absolute, like the restitutions.
    {"packing_fraction", {0.0, 1e-3}},
    {"packing_fraction_interior", {0.0, 1e-3}},
    {"orf", {0.0, 1e-3}},
    {"dose_remaining", {0.0, 1e-3}},
    {"coordination_number", {0.0, 1e-3}},
    {"discharged_fraction", {0.0, 1e-3}},
    {"orf_largest_drop", {0.0, 1e-3}},
    {"largest_departed_fragment", {0.0, 1e-3}},
    {"fluidisation_time", {1e-3, 0.0}},
    // A rate: relative.
    {"mass_flow_rate", {1e-3, 0.0}},
}};

const cases::RunResult* find_run(const std::vector<cases::RunResult>& runs,
                                 const std::string& name) {
  for (const auto& r : runs) {
    if (r.engine == name) return &r;
  }
  return nullptr;
}

/// Status of an engine that did not produce results.
Status status_of_run(cases::RunStatus s) {
  switch (s) {
    case cases::RunStatus::missing: return Status::missing;
    case cases::RunStatus::not_applicable: return Status::not_applicable;
    case cases::RunStatus::ok:
    case cases::RunStatus::error: break;
  }
  return Status::error;
}

/// Metric value of `engine`, or empty with `why` set.
std::optional<double> value_of(const std::map<std::string, MetricSet>& metrics,
                               const std::string& engine, const std::string& metric,
                               std::string& why) {
  const auto e = metrics.find(engine);
  if (e == metrics.end()) {
    why = fmt::format("no metrics for engine '{}'", engine);
    return std::nullopt;
  }
  const auto m = e->second.find(metric);
  if (m == e->second.end()) {
    why = fmt::format("metric '{}' not computed for '{}'", metric, engine);
    return std::nullopt;
  }
  if (!m->second.value) why = fmt::format("{}: {}", engine, m->second.problem);
  return m->second.value;
}

/// True when `engine` declared that it cannot express `metric` in this case.
bool declared_not_applicable(const std::map<std::string, MetricSet>& metrics, const std::string& engine,
                             const std::string& metric) {
  const auto e = metrics.find(engine);
  if (e == metrics.end()) return false;
  const auto it = e->second.find(metric);
  return it != e->second.end() && it->second.not_applicable;
}

/// Fills one comparison row for an engine that ran.
void judge_row(Comparison& row, const std::map<std::string, MetricSet>& metrics,
               const cases::RunResult& reference) {
  std::string why;
  row.value = value_of(metrics, row.engine, row.metric, why);
  if (!row.value) {
    row.note = why;
    if (declared_not_applicable(metrics, row.engine, row.metric)) row.status = Status::not_applicable;
    return;
  }
  if (row.metric == "amplitude_error") {
    row.reference_value = 0.0;  // εx_amp measures the distance to the analytic solution itself
  } else {
    if (reference.status != cases::RunStatus::ok) {
      row.note = fmt::format("reference '{}' has no results ({}: {})", reference.engine,
                             cases::to_string(reference.status), reference.reason);
      return;
    }
    row.reference_value = value_of(metrics, reference.engine, row.metric, why);
    if (!row.reference_value) {
      row.note = "reference " + why;
      // The reference states it cannot express this metric here: nothing to compare.
      if (declared_not_applicable(metrics, reference.engine, row.metric)) row.status = Status::not_applicable;
      return;
    }
  }
  row.abs_diff = std::abs(*row.value - *row.reference_value);
  if (*row.reference_value != 0.0) row.rel_diff = *row.abs_diff / std::abs(*row.reference_value);
  row.status = judge(*row.value, *row.reference_value, row.tolerance);
}

/// Appends `text` to a row's note, separated by "; ".
void add_note(Comparison& row, const std::string& text) { row.note += (row.note.empty() ? "" : "; ") + text; }

/// A native reference-code row's own discretisation error and the Δt of its value; a note when
/// the check stopped early or could not bring the estimate within a tenth of the tolerance.
void attach_refinement(Comparison& row, const cases::TimeStepRefinement& r) {
  if (!r.metrics.contains(row.metric)) return;
  row.timestep = r.timestep;
  const auto e = r.estimates.find(row.metric);
  if (e == r.estimates.end()) {
    add_note(row, "no estimate of the reference code's own error" + (r.problem.empty() ? "" : ": " + r.problem));
    return;
  }
  row.error_estimate = e->second;
  if (!r.problem.empty()) {
    add_note(row, fmt::format("Δt refinement stopped after {} halvings: {}", r.halvings, r.problem));
  } else if (r.limit_reached) {
    add_note(row, fmt::format("Δt refined {} times (the limit): the code's own error is still estimated "
                              "above a tenth of the tolerance",
                              r.halvings));
  }
}

/// Rows comparing each matched run "inhouse@<code>" with <code>: every metric but the amplitude
/// error, and the position-trace deviation.
void append_matched_rows(const cases::Scene& scene, const std::vector<cases::RunResult>& runs,
                         const std::map<std::string, MetricSet>& metrics, std::vector<Comparison>& rows) {
  for (const cases::RunResult& run : runs) {
    const std::string_view code = cases::matched_code(run.engine);
    if (code.empty()) continue;
    const cases::RunResult* target = find_run(runs, std::string(code));
    if (target == nullptr) continue;
    const auto add = [&](const std::string& metric, cases::Tolerance tol) -> Comparison& {
      Comparison& row = rows.emplace_back();
      row.metric = metric;
      row.engine = run.engine;
      row.reference = target->engine;
      row.tolerance = tol;
      return row;
    };
    const auto failed = [&](Comparison& row) -> bool {
      for (const cases::RunResult* r : {&run, target}) {
        if (r->status == cases::RunStatus::ok) continue;
        row.status = status_of_run(r->status);
        row.note = fmt::format("{}: {}", r->engine, r->reason);
        return true;
      }
      return false;
    };
    // A metric the code cannot express *for this case* (e.g. a JKR rupture it places elsewhere
    // by design) is still well defined in its trace, and the matched run follows the code's
    // rule: compare the two traces' values, and say why the native row is n/a.
    std::map<std::string, MetricSet> matched_metrics;
    if (const auto it = metrics.find(run.engine); it != metrics.end()) matched_metrics[run.engine] = it->second;
    cases::RunResult raw = *target;
    const auto inexpressible = raw.inexpressible_metrics;
    raw.inexpressible_metrics.clear();
    raw.refinement.reset();  // matched runs share the case's Δt
    matched_metrics[target->engine] = compute_metrics(scene, raw, find_run(runs, "analytic"));
    for (const std::string& metric : scene.compare.metrics) {
      if (metric == "amplitude_error") continue;  // measured against the analytic solution
      Comparison& row = add(metric, matched_tolerance_for(scene, metric));
      if (failed(row)) continue;
      judge_row(row, matched_metrics, *target);
      if (const auto na = inexpressible.find(metric); na != inexpressible.end() && row.note.empty()) {
        row.note = "compared under " + target->engine + "'s own rule; natively n/a: " + na->second;
      }
    }
    Comparison& row = add("trace_deviation", {0.0, 1e-8});
    if (failed(row)) continue;
    std::string problem;
    const std::optional<TraceDeviation> d = trace_deviation(scene, run, *target, problem);
    if (!d) {
      row.note = problem;
      continue;
    }
    if (d->horizon < d->rows && 10 * d->horizon < d->rows) {
      // Less than a tenth of the run lies before the horizon: too little to judge anything by.
      row.status = Status::not_applicable;
      row.note = fmt::format("{} t = {:.4g} s, row {} of {}: under a tenth of the run can be compared at round-off "
                             "(whole-trace deviation {:.3g})",
                             kRoundoffHorizonNote, d->horizon_time, d->horizon, d->rows, d->whole);
      continue;
    }
    row.value = d->value;
    row.reference_value = 0.0;
    row.abs_diff = d->value;
    row.status = judge(d->value, 0.0, row.tolerance);
    if (d->horizon < d->rows) {
      row.note = fmt::format("{} t = {:.4g} s, row {} of {}: a one-ulp nudge of the start drifts past {:.0e} "
                             "there, so later rows are not compared (whole-trace deviation {:.3g})",
                             kRoundoffHorizonNote, d->horizon_time, d->horizon, d->rows, kRoundoffDrift, d->whole);
    }
  }
}

}  // namespace

cases::Tolerance default_tolerance(std::string_view metric) noexcept {
  for (const auto& [name, tol] : kDefaults) {
    if (name == metric) return tol;
  }
  return {1e-3, 0.0};
}

cases::Tolerance matched_tolerance_for(const cases::Scene& scene, const std::string& metric) {
  const auto it = scene.compare.matched_tolerances.find(metric);
  if (it != scene.compare.matched_tolerances.end()) return it->second;
  const cases::Tolerance native = default_tolerance(metric);
  // Same kind as the native default (relative or absolute), at 1e-8.
  return {native.rel > 0.0 ? 1e-8 : 0.0, native.abs > 0.0 ? 1e-8 : 0.0};
}

cases::Tolerance tolerance_for(const cases::Scene& scene, const std::string& metric) {
  const auto it = scene.compare.tolerances.find(metric);
  return it == scene.compare.tolerances.end() ? default_tolerance(metric) : it->second;
}

Status judge(double value, double reference, const cases::Tolerance& tol) noexcept {
  const double diff = std::abs(value - reference);
  return diff <= tol.abs + tol.rel * std::abs(reference) ? Status::pass : Status::fail;
}

std::vector<Comparison> compare_runs(const cases::Scene& scene,
                                     const std::vector<cases::RunResult>& runs,
                                     const std::map<std::string, MetricSet>& metrics) {
  std::vector<Comparison> rows;
  const std::string& ref_name = scene.compare.reference;
  const cases::RunResult* reference = find_run(runs, ref_name);
  for (const std::string& metric : scene.compare.metrics) {
    for (const cases::RunResult& run : runs) {
      if (run.engine == ref_name) continue;
      // A matched run adopts its reference code's conventions on purpose (e.g. where a JKR
      // contact breaks): it is judged against that code only (append_matched_rows).
      if (!cases::matched_code(run.engine).empty()) continue;
      Comparison row;
      row.metric = metric;
      row.engine = run.engine;
      row.reference = ref_name;
      row.tolerance = tolerance_for(scene, metric);
      if (run.status != cases::RunStatus::ok) {
        row.status = status_of_run(run.status);
        row.note = run.reason;
      } else if (reference == nullptr && metric != "amplitude_error") {
        row.note = fmt::format("reference engine '{}' was not run", ref_name);
      } else if (reference != nullptr && reference->status == cases::RunStatus::not_applicable &&
                 metric != "amplitude_error") {
        // A reference that cannot express the case compares nothing: that is a broken case,
        // not a pass.
        row.note = fmt::format("reference '{}' cannot express this case: {}", ref_name,
                               reference->reason);
      } else {
        static const cases::RunResult kNoReference{};
        judge_row(row, metrics, reference != nullptr ? *reference : kNoReference);
        if (run.refinement && row.value) attach_refinement(row, *run.refinement);
      }
      rows.push_back(std::move(row));
    }
  }
  append_matched_rows(scene, runs, metrics, rows);
  return rows;
}

}  // namespace comparison
