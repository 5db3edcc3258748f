// SPDX-License-Identifier: MIT
// The gate on typed results: what passes, what fails and what it notes, on results built by hand;
// and the same findings whether the results come from a run in this process or are read back
// from the results.json that run wrote.
#include "results/gate.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "../reference/analytic_scenes.hpp"
#include "compare/case_outcome.hpp"
#include "reference/registry.hpp"
#include "reports/results_json.hpp"
#include "store/result_cache.hpp"

namespace {

namespace fs = std::filesystem;

comparison::Comparison row(const std::string& metric, comparison::Status status, double value, double reference,
                           const std::string& note = "") {
  comparison::Comparison c;
  c.metric = metric;
  c.engine = "inhouse";
  c.reference = "analytic";
  c.value = value;
  c.reference_value = reference;
  c.tolerance = {1e-3, 0.0};
  c.status = status;
  c.note = note;
  return c;
}

results::CaseResults one_case(std::vector<comparison::Comparison> rows) {
  results::CaseResults c;
  c.name = "single_collision";
  c.tier = cases::Tier::fast;
  c.comparisons = std::move(rows);
  c.engines.push_back({"inhouse", cases::RunStatus::ok, "run", {{"restitution", 0.99}}});
  c.tolerances.emplace_back("restitution", cases::Tolerance{1e-3, 0.0});
  return c;
}

results::SuiteResults suite_of(std::vector<results::CaseResults> cases) {
  results::SuiteResults s;
  s.suite = "canonical";
  s.tier = cases::Tier::fast;
  s.cases = std::move(cases);
  return s;
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("demwb-gate-test-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(Gate, PassAndNotApplicableRowsPassAndAreCountedByStatus) {
  const auto g = results::gate(suite_of({one_case({row("restitution", comparison::Status::pass, 0.99, 0.99),
                                                   row("max_overlap", comparison::Status::not_applicable, 1, 1)})}),
                               {});
  EXPECT_TRUE(g.passed());
  EXPECT_EQ(g.cases, 1U);
  EXPECT_EQ(g.comparisons, 2U);
  EXPECT_EQ(g.by_status.at("pass"), 1U);
  EXPECT_EQ(g.by_status.at("n/a"), 1U);
  EXPECT_EQ(results::gate_summary(g, {}), "gate: 1 case(s), 2 comparison(s) (1 n/a, 1 pass) — PASS");
}

TEST(Gate, AFailingRowFailsNamingCaseMetricEnginesValuesAndNote) {
  const auto g = results::gate(
      suite_of({one_case({row("restitution", comparison::Status::fail, 0.5, 0.99, "outside tolerance")})}), {});
  ASSERT_EQ(g.failures.size(), 1U);
  EXPECT_EQ(g.failures[0],
            "single_collision: restitution inhouse vs analytic: fail — value 0.5 reference 0.99 (outside tolerance)");
  EXPECT_EQ(results::gate_summary(g, {}), "gate: 1 case(s), 1 comparison(s) (1 fail) — FAIL");
}

TEST(Gate, AMissingEngineFailsUnlessAllowedAndAValueWithoutNumberPrintsADash) {
  comparison::Comparison missing = row("restitution", comparison::Status::missing, 0.0, 0.99);
  missing.value.reset();
  const auto suite = suite_of({one_case({missing})});
  const auto strict = results::gate(suite, {});
  ASSERT_EQ(strict.failures.size(), 1U);
  EXPECT_NE(strict.failures[0].find("value — reference 0.99"), std::string::npos) << strict.failures[0];
  results::GateOptions lenient;
  lenient.allow_missing = true;
  EXPECT_TRUE(results::gate(suite, lenient).passed());
  EXPECT_NE(results::gate_summary(results::gate(suite, lenient), lenient).find(", missing engines allowed"),
            std::string::npos);
}

TEST(Gate, ACaseThatDidNotLoadFailsWithItsReason) {
  const auto g = results::gate(suite_of({results::failed_case("cases/canonical/broken.toml", "model.normal: unknown")}), {});
  ASSERT_EQ(g.failures.size(), 1U);
  EXPECT_EQ(g.failures[0], "cases/canonical/broken.toml: error — model.normal: unknown");
  EXPECT_EQ(g.cases, 1U);
  EXPECT_EQ(g.comparisons, 0U);
}

TEST(Gate, CasesWithoutComparisonsAreNotedAccordingToTheirTolerances) {
  results::CaseResults one_engine = one_case({});
  results::CaseResults no_metrics = one_case({});
  no_metrics.name = "no_metrics";
  no_metrics.tolerances.clear();
  const auto g = results::gate(suite_of({one_engine, no_metrics}), {});
  EXPECT_TRUE(g.passed());
  ASSERT_EQ(g.notes.size(), 2U);
  EXPECT_NE(g.notes[0].find("one engine"), std::string::npos) << g.notes[0];
  EXPECT_NE(g.notes[1].find("lists no metrics"), std::string::npos) << g.notes[1];
}

TEST(Gate, BaselineResultsAreNotedAsNotRunInTheFastTierOrNotInstalled) {
  results::CaseResults full = one_case({row("restitution", comparison::Status::pass, 0.99, 0.99)});
  full.tier = cases::Tier::full;
  full.engines.push_back({"lammps", cases::RunStatus::ok, "baseline", {}});
  full.engines.push_back({"yade", cases::RunStatus::error, "baseline", {}});  // not ok: no note
  results::SuiteResults suite = suite_of({full});
  auto g = results::gate(suite, {});
  ASSERT_EQ(g.notes.size(), 1U);
  EXPECT_EQ(g.notes[0], "single_collision: lammps not run (a full-tier case in the fast tier); compared against its "
                        "committed baseline");
  suite.tier = cases::Tier::full;
  g = results::gate(suite, {});
  ASSERT_EQ(g.notes.size(), 1U);
  EXPECT_NE(g.notes[0].find("lammps not installed"), std::string::npos) << g.notes[0];
}

TEST(Gate, AStoredEnsembleThatIsNotCurrentFails) {
  results::SuiteResults suite = suite_of({one_case({row("restitution", comparison::Status::pass, 0.99, 0.99)})});
  suite.ensembles.push_back({"agglomerate_speed", true, ""});
  suite.ensembles.push_back({"packing_seeds", false, "its case file changed"});
  const auto g = results::gate(suite, {});
  ASSERT_EQ(g.failures.size(), 1U);
  EXPECT_EQ(g.failures[0], "stored ensemble packing_seeds: its case file changed");
}

TEST(Gate, AnInhouseMetricThatMovedFromItsBaselineFails) {
  const fs::path dir = scratch("drift");
  store::Baseline b;
  b.case_name = "single_collision";
  b.inhouse_metrics["restitution"] = 0.99;
  store::write_baseline(dir / "single_collision.json", b);
  results::GateOptions options;
  options.baselines = dir;

  results::CaseResults same = one_case({});
  EXPECT_TRUE(results::gate(suite_of({same}), options).passed());

  results::CaseResults moved = one_case({});
  moved.engines[0].metrics = {{"restitution", 0.98}};
  auto g = results::gate(suite_of({moved}), options);
  ASSERT_EQ(g.failures.size(), 1U);
  EXPECT_NE(g.failures[0].find("in-house restitution drifted from the baseline: 0.98 now, 0.99 in"), std::string::npos)
      << g.failures[0];

  results::CaseResults gone = one_case({});
  gone.engines[0].metrics = {{"restitution", std::nullopt}};
  g = results::gate(suite_of({gone}), options);
  ASSERT_EQ(g.failures.size(), 1U);
  EXPECT_EQ(g.failures[0], "single_collision: in-house restitution has no value now (baseline 0.99)");

  // A tolerance of the comparison rows wins over the case's table: 1 % lets 0.98 pass.
  moved.comparisons.push_back(row("restitution", comparison::Status::pass, 0.98, 0.98));
  moved.comparisons.back().tolerance = {2e-2, 0.0};
  EXPECT_TRUE(results::gate(suite_of({moved}), options).passed());
}

/// The outcome of a real comparison: the core and the closed forms on a single collision whose
/// core runs at a coarse step, with a tight tolerance on one metric so that a row fails.
comparison::CaseOutcome real_outcome() {
  cases::Scene scene = demwb_test::single_collision();
  scene.compare.metrics = {"restitution", "max_overlap", "contact_duration"};
  scene.compare.tolerances["max_overlap"] = cases::Tolerance{1e-12, 0.0};
  std::vector<cases::RunResult> runs;
  for (const char* name : {"inhouse", "analytic"}) runs.push_back(reference::run_engine(*reference::make_engine(name), scene, {}));
  return comparison::evaluate_runs(scene, std::move(runs));
}

TEST(SuiteResults, ARunAndItsResultsJsonGiveTheSameFindings) {
  const comparison::CaseOutcome outcome = real_outcome();
  ASSERT_FALSE(outcome.comparisons.empty());
  results::SuiteResults typed = suite_of({results::case_results(outcome), results::failed_case("x.toml", "bad")});
  nlohmann::ordered_json document;
  document["suite"] = "canonical";
  document["tier"] = "fast";
  document["cases"] = nlohmann::ordered_json::array();
  document["cases"].push_back(reports::results_json(outcome, false));
  document["cases"].push_back({{"case_file", "x.toml"}, {"status", "error"}, {"reason", "bad"}});
  document["ensembles"] = nlohmann::ordered_json::array();
  const results::SuiteResults read = results::read_suite_results(document, "results.json");

  const fs::path dir = scratch("round-trip");
  store::Baseline b;
  b.case_name = outcome.scene.name;
  b.inhouse_metrics["restitution"] = 0.5;  // drifted: both paths must say so
  store::write_baseline(dir / (outcome.scene.name + ".json"), b);
  for (const bool allow_missing : {false, true}) {
    results::GateOptions options;
    options.allow_missing = allow_missing;
    options.baselines = dir;
    const auto a = results::gate(typed, options);
    const auto r = results::gate(read, options);
    EXPECT_FALSE(a.passed());
    EXPECT_EQ(a.failures, r.failures);
    EXPECT_EQ(a.notes, r.notes);
    EXPECT_EQ(a.by_status, r.by_status);
    EXPECT_EQ(a.comparisons, r.comparisons);
    EXPECT_EQ(results::gate_summary(a, options), results::gate_summary(r, options));
  }
  // A single case's results.json (demwb run) reads as a suite of one.
  const auto single = results::read_suite_results(reports::results_json(outcome, false), "run/results.json");
  ASSERT_EQ(single.cases.size(), 1U);
  EXPECT_EQ(single.cases[0].name, outcome.scene.name);
  EXPECT_EQ(single.cases[0].comparisons.size(), outcome.comparisons.size());
}

TEST(SuiteResults, AMalformedResultsJsonIsAnErrorNamingTheFileAndTheKey) {
  const auto message = [](const nlohmann::ordered_json& doc) {
    try {
      static_cast<void>(results::read_suite_results(doc, "out/x/results.json"));
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(nlohmann::ordered_json::array()), "out/x/results.json: the document is not a JSON object");
  EXPECT_EQ(message({{"cases", 3}}), "out/x/results.json: cases is not an array");
  nlohmann::ordered_json bad_status = {
      {"cases", {{{"case", "a"}, {"comparisons", {{{"metric", "m"}, {"engine", "e"}, {"reference", "r"}, {"status", "great"}}}}}}}};
  EXPECT_EQ(message(bad_status),
            "out/x/results.json: cases[0].comparisons[0].status 'great' is not a status (pass, fail, error, missing, n/a)");
  nlohmann::ordered_json no_metric = {{"cases", {{{"case", "a"}, {"comparisons", {{{"engine", "e"}}}}}}}};
  EXPECT_EQ(message(no_metric), "out/x/results.json: cases[0].comparisons[0].metric is missing");
  nlohmann::ordered_json text_value = {
      {"case", "a"},
      {"comparisons", {{{"metric", "m"}, {"engine", "e"}, {"reference", "r"}, {"status", "pass"}, {"value", "1"}}}}};
  EXPECT_EQ(message(text_value), "out/x/results.json: (case).comparisons[0].value is neither a number nor null");
}

}  // namespace
