// SPDX-License-Identifier: MIT
// Statuses of comparisons: pass/fail by tolerance; error, missing and n/a never pass.
#include <gtest/gtest.h>

#include <algorithm>

#include "cases/catalogue.hpp"
#include "compare/case_outcome.hpp"
#include "compare/discrepancy.hpp"
#include "scene_fixtures.hpp"

namespace discrepancy_test {

using comparison::Status;
using test_support::collision_scene;
using test_support::collision_trace;
using test_support::ok_run;

TEST(Judge, PassesWithinAbsPlusRelTimesReference) {
  EXPECT_EQ(comparison::judge(1.0009, 1.0, {1e-3, 0.0}), Status::pass);
  EXPECT_EQ(comparison::judge(1.0011, 1.0, {1e-3, 0.0}), Status::fail);
  EXPECT_EQ(comparison::judge(0.0009, 0.0, {0.0, 1e-3}), Status::pass);
  EXPECT_EQ(comparison::judge(0.0011, 0.0, {0.0, 1e-3}), Status::fail);
}

TEST(Statuses, OnlyPassAndNotApplicableAreGreen) {
  EXPECT_TRUE(comparison::is_green(Status::pass));
  EXPECT_TRUE(comparison::is_green(Status::not_applicable));
  EXPECT_FALSE(comparison::is_green(Status::fail));
  EXPECT_FALSE(comparison::is_green(Status::error));
  EXPECT_FALSE(comparison::is_green(Status::missing));
  for (const auto s : {Status::pass, Status::fail, Status::error, Status::missing, Status::not_applicable}) {
    EXPECT_EQ(comparison::parse_status(comparison::to_string(s)), s);
  }
}

cases::RunResult failed_run(const std::string& engine, cases::RunStatus status, const std::string& reason) {
  cases::RunResult r;
  r.engine = engine;
  r.status = status;
  r.reason = reason;
  return r;
}

TEST(CompareRuns, IdenticalTracesPassAndAmplitudeErrorIsMeasuredAgainstZero) {
  const auto scene = collision_scene({"contact_duration", "amplitude_error"});
  const auto o = comparison::evaluate_runs(scene, {ok_run("analytic", collision_trace(5e-6)),
                                                   ok_run("inhouse", collision_trace(5e-6))});
  ASSERT_EQ(o.comparisons.size(), 2U);
  for (const auto& c : o.comparisons) {
    EXPECT_EQ(c.status, Status::pass) << c.metric << ": " << c.note;
    EXPECT_EQ(c.engine, "inhouse");
  }
  EXPECT_EQ(*o.comparisons[1].reference_value, 0.0);
  EXPECT_FALSE(o.comparisons[1].rel_diff.has_value());  // relative to 0 is undefined, not NaN
  EXPECT_EQ(comparison::worst_status(o), Status::pass);
}

TEST(CompareRuns, OutOfToleranceFails) {
  auto scene = collision_scene({"restitution"});
  const auto o = comparison::evaluate_runs(scene, {ok_run("analytic", collision_trace(5e-6)),
                                                   ok_run("inhouse", collision_trace(5e-6, 0.99))});
  ASSERT_EQ(o.comparisons.size(), 1U);
  EXPECT_EQ(o.comparisons[0].status, Status::fail);
  EXPECT_NEAR(*o.comparisons[0].abs_diff, 0.01, 1e-9);
}

TEST(CompareRuns, MissingErrorAndNotApplicableEnginesNeverPass) {
  const auto scene = collision_scene({"max_overlap"});
  const auto o = comparison::evaluate_runs(
      scene, {ok_run("analytic", collision_trace(5e-6)), failed_run("lammps", cases::RunStatus::missing, "not installed"),
              failed_run("yade", cases::RunStatus::error, "segfault"),
              failed_run("inhouse", cases::RunStatus::not_applicable, "cannot")});
  ASSERT_EQ(o.comparisons.size(), 3U);
  EXPECT_EQ(o.comparisons[0].status, Status::missing);
  EXPECT_EQ(o.comparisons[1].status, Status::error);
  EXPECT_EQ(o.comparisons[1].note, "segfault");
  EXPECT_EQ(o.comparisons[2].status, Status::not_applicable);
  EXPECT_EQ(comparison::worst_status(o), Status::error);
}

TEST(CompareRuns, AReferenceThatCannotExpressTheCaseIsAnErrorNotAPass) {
  const auto scene = collision_scene({"max_overlap"});
  const auto o = comparison::evaluate_runs(
      scene, {failed_run("analytic", cases::RunStatus::not_applicable, "no closed form"),
              ok_run("inhouse", collision_trace(5e-6))});
  ASSERT_EQ(o.comparisons.size(), 1U);
  EXPECT_EQ(o.comparisons[0].status, Status::error);
  EXPECT_NE(o.comparisons[0].note.find("no closed form"), std::string::npos);
}

TEST(CompareRuns, AMetricThatCannotBeComputedIsAnError) {
  auto scene = collision_scene({"max_overlap"});
  cases::Trace empty;
  empty.add_column("time");
  const auto o = comparison::evaluate_runs(scene, {ok_run("analytic", collision_trace(5e-6)), ok_run("inhouse", empty)});
  ASSERT_EQ(o.comparisons.size(), 1U);
  EXPECT_EQ(o.comparisons[0].status, Status::error);
  EXPECT_FALSE(o.comparisons[0].note.empty());
}

TEST(CompareRuns, CaseTolerancesOverrideTheDefaults) {
  auto scene = collision_scene({"restitution"});
  EXPECT_EQ(comparison::tolerance_for(scene, "restitution").abs, 1e-3);
  scene.compare.tolerances["restitution"] = {0.0, 0.05};
  const auto o = comparison::evaluate_runs(scene, {ok_run("analytic", collision_trace(5e-6)),
                                                   ok_run("inhouse", collision_trace(5e-6, 0.99))});
  EXPECT_EQ(o.comparisons[0].status, Status::pass);
}

}  // namespace

namespace discrepancy_test {

TEST(CompareRuns, AMetricTheEngineCannotExpressIsNotApplicableWithItsReason) {
  const auto scene = test_support::collision_scene({"max_overlap", "restitution"});
  auto lammps = test_support::ok_run("lammps", test_support::collision_trace(5e-6));
  lammps.inexpressible_metrics["restitution"] = "breaks contacts elsewhere by design";
  const auto o = comparison::evaluate_runs(scene, {test_support::ok_run("analytic", test_support::collision_trace(5e-6)), lammps});
  ASSERT_EQ(o.comparisons.size(), 2U);
  EXPECT_EQ(o.comparisons[0].status, comparison::Status::pass);
  EXPECT_EQ(o.comparisons[1].status, comparison::Status::not_applicable);
  EXPECT_EQ(o.comparisons[1].note, "lammps: breaks contacts elsewhere by design");
}

}  // namespace

namespace discrepancy_test {

TEST(DefaultTolerances, EveryCataloguedMetricHasOneOfItsKindAndMatchedRowsUseOneE8) {
  for (const auto& m : cases::metric_catalogue()) {
    const cases::Tolerance t = comparison::default_tolerance(m.name);
    // End-state components and the tangential force peak are relative with an absolute floor
    // (a component, or a frictionless contact's force, that is 0 in the reference); every other
    // metric has exactly one kind.
    if (m.name.find("velocity_after_") != std::string_view::npos || m.name == "tangential_force_max") {
      EXPECT_EQ(t.rel, 1e-3) << m.name;
      EXPECT_GT(t.abs, 0.0) << m.name;
      EXPECT_EQ(comparison::matched_tolerance_for(cases::Scene{}, std::string(m.name)).abs, 1e-8) << m.name;
      continue;
    }
    EXPECT_TRUE((t.rel > 0.0) != (t.abs > 0.0)) << m.name << " should have exactly one default kind";
  }
  EXPECT_EQ(comparison::default_tolerance("rebound_angle").abs, 0.05);
  EXPECT_EQ(comparison::default_tolerance("tangential_restitution").abs, 1e-3);
  EXPECT_EQ(comparison::default_tolerance("rupture_separation").rel, 5e-3);
  cases::Scene scene;
  EXPECT_EQ(comparison::matched_tolerance_for(scene, "restitution").abs, 1e-8);
  EXPECT_EQ(comparison::matched_tolerance_for(scene, "restitution").rel, 0.0);
  EXPECT_EQ(comparison::matched_tolerance_for(scene, "contact_duration").rel, 1e-8);
  scene.compare.matched_tolerances["contact_duration"] = {1e-10, 0.0};
  EXPECT_EQ(comparison::matched_tolerance_for(scene, "contact_duration").rel, 1e-10);
}

}  // namespace

namespace discrepancy_test {

/// Rows of `o` for `engine` against `reference`.
std::vector<comparison::Comparison> rows_of(const comparison::CaseOutcome& o, const std::string& engine,
                                            const std::string& reference) {
  std::vector<comparison::Comparison> rows;
  for (const auto& c : o.comparisons) {
    if (c.engine == engine && c.reference == reference) rows.push_back(c);
  }
  return rows;
}

TEST(MatchedRows, AMatchedRunIsJudgedAgainstItsCodeOnlyWithTheTraceDeviation) {
  auto scene = test_support::collision_scene({"max_overlap", "restitution"});
  scene.compare.matched = {"lammps"};
  scene.output.trace_particles = {0};
  const auto trace = test_support::collision_trace(5e-6, 0.9);
  const auto o = comparison::evaluate_runs(
      scene, {test_support::ok_run("analytic", test_support::collision_trace(5e-6)),
              test_support::ok_run("lammps", trace), test_support::ok_run("inhouse@lammps", trace)});
  EXPECT_TRUE(rows_of(o, "inhouse@lammps", "analytic").empty());
  const auto matched = rows_of(o, "inhouse@lammps", "lammps");
  ASSERT_EQ(matched.size(), 3U);
  EXPECT_EQ(matched[0].metric, "max_overlap");
  EXPECT_EQ(matched[0].tolerance.rel, 1e-8);
  EXPECT_EQ(matched[1].metric, "restitution");
  EXPECT_EQ(matched[1].tolerance.abs, 1e-8);
  EXPECT_EQ(matched[2].metric, "trace_deviation");
  for (const auto& row : matched) {
    EXPECT_EQ(row.status, comparison::Status::pass) << row.metric << ": " << row.note;
  }
  ASSERT_TRUE(matched[2].value) << matched[2].note;
  EXPECT_EQ(*matched[2].value, 0.0);
  // The native LAMMPS run (restitution 0.9) fails against the elastic closed form.
  const auto native = rows_of(o, "lammps", "analytic");
  ASSERT_EQ(native.size(), 2U);
  EXPECT_EQ(native[1].status, comparison::Status::fail);
}

TEST(MatchedRows, ARestitutionOffByOnePartInAMillionFailsTheTraceDeviation) {
  auto scene = test_support::collision_scene({"max_overlap"});
  scene.compare.matched = {"yade"};
  scene.output.trace_particles = {0};
  const auto trace = test_support::collision_trace(5e-6);
  const cases::Trace shifted = test_support::collision_trace(5e-6, 1.0 - 1e-6);
  const auto o = comparison::evaluate_runs(
      scene, {test_support::ok_run("analytic", trace), test_support::ok_run("yade", trace),
              test_support::ok_run("inhouse@yade", shifted)});
  const auto matched = rows_of(o, "inhouse@yade", "yade");
  ASSERT_EQ(matched.size(), 2U);
  EXPECT_EQ(matched[1].metric, "trace_deviation");
  EXPECT_EQ(matched[1].status, comparison::Status::fail) << matched[1].note;
  ASSERT_TRUE(matched[1].value) << matched[1].note;
  EXPECT_GT(*matched[1].value, 1e-8);
  EXPECT_LT(*matched[1].value, 1e-4);
}

/// `trace` with `dx` [m] added to p0.x from row `from` on (a trace that parts there).
cases::Trace drifted(const cases::Trace& trace, std::size_t from, double dx) {
  cases::Trace out;
  for (const std::string& name : trace.columns()) out.add_column(name);
  const std::size_t x = static_cast<std::size_t>(
      std::find(trace.columns().begin(), trace.columns().end(), cases::particle_column(0, "x")) - trace.columns().begin());
  for (std::size_t k = 0; k < trace.rows(); ++k) {
    std::vector<double> row;
    for (std::size_t c = 0; c < trace.columns().size(); ++c) row.push_back(trace.values(c)[k]);
    if (k >= from) row[x] += dx;
    out.append_row(row);
  }
  return out;
}

/// The matched rows of a collision in which the matched run departs from the code by `gap`
/// [m] from row `parts` on, and its round-off twin departs from the run by `twin_gap` from row
/// `twin_parts` on.
std::vector<comparison::Comparison> matched_with_twin(std::size_t parts, double gap, std::size_t twin_parts,
                                                      double twin_gap) {
  auto scene = test_support::collision_scene({"max_overlap"});
  scene.compare.matched = {"lammps"};
  scene.output.trace_particles = {0};
  const auto trace = test_support::collision_trace(5e-6);
  auto ours = test_support::ok_run("inhouse@lammps", drifted(trace, parts, gap));
  ours.roundoff_twin = drifted(ours.trace, twin_parts, twin_gap);
  const auto o = comparison::evaluate_runs(
      scene, {test_support::ok_run("analytic", trace), test_support::ok_run("lammps", trace), ours});
  return rows_of(o, "inhouse@lammps", "lammps");
}

TEST(MatchedRows, RowsPastTheRoundoffHorizonAreNotCompared) {
  const auto reference_rows = test_support::collision_trace(5e-6).rows();
  // The twin drifts past 1e-10 (relative to the max overlap u/ω ≈ 8.2e-4 m) at row 60; the run parts
  // from the code there too, by far more than the tolerance: only rows before 60 count.
  const auto horizon = matched_with_twin(60, 1e-6, 60, 1e-12);
  ASSERT_EQ(horizon.back().metric, "trace_deviation");
  EXPECT_EQ(horizon.back().status, comparison::Status::pass) << horizon.back().note;
  ASSERT_TRUE(horizon.back().value);
  EXPECT_EQ(*horizon.back().value, 0.0);
  EXPECT_NE(horizon.back().note.find(comparison::kRoundoffHorizonNote), std::string::npos) << horizon.back().note;
  EXPECT_NE(horizon.back().note.find("row 60 of " + std::to_string(reference_rows)), std::string::npos)
      << horizon.back().note;
  // A twin that stays within 1e-10 leaves every row compared: the same departure fails.
  const auto steady = matched_with_twin(60, 1e-6, 60, 1e-16);
  EXPECT_EQ(steady.back().status, comparison::Status::fail) << steady.back().note;
  EXPECT_EQ(steady.back().note.find(comparison::kRoundoffHorizonNote), std::string::npos) << steady.back().note;
  // A model difference shows before the horizon and fails however chaotic the scene is later.
  const auto early = matched_with_twin(40, 1e-9, 60, 1e-12);
  EXPECT_EQ(early.back().status, comparison::Status::fail) << early.back().note;
  ASSERT_TRUE(early.back().value);
  EXPECT_GT(*early.back().value, 1e-8);
  // A horizon within the first tenth of the run leaves too little to judge: n/a, with the reason.
  const auto vacuous = matched_with_twin(5, 1e-6, 5, 1e-12);
  EXPECT_EQ(vacuous.back().status, comparison::Status::not_applicable) << vacuous.back().note;
  EXPECT_NE(vacuous.back().note.find("under a tenth"), std::string::npos) << vacuous.back().note;
}

TEST(MatchedRows, AMetricItsCodeCannotExpressForTheCaseIsStillComparedInTheMatchedRun) {
  auto scene = test_support::collision_scene({"max_overlap", "restitution"});
  scene.compare.matched = {"lammps"};
  const auto trace = test_support::collision_trace(5e-6);
  auto lammps = test_support::ok_run("lammps", trace);
  lammps.inexpressible_metrics["restitution"] = "breaks contacts elsewhere by design";
  const auto o = comparison::evaluate_runs(
      scene, {test_support::ok_run("analytic", trace), lammps, test_support::ok_run("inhouse@lammps", trace)});
  const auto native = rows_of(o, "lammps", "analytic");
  ASSERT_EQ(native.size(), 2U);
  EXPECT_EQ(native[1].status, comparison::Status::not_applicable);
  const auto matched = rows_of(o, "inhouse@lammps", "lammps");
  ASSERT_EQ(matched.size(), 3U);
  EXPECT_EQ(matched[0].status, comparison::Status::pass);
  EXPECT_EQ(matched[1].status, comparison::Status::pass) << matched[1].note;
  EXPECT_NE(matched[1].note.find("breaks contacts elsewhere by design"), std::string::npos) << matched[1].note;
}

TEST(MatchedRows, AMatchedRunThatDisagreesOnSuchAMetricFails) {
  auto scene = test_support::collision_scene({"restitution"});
  scene.compare.matched = {"lammps"};
  auto lammps = test_support::ok_run("lammps", test_support::collision_trace(5e-6, 0.9));
  lammps.inexpressible_metrics["restitution"] = "breaks contacts elsewhere by design";
  const auto o = comparison::evaluate_runs(scene, {test_support::ok_run("analytic", test_support::collision_trace(5e-6)),
                                                   lammps,
                                                   test_support::ok_run("inhouse@lammps", test_support::collision_trace(5e-6))});
  const auto matched = rows_of(o, "inhouse@lammps", "lammps");
  ASSERT_FALSE(matched.empty());
  EXPECT_EQ(matched[0].status, comparison::Status::fail);
}

TEST(MatchedRows, AMatchedCodeThatFailedMakesEveryMatchedRowAnError) {
  auto scene = test_support::collision_scene({"max_overlap"});
  scene.compare.matched = {"lammps"};
  const auto trace = test_support::collision_trace(5e-6);
  cases::RunResult crashed;
  crashed.engine = "lammps";
  crashed.status = cases::RunStatus::error;
  crashed.reason = "lmp exited with status 1";
  const auto o = comparison::evaluate_runs(
      scene, {test_support::ok_run("analytic", trace), crashed, test_support::ok_run("inhouse@lammps", trace)});
  for (const auto& row : rows_of(o, "inhouse@lammps", "lammps")) {
    EXPECT_EQ(row.status, comparison::Status::error) << row.metric;
    EXPECT_NE(row.note.find("lmp exited with status 1"), std::string::npos) << row.note;
  }
}

}  // namespace

namespace discrepancy_test {

/// An outcome whose rows have the given statuses.
comparison::CaseOutcome with_statuses(std::initializer_list<comparison::Status> statuses) {
  comparison::CaseOutcome o;
  for (const auto s : statuses) {
    comparison::Comparison c;
    c.status = s;
    o.comparisons.push_back(c);
  }
  return o;
}

TEST(WorstStatus, NotApplicableRowsDoNotTurnAPassingCaseIntoNotApplicable) {
  using comparison::Status;
  EXPECT_EQ(comparison::worst_status(with_statuses({})), Status::pass);
  EXPECT_EQ(comparison::worst_status(with_statuses({Status::pass, Status::not_applicable})), Status::pass);
  EXPECT_EQ(comparison::worst_status(with_statuses({Status::not_applicable})), Status::not_applicable);
  EXPECT_EQ(comparison::worst_status(with_statuses({Status::not_applicable, Status::missing})), Status::missing);
  EXPECT_EQ(comparison::worst_status(with_statuses({Status::fail, Status::missing, Status::pass})), Status::fail);
  EXPECT_EQ(comparison::worst_status(with_statuses({Status::fail, Status::error})), Status::error);
  EXPECT_EQ(comparison::worse(Status::missing, Status::fail), Status::fail);
}

}  // namespace
