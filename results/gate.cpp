// SPDX-License-Identifier: MIT
#include "results/gate.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "compare/discrepancy.hpp"
#include "store/result_cache.hpp"

namespace results {
namespace {

std::string number_text(std::optional<double> v) {
  return v && std::isfinite(*v) ? fmt::format("{:.9g}", *v) : "—";
}

/// Fails on stored cross-code ensembles that no longer fit their sweep and case files: their
/// tables would describe another case.
void check_ensembles(const SuiteResults& results, GateFindings& g) {
  for (const auto& e : results.ensembles) {
    if (e.current) continue;
    g.failures.push_back(fmt::format("stored ensemble {}: {}", e.sweep, e.problem.empty() ? "not current" : e.problem));
  }
}

/// Checks every comparison row of one case, and notes results that came from baselines.
void check_comparisons(const CaseResults& c, cases::Tier tier, bool allow_missing, GateFindings& g) {
  if (!c.failure.empty()) {
    g.failures.push_back(fmt::format("{}: {}", c.name, c.failure));
    return;
  }
  if (c.comparisons.empty()) {
    g.notes.push_back(c.name + (!c.tolerances.empty()
                                    ? ": no comparison between engines (one engine); its figures are checked against "
                                      "the committed baseline"
                                    : ": no comparisons (the case lists no metrics)"));
  }
  for (const auto& row : c.comparisons) {
    ++g.comparisons;
    ++g.by_status[std::string(comparison::to_string(row.status))];
    const bool green = comparison::is_green(row.status) || (row.status == comparison::Status::missing && allow_missing);
    if (green) continue;
    g.failures.push_back(fmt::format("{}: {} {} vs {}: {} — value {} reference {}{}", c.name, row.metric, row.engine,
                                     row.reference, comparison::to_string(row.status), number_text(row.value),
                                     number_text(row.reference_value), row.note.empty() ? "" : " (" + row.note + ")"));
  }
  for (const auto& e : c.engines) {
    if (e.source != "baseline" || e.status != cases::RunStatus::ok) continue;
    const bool fast_tier = c.tier == cases::Tier::full && tier == cases::Tier::fast;
    g.notes.push_back(fmt::format("{}: {} {}; compared against its committed baseline", c.name, e.name,
                                  fast_tier ? "not run (a full-tier case in the fast tier)" : "not installed"));
  }
}

/// Tolerance of `metric` in a case: its comparison rows', else its tolerance table's, else the
/// default.
cases::Tolerance tolerance_in(const CaseResults& c, const std::string& metric) {
  for (const auto& row : c.comparisons) {
    if (row.metric == metric) return row.tolerance;
  }
  for (const auto& [name, t] : c.tolerances) {
    if (name == metric) return t;
  }
  return comparison::default_tolerance(metric);
}

/// Reports in-house metrics that moved beyond tolerance from the committed baseline.
void check_drift(const CaseResults& c, const std::filesystem::path& baselines, GateFindings& g) {
  if (!c.failure.empty()) return;
  const auto inhouse = std::find_if(c.engines.begin(), c.engines.end(), [](const auto& e) { return e.name == "inhouse"; });
  if (inhouse == c.engines.end()) return;
  const auto file = std::filesystem::is_directory(baselines) ? baselines / (c.name + ".json") : baselines;
  if (!std::filesystem::exists(file)) return;
  store::Baseline b;
  try {
    b = store::read_baseline(file);
  } catch (const std::exception& e) {
    g.failures.push_back(fmt::format("{}: the drift check cannot use its baseline: {}", c.name, e.what()));
    return;
  }
  if (b.case_name != c.name) return;
  for (const auto& [metric, base] : b.inhouse_metrics) {
    const auto now = std::find_if(inhouse->metrics.begin(), inhouse->metrics.end(),
                                  [&](const auto& m) { return m.first == metric; });
    if (now == inhouse->metrics.end()) continue;
    if (!now->second) {
      g.failures.push_back(fmt::format("{}: in-house {} has no value now (baseline {:.9g})", c.name, metric, base));
      continue;
    }
    const double v = *now->second;
    const cases::Tolerance tol = tolerance_in(c, metric);
    if (comparison::judge(v, base, tol) != comparison::Status::pass) {
      g.failures.push_back(fmt::format(
          "{}: in-house {} drifted from the baseline: {:.9g} now, {:.9g} in {} (tolerance rel {:.3g} abs {:.3g}); "
          "if the change is intended, run `demwb refresh --write-baselines`",
          c.name, metric, v, base, file.string(), tol.rel, tol.abs));
    }
  }
}

}  // namespace

GateFindings gate(const SuiteResults& results, const GateOptions& options) {
  GateFindings g;
  check_ensembles(results, g);
  for (const CaseResults& c : results.cases) {
    ++g.cases;
    check_comparisons(c, results.tier, options.allow_missing, g);
    if (options.baselines) check_drift(c, *options.baselines, g);
  }
  return g;
}

std::string gate_summary(const GateFindings& g, const GateOptions& options) {
  std::string counts;
  for (const auto& [status, n] : g.by_status) counts += fmt::format("{}{} {}", counts.empty() ? "" : ", ", n, status);
  return fmt::format("gate: {} case(s), {} comparison(s) ({}){} — {}", g.cases, g.comparisons, counts,
                     options.allow_missing ? ", missing engines allowed" : "", g.passed() ? "PASS" : "FAIL");
}

}  // namespace results
