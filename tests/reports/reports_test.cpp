// SPDX-License-Identifier: MIT
// Report building blocks: tables, numbers, results.json, trace CSV, gnuplot PNGs.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "reports/case_report.hpp"
#include "reports/gnuplot.hpp"
#include "reports/markdown.hpp"
#include "reports/results_json.hpp"
#include "reports/snapshot_vtk.hpp"
#include "reports/trace_csv.hpp"
#include "support/text_file.hpp"

namespace reports_test {

TEST(MarkdownTable, RendersHeaderSeparatorAndEscapedCells) {
  reports::MarkdownTable t({"a", "b"});
  t.add_row({"x|y", "line\nbreak"});
  t.add_row({"only one"});
  EXPECT_EQ(t.render(), "| a | b |\n|---|---|\n| x\\|y | line break |\n| only one |  |\n");
  EXPECT_THROW(t.add_row({"1", "2", "3"}), std::invalid_argument);
}

TEST(Numbers, NeverPrintNaN) {
  EXPECT_EQ(reports::format_number(std::nan("")), "—");
  EXPECT_EQ(reports::format_number(std::nullopt), "—");
  EXPECT_EQ(reports::format_number(0.000643), "0.000643");
  EXPECT_EQ(reports::format_ratio(1.5e-7), "1.50e-07");
}

TEST(ResultsJson, HasTheContractFieldsAndNullInsteadOfNaN) {
  comparison::CaseOutcome o;
  o.scene.name = "c";
  o.scene.source_sha256 = "abc";
  cases::RunResult r;
  r.engine = "inhouse";
  r.status = cases::RunStatus::ok;
  r.version = "v";
  r.wall_time_s = 0.5;
  o.runs.push_back(r);
  o.metrics["inhouse"]["restitution"] = comparison::MetricValue{1.0, "trace", ""};
  o.metrics["inhouse"]["max_overlap"] = comparison::MetricValue{std::nullopt, "", "no contact"};
  comparison::Comparison c;
  c.metric = "restitution";
  c.engine = "inhouse";
  c.reference = "analytic";
  c.value = 1.0;
  c.reference_value = 0.0;
  c.rel_diff = std::nan("");
  c.tolerance = {1e-3, 0.0};
  c.status = comparison::Status::pass;
  o.comparisons.push_back(c);
  const auto j = reports::results_json(o);
  EXPECT_EQ(j["case"], "c");
  EXPECT_EQ(j["case_sha256"], "abc");
  EXPECT_EQ(j["engines"]["inhouse"]["status"], "ok");
  EXPECT_EQ(j["engines"]["inhouse"]["metrics"]["restitution"], 1.0);
  EXPECT_TRUE(j["engines"]["inhouse"]["metrics"]["max_overlap"].is_null());
  EXPECT_EQ(j["engines"]["inhouse"]["metric_problems"]["max_overlap"], "no contact");
  EXPECT_TRUE(j["comparisons"][0]["rel_diff"].is_null());
  EXPECT_EQ(j["comparisons"][0]["tolerance"]["rel"], 1e-3);
  EXPECT_EQ(j["comparisons"][0]["status"], "pass");
  EXPECT_EQ(j.dump().find("NaN"), std::string::npos);
}

TEST(TraceCsv, RoundTripsDoublesExactly) {
  cases::Trace t;
  t.add_column("time");
  t.add_column("p0.x");
  t.append_row({0.1, 1.0 / 3.0});
  const std::string csv = reports::trace_csv(t);
  std::istringstream in(csv);
  std::string header, line;
  std::getline(in, header);
  std::getline(in, line);
  EXPECT_EQ(header, "time,p0.x");
  EXPECT_EQ(std::stod(line.substr(line.find(',') + 1)), 1.0 / 3.0);
}

TEST(SnapshotVtk, WritesPointsRadiiAndVelocities) {
  cases::Scene scene;
  scene.name = "s";
  scene.particles.resize(2);
  scene.particles[0].radius = 0.01;
  scene.particles[1].radius = 0.1;
  scene.particles[1].fixed = true;
  cases::Snapshot snap;
  snap.time = 0.5;
  snap.position = {{0, 0, 0}, {0.11, 0, 0}};
  snap.velocity = {{4, 0, 0}, {0, 0, 0}};
  snap.angular_velocity = {{0, 0, 0}, {0, 0, 0}};
  const std::string vtk = reports::snapshot_vtk(scene, snap, "inhouse");
  EXPECT_EQ(vtk.rfind("# vtk DataFile Version 3.0\n", 0), 0U);
  EXPECT_NE(vtk.find("POINTS 2 double\n0 0 0\n0.11 0 0\n"), std::string::npos) << vtk;
  EXPECT_NE(vtk.find("SCALARS radius double 1\nLOOKUP_TABLE default\n0.01\n0.10000000000000001\n"), std::string::npos);
  EXPECT_NE(vtk.find("SCALARS fixed int 1\nLOOKUP_TABLE default\n0\n1\n"), std::string::npos);
  EXPECT_NE(vtk.find("VECTORS velocity double\n4 0 0\n"), std::string::npos);
  EXPECT_NE(vtk.find("SCALARS material int 1\nLOOKUP_TABLE default\n0\n0\n"), std::string::npos) << vtk;
  EXPECT_NE(vtk.find("SCALARS contacts int 1\nLOOKUP_TABLE default\n"), std::string::npos) << vtk;
}

TEST(SnapshotVtk, CountsEachSpheresContactsWithSpheresAndWalls) {
  // Three spheres of radius 10 mm over a floor that rises at 1 mm/s: 0 and 1 overlap (15.6 mm
  // apart), 2 is 30 mm from both; at t = 1 s the floor is at z = 1 mm and 0 and 2 (centres 9 and
  // 9.5 mm above it) overlap it, while 1 (19 mm above) does not.
  cases::Scene scene;
  scene.particles.resize(3);
  for (auto& p : scene.particles) p.radius = 0.01;
  cases::WallSpec floor;
  floor.normal = {0.0, 0.0, 1.0};
  floor.velocity = {0.0, 0.0, 0.001};  // at t = 1 s the floor is at z = 1 mm
  scene.walls.push_back(floor);
  cases::Snapshot snap;
  snap.time = 1.0;
  snap.position = {{0.0, 0.0, 0.010}, {0.012, 0.0, 0.02}, {0.0, 0.03, 0.0105}};
  EXPECT_EQ(reports::snapshot_contacts(scene, snap), (std::vector<int>{2, 1, 1}));
  snap.time = 0.0;  // the floor at z = 0: spheres 0 (10 mm up) and 2 (10.5 mm) no longer overlap it
  EXPECT_EQ(reports::snapshot_contacts(scene, snap), (std::vector<int>{1, 1, 0}));
}

TEST(SnapshotVtk, TheSeriesFileListsEachSnapshotWithItsTime) {
  const auto j = nlohmann::json::parse(reports::vtk_series({{"inhouse_0000.vtk", 0.0}, {"inhouse_0001.vtk", 0.045}}));
  EXPECT_EQ(j.at("file-series-version"), "1.0");
  ASSERT_EQ(j.at("files").size(), 2U);
  EXPECT_EQ(j.at("files")[1].at("name"), "inhouse_0001.vtk");
  EXPECT_EQ(j.at("files")[1].at("time"), 0.045);
}

TEST(Gnuplot, RendersAPngAndKeepsItsDataAndScript) {
  const auto dir = std::filesystem::temp_directory_path() / "demwb_gnuplot_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  reports::Plot p;
  p.title = "test";
  p.xlabel = "x";
  p.ylabel = "y";
  p.log_y = true;
  p.series.push_back({"curve", {1, 2, 3, 4}, {1, 4, 9, std::nan("")}, "linespoints", {}});
  const auto problem = reports::render_png(p, dir / "plot.png");
  ASSERT_FALSE(problem.has_value()) << *problem;
  const std::string png = support::read_file(dir / "plot.png");
  ASSERT_GT(png.size(), 8U);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  EXPECT_TRUE(std::filesystem::exists(dir / "plot.gp"));
  EXPECT_EQ(support::read_file(dir / "plot.dat").find("nan"), std::string::npos);
}

}  // namespace

namespace reports_test {

/// An outcome whose LAMMPS run was calibrated and cannot express one metric.
comparison::CaseOutcome calibrated_outcome() {
  comparison::CaseOutcome o;
  o.scene.name = "damped";
  o.scene.source_sha256 = "0123456789abcdef0123";
  cases::RunResult r;
  r.engine = "lammps";
  r.status = cases::RunStatus::ok;
  r.inexpressible_metrics["rupture_separation"] = "breaks at the load-controlled pull-off point";
  r.calibrations.push_back({"tsuji e_in", 0.5, 0.47, {{0.5, 0.52}, {0.47, 0.5}}, "secant on two-body runs"});
  o.runs.push_back(r);
  return o;
}

TEST(ResultsJson, CarriesCalibrationsAndInexpressibleMetrics) {
  const auto j = reports::results_json(calibrated_outcome());
  const auto& e = j["engines"]["lammps"];
  EXPECT_EQ(e["inexpressible_metrics"]["rupture_separation"], "breaks at the load-controlled pull-off point");
  ASSERT_EQ(e["calibrations"].size(), 1U);
  EXPECT_EQ(e["calibrations"][0]["chosen"], 0.47);
  EXPECT_EQ(e["calibrations"][0]["samples"][0]["restitution"], 0.52);
}

TEST(CaseReport, ShowsTheCalibrationTableAndWhyAMetricIsNotCompared) {
  const std::string md = reports::case_section(calibrated_outcome(), "/tmp/plots", "/tmp", 2);
  EXPECT_NE(md.find("Restitution calibration"), std::string::npos) << md;
  EXPECT_NE(md.find("| 0.47 | 0.5 | 0.00e+00 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| lammps | rupture_separation | breaks at the load-controlled pull-off point |"),
            std::string::npos)
      << md;
}

/// An outcome whose case lists the core alone: LAMMPS expresses it, LIGGGHTS cannot.
comparison::CaseOutcome unlisted_outcome() {
  comparison::CaseOutcome o;
  o.scene.name = "pour";
  o.scene.source_sha256 = "0123456789abcdef0123";
  cases::RunResult r;
  r.engine = "inhouse";
  r.status = cases::RunStatus::ok;
  o.runs.push_back(r);
  o.metrics["inhouse"] = {};
  o.unlisted.push_back({"lammps", {}});
  o.unlisted.push_back({"liggghts", "no incremental Mindlin; no cone | walls"});
  return o;
}

TEST(ResultsJson, CarriesTheVerdictsOfReferenceCodesTheCaseDoesNotList) {
  const auto j = reports::results_json(unlisted_outcome());
  EXPECT_EQ(j["unlisted_codes"]["lammps"]["status"], "expressible");
  EXPECT_FALSE(j["unlisted_codes"]["lammps"].contains("reason"));
  EXPECT_EQ(j["unlisted_codes"]["liggghts"]["status"], "n/a");
  EXPECT_EQ(j["unlisted_codes"]["liggghts"]["reason"], "no incremental Mindlin; no cone | walls");
  EXPECT_FALSE(j["engines"].contains("liggghts")) << "a code that did not run is no engine entry";
  // A command that did not ask (demwb run) writes no such key.
  comparison::CaseOutcome asked_none = unlisted_outcome();
  asked_none.unlisted.clear();
  EXPECT_FALSE(reports::results_json(asked_none).contains("unlisted_codes"));
}

TEST(CaseReport, ListsTheReferenceCodesTheCaseDoesNotListWithTheirVerdicts) {
  const std::string md = reports::case_section(unlisted_outcome(), "/tmp/plots", "/tmp", 2);
  EXPECT_NE(md.find("### Reference codes not among the engines"), std::string::npos) << md;
  EXPECT_NE(md.find("| lammps | expresses it | — |"), std::string::npos) << md;
  EXPECT_NE(md.find("| liggghts | n/a | no incremental Mindlin; no cone \\| walls |"), std::string::npos) << md;
  EXPECT_NE(md.find("leave it out"), std::string::npos) << md;
  // Only codes that cannot: no sentence about codes that could run.
  comparison::CaseOutcome none_can = unlisted_outcome();
  none_can.unlisted.erase(none_can.unlisted.begin());
  const std::string only_na = reports::case_section(none_can, "/tmp/plots", "/tmp", 2);
  EXPECT_NE(only_na.find("| liggghts | n/a |"), std::string::npos) << only_na;
  EXPECT_EQ(only_na.find("leave it out"), std::string::npos) << only_na;
  none_can.unlisted.clear();
  EXPECT_EQ(reports::case_section(none_can, "/tmp/plots", "/tmp", 2).find("not among the engines"), std::string::npos);
}

}  // namespace
