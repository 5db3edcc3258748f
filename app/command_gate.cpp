// SPDX-License-Identifier: MIT
// `demwb gate`: exit 0 only when every comparison is pass or n/a, and no in-house metric drifted
// from its committed baseline.
#include <cmath>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/case_runner.hpp"
#include "app/cli.hpp"
#include "app/options.hpp"
#include "cases/case_library.hpp"
#include "compare/discrepancy.hpp"
#include "store/result_cache.hpp"
#include "support/text_file.hpp"

namespace app {
namespace {

namespace po = boost::program_options;
using Json = nlohmann::ordered_json;

/// What the gate found.
struct GateFindings {
  std::vector<std::string> failures;
  std::vector<std::string> notes;
  std::size_t cases = 0;
  std::size_t comparisons = 0;
  std::map<std::string, std::size_t> by_status;
  cases::Tier tier = cases::Tier::fast;  ///< the tier the results were made in
};

/// Fails on stored cross-code ensembles (cases/baselines/sweeps) that no longer fit their sweep
/// and case files: their tables would describe another case.
void check_ensembles(const Json& results, GateFindings& g) {
  if (!results.contains("ensembles")) return;
  for (const auto& e : results["ensembles"]) {
    if (e.value("current", false)) continue;
    g.failures.push_back(fmt::format("stored ensemble {}: {}", e.value("sweep", std::string("?")),
                                     e.value("problem", std::string("not current"))));
  }
}

/// The per-case documents of a results.json (aggregate or single case).
std::vector<Json> case_documents(const Json& results) {
  if (results.contains("cases")) return results["cases"].get<std::vector<Json>>();
  return {results};
}

std::string number_text(const Json& v) { return v.is_number() ? fmt::format("{:.9g}", v.get<double>()) : "—"; }

/// Checks every comparison row of one case.
void check_comparisons(const Json& c, bool allow_missing, GateFindings& g) {
  const std::string name = c.value("case", c.value("case_file", std::string("?")));
  if (!c.contains("comparisons")) {
    g.failures.push_back(fmt::format("{}: {} — {}", name, c.value("status", std::string("error")),
                                     c.value("reason", std::string("no results"))));
    return;
  }
  if (c["comparisons"].empty()) {
    g.notes.push_back(name + (c.contains("tolerances") && !c["tolerances"].empty()
                                  ? ": no comparison between engines (one engine); its figures are checked against the "
                                    "committed baseline"
                                  : ": no comparisons (the case lists no metrics)"));
  }
  for (const auto& row : c["comparisons"]) {
    ++g.comparisons;
    const std::string status = row["status"];
    ++g.by_status[status];
    const bool green = status == "pass" || status == "n/a" || (status == "missing" && allow_missing);
    if (green) continue;
    g.failures.push_back(fmt::format("{}: {} {} vs {}: {} — value {} reference {}{}", name, row["metric"].get<std::string>(),
                                     row["engine"].get<std::string>(), row["reference"].get<std::string>(), status,
                                     number_text(row["value"]), number_text(row["reference_value"]),
                                     row.contains("note") ? " (" + row["note"].get<std::string>() + ")" : ""));
  }
  if (c.contains("engines")) {
    for (const auto& [engine, e] : c["engines"].items()) {
      if (e.value("source", std::string("run")) != "baseline" || e.value("status", std::string()) != "ok") continue;
      const bool fast_tier = c.value("tier", std::string("fast")) == "full" && g.tier == cases::Tier::fast;
      g.notes.push_back(fmt::format("{}: {} {}; compared against its committed baseline", name, engine,
                                    fast_tier ? "not run (a full-tier case in the fast tier)" : "not installed"));
    }
  }
}

/// Tolerance of `metric` in a case document (the case's own: its comparison rows, else its
/// tolerance table), else the default.
cases::Tolerance tolerance_in(const Json& c, const std::string& metric) {
  for (const auto& row : c["comparisons"]) {
    if (row["metric"] == metric) {
      return {row["tolerance"].value("rel", 0.0), row["tolerance"].value("abs", 0.0)};
    }
  }
  if (c.contains("tolerances") && c["tolerances"].contains(metric)) {
    const Json& t = c["tolerances"][metric];
    return {t.value("rel", 0.0), t.value("abs", 0.0)};
  }
  return comparison::default_tolerance(metric);
}

/// Reports in-house metrics that moved beyond tolerance from the committed baseline.
void check_drift(const Json& c, const std::filesystem::path& baselines, GateFindings& g) {
  if (!c.contains("case") || !c.contains("engines") || !c["engines"].contains("inhouse")) return;
  const std::string name = c["case"];
  const auto file = std::filesystem::is_directory(baselines) ? baselines / (name + ".json") : baselines;
  if (!std::filesystem::exists(file)) return;
  store::Baseline b;
  try {
    b = store::read_baseline(file);
  } catch (const std::exception& e) {
    g.failures.push_back(fmt::format("{}: the drift check cannot use its baseline: {}", name, e.what()));
    return;
  }
  if (b.case_name != name) return;
  const Json& now = c["engines"]["inhouse"]["metrics"];
  for (const auto& [metric, base] : b.inhouse_metrics) {
    if (!now.contains(metric)) continue;
    if (!now[metric].is_number()) {
      g.failures.push_back(fmt::format("{}: in-house {} has no value now (baseline {:.9g})", name, metric, base));
      continue;
    }
    const double v = now[metric].get<double>();
    const cases::Tolerance tol = tolerance_in(c, metric);
    if (comparison::judge(v, base, tol) != comparison::Status::pass) {
      g.failures.push_back(fmt::format(
          "{}: in-house {} drifted from the baseline: {:.9g} now, {:.9g} in {} (tolerance rel {:.3g} abs {:.3g}); "
          "if the change is intended, run `demwb refresh --write-baselines`",
          name, metric, v, base, file.string(), tol.rel, tol.abs));
    }
  }
}

}  // namespace

int command_gate(const std::vector<std::string>& args, const Invocation& inv) {
  po::options_description opts("options");
  opts.add_options()("baseline", po::value<std::string>(),
                     "baseline file or directory for the drift check (default cases/baselines)")(
      "allow-missing", "let comparisons with an engine that is not installed pass")(
      "output,o", po::value<std::string>(), "where a suite run writes its report (default out/gate-<suite>)")(
      "jobs,j", po::value<unsigned>()->default_value(1), "cases run concurrently (suite runs)");
  add_run_options(opts);
  add_tier_option(opts);
  const auto vm = parse_command(args, "usage: demwb gate DIR|SUITE [--baseline FILE] [--allow-missing] [--tier fast|full]", opts,
                                {"target"});
  if (!vm) return kExitOk;
  const std::string target = (*vm)["target"].as<std::string>();
  std::filesystem::path dir = target;
  if (!std::filesystem::exists(dir / "results.json")) {
    // A suite: run it first, then gate its results.
    const std::filesystem::path suite = cases::resolve_suite(target);
    dir = vm->count("output") != 0 ? std::filesystem::path((*vm)["output"].as<std::string>())
                                   : std::filesystem::path("out") / ("gate-" + suite.filename().string());
    std::vector<std::string> suite_args{suite.string(), "-o", dir.string(), "-j",
                                        std::to_string((*vm)["jobs"].as<unsigned>()), "--tier",
                                        std::string(cases::to_string(tier_option(*vm)))};
    for (auto& a : forwarded_run_options(*vm)) suite_args.push_back(std::move(a));
    if (vm->count("reproducible") != 0) suite_args.push_back("--reproducible");
    if (vm->count("match") != 0) {
      for (const auto& m : (*vm)["match"].as<std::vector<std::string>>()) suite_args.insert(suite_args.end(), {"--match", m});
    }
    if (vm->count("baselines") != 0) {
      suite_args.insert(suite_args.end(), {"--baselines", (*vm)["baselines"].as<std::string>()});
    }
    command_suite(suite_args, inv);
  }
  const Json results = Json::parse(support::read_file(dir / "results.json"));
  const bool allow_missing = vm->count("allow-missing") != 0;
  std::optional<std::filesystem::path> baselines =
      vm->count("baseline") != 0 ? std::optional<std::filesystem::path>((*vm)["baseline"].as<std::string>())
                                 : default_baselines();
  GateFindings g;
  g.tier = cases::parse_tier(results.value("tier", std::string("full"))).value_or(cases::Tier::full);
  check_ensembles(results, g);
  for (const Json& c : case_documents(results)) {
    ++g.cases;
    check_comparisons(c, allow_missing, g);
    if (baselines) check_drift(c, *baselines, g);
  }
  std::string counts;
  for (const auto& [status, n] : g.by_status) counts += fmt::format("{}{} {}", counts.empty() ? "" : ", ", n, status);
  for (const auto& n : g.notes) std::cout << "note: " << n << "\n";
  for (const auto& f : g.failures) std::cout << "FAIL " << f << "\n";
  std::cout << fmt::format("gate: {} case(s), {} comparison(s) ({}){} — {}\n", g.cases, g.comparisons, counts,
                           allow_missing ? ", missing engines allowed" : "", g.failures.empty() ? "PASS" : "FAIL");
  return g.failures.empty() ? kExitOk : kExitFailed;
}

}  // namespace app
