// SPDX-License-Identifier: MIT
#include "reports/results_json.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

namespace reports {
namespace {

using Json = nlohmann::ordered_json;

/// A finite number, or null.
Json number(std::optional<double> v) {
  if (!v || !std::isfinite(*v)) return nullptr;
  return *v;
}

Json engine_entry(const cases::RunResult& run, const comparison::MetricSet& metrics, bool wall_times) {
  Json e;
  e["status"] = std::string(cases::to_string(run.status));
  e["version"] = run.version;
  e["source"] = run.source;
  if (wall_times) e["wall_time_s"] = number(run.wall_time_s);
  if (wall_times && !run.scratch_dir.empty()) e["scratch_directory"] = run.scratch_dir;
  if (!run.reason.empty()) e["reason"] = run.reason;
  Json values = Json::object();
  Json sources = Json::object();
  Json problems = Json::object();
  for (const auto& [name, m] : metrics) {
    values[name] = number(m.value);
    if (m.value) sources[name] = m.source;
    if (!m.problem.empty()) problems[name] = m.problem;
  }
  e["metrics"] = values;
  e["metric_sources"] = sources;
  if (!problems.empty()) e["metric_problems"] = problems;
  if (!run.warnings.empty()) e["warnings"] = run.warnings;
  if (!run.conventions.empty()) {
    Json c = Json::object();
    for (const auto& [k, v] : run.conventions) c[k] = v;
    e["conventions"] = c;
  }
  if (!run.inexpressible_metrics.empty()) {
    Json n = Json::object();
    for (const auto& [k, v] : run.inexpressible_metrics) n[k] = v;
    e["inexpressible_metrics"] = n;
  }
  if (!run.calibrations.empty()) {
    Json cs = Json::array();
    for (const auto& c : run.calibrations) {
      Json samples = Json::array();
      for (const auto& [input, measured] : c.samples) samples.push_back({{"input", input}, {"restitution", number(measured)}});
      cs.push_back({{"parameter", c.parameter}, {"target", c.target}, {"chosen", number(c.chosen)},
                    {"method", c.method}, {"samples", samples}});
    }
    e["calibrations"] = cs;
  }
  if (const auto& f = run.refinement) {
    Json estimates = Json::object();
    for (const auto& [k, v] : f->estimates) estimates[k] = number(v);
    e["time_step_check"] = {{"timestep", f->timestep}, {"halvings", f->halvings}, {"limit", f->limit},
                            {"limit_reached", f->limit_reached}, {"error_estimates", estimates}};
    if (!f->problem.empty()) e["time_step_check"]["problem"] = f->problem;
  }
  if (!run.log_tail.empty()) e["log_tail"] = run.log_tail;
  return e;
}

Json comparison_entry(const comparison::Comparison& c) {
  Json j;
  j["metric"] = c.metric;
  j["engine"] = c.engine;
  j["reference"] = c.reference;
  j["value"] = number(c.value);
  j["reference_value"] = number(c.reference_value);
  j["abs_diff"] = number(c.abs_diff);
  j["rel_diff"] = number(c.rel_diff);
  Json tol = Json::object();
  if (c.tolerance.rel > 0.0) tol["rel"] = c.tolerance.rel;
  if (c.tolerance.abs > 0.0) tol["abs"] = c.tolerance.abs;
  j["tolerance"] = tol;
  j["status"] = std::string(comparison::to_string(c.status));
  if (c.error_estimate) j["error_estimate"] = *c.error_estimate;
  if (c.timestep) j["timestep"] = *c.timestep;
  if (!c.note.empty()) j["note"] = c.note;
  return j;
}

}  // namespace

nlohmann::ordered_json results_json(const comparison::CaseOutcome& outcome, bool wall_times) {
  Json doc;
  doc["case"] = outcome.scene.name;
  doc["case_sha256"] = outcome.scene.source_sha256;
  doc["case_file"] = outcome.scene.source_path;
  doc["tier"] = std::string(cases::to_string(outcome.scene.tier));
  Json engines = Json::object();
  for (const auto& run : outcome.runs) {
    const auto m = outcome.metrics.find(run.engine);
    engines[run.engine] = engine_entry(run, m == outcome.metrics.end() ? comparison::MetricSet{} : m->second, wall_times);
  }
  doc["engines"] = engines;
  if (!outcome.unlisted.empty()) {
    // Reference codes the case does not list: what each driver makes of the scene (none ran).
    Json unlisted = Json::object();
    for (const auto& u : outcome.unlisted) {
      Json entry = Json::object();
      entry["status"] = u.reason.empty() ? "expressible" : "n/a";
      if (!u.reason.empty()) entry["reason"] = u.reason;
      unlisted[u.engine] = entry;
    }
    doc["unlisted_codes"] = unlisted;
  }
  Json rows = Json::array();
  for (const auto& c : outcome.comparisons) rows.push_back(comparison_entry(c));
  doc["comparisons"] = rows;
  doc["status"] = std::string(comparison::to_string(comparison::worst_status(outcome)));
  // Every listed metric's tolerance, also when no comparison row carries it (a one-engine case's
  // figures are judged only against the committed baseline, with these tolerances).
  Json tolerances = Json::object();
  for (const auto& metric : outcome.scene.compare.metrics) {
    const cases::Tolerance t = comparison::tolerance_for(outcome.scene, metric);
    Json tol = Json::object();
    if (t.rel > 0.0) tol["rel"] = t.rel;
    if (t.abs > 0.0) tol["abs"] = t.abs;
    tolerances[metric] = tol;
  }
  doc["tolerances"] = tolerances;
  if (!outcome.scene.warnings.empty()) doc["warnings"] = outcome.scene.warnings;
  if (!outcome.scene.stage_log.empty()) {
    Json stages = Json::array();
    for (const cases::StageRecord& st : outcome.scene.stage_log) {
      Json figures = Json::object();
      for (const auto& [name, value] : st.figures) figures[name] = value;
      stages.push_back({{"name", st.name}, {"kind", st.kind}, {"cached", st.cached}, {"figures", figures}});
    }
    doc["stages"] = stages;
  }
  return doc;
}

}  // namespace reports
