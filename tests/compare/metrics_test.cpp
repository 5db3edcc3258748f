// SPDX-License-Identifier: MIT
// Metrics computed from traces, the same way for every engine.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "compare/metrics.hpp"
#include "scene_fixtures.hpp"

namespace metrics_test {

using test_support::collision_scene;
using test_support::collision_trace;
using test_support::ok_run;

constexpr double kOmega = 4886.025119;

TEST(Metrics, ContactDurationAndMaxOverlapFromASampledTrace) {
  const auto scene = collision_scene({"contact_duration", "max_overlap", "max_force", "restitution", "max_position"});
  const auto m = comparison::compute_metrics(scene, ok_run("inhouse", collision_trace(5e-6)), nullptr);
  EXPECT_NEAR(*m.at("contact_duration").value, std::numbers::pi / kOmega, 2e-3 * std::numbers::pi / kOmega);
  EXPECT_NEAR(*m.at("max_overlap").value, 4.0 / kOmega, 1e-6 * 4.0 / kOmega);  // parabola-refined
  EXPECT_NEAR(*m.at("max_force").value, 1e5 * 4.0 / kOmega, 1e-6 * 1e5 * 4.0 / kOmega);
  EXPECT_NEAR(*m.at("restitution").value, 1.0, 1e-12);
  EXPECT_NEAR(*m.at("max_position").value, 0.0002 + 4.0 / kOmega, 1e-4 * 4.0 / kOmega);
  EXPECT_EQ(m.at("max_overlap").source, "trace");
}

TEST(Metrics, RestitutionIsTheRatioOfNormalSpeeds) {
  const auto scene = collision_scene({"restitution"});
  const auto m = comparison::compute_metrics(scene, ok_run("inhouse", collision_trace(5e-6, 0.6)), nullptr);
  EXPECT_NEAR(*m.at("restitution").value, 0.6, 1e-12);
}

TEST(Metrics, ClosedFormValuesOfAnEngineTakePrecedence) {
  auto run = ok_run("analytic", collision_trace(5e-6));
  run.exact_metrics["contact_duration"] = 1.25;
  const auto m = comparison::compute_metrics(collision_scene({"contact_duration"}), run, nullptr);
  EXPECT_EQ(*m.at("contact_duration").value, 1.25);
  EXPECT_EQ(m.at("contact_duration").source, "closed form");
}

TEST(Metrics, AmplitudeErrorOfTheAnalyticTraceItselfIsZero) {
  const auto scene = collision_scene({"amplitude_error"});
  const auto exact = ok_run("analytic", collision_trace(5e-6));
  const auto m = comparison::compute_metrics(scene, exact, &exact);
  EXPECT_EQ(*m.at("amplitude_error").value, 0.0);
}

TEST(Metrics, AmplitudeErrorFollowsEquation48) {
  const auto scene = collision_scene({"amplitude_error"});
  const auto exact = ok_run("analytic", collision_trace(5e-6));
  cases::Trace shifted = collision_trace(5e-6);
  // Push the numerical maximum 1 µm further: εx_amp = 1e-6 / max overlap.
  auto x = *shifted.column("p0.x");
  cases::Trace bumped;
  for (const auto& name : shifted.columns()) bumped.add_column(name);
  for (std::size_t r = 0; r < shifted.rows(); ++r) {
    std::vector<double> row;
    for (std::size_t c = 0; c < shifted.columns().size(); ++c) row.push_back(shifted.values(c)[r]);
    row[1] += 1e-6;
    bumped.append_row(row);
  }
  const auto m = comparison::compute_metrics(scene, ok_run("inhouse", bumped), &exact);
  double max_overlap = 0.0;
  for (const double d : *exact.trace.column("c0-1.overlap")) max_overlap = std::max(max_overlap, d);
  EXPECT_NEAR(*m.at("amplitude_error").value, 1e-6 / max_overlap, 1e-9);
}

TEST(Metrics, AmplitudeErrorRefusesTracesSampledAtOtherTimes) {
  const auto scene = collision_scene({"amplitude_error"});
  const auto exact = ok_run("analytic", collision_trace(5e-6));
  const auto m = comparison::compute_metrics(scene, ok_run("inhouse", collision_trace(5e-6, 1.0, 1e-7)), &exact);
  EXPECT_FALSE(m.at("amplitude_error").value.has_value());
  EXPECT_NE(m.at("amplitude_error").problem.find("other times"), std::string::npos);
}

TEST(Metrics, MissingContactGivesAProblemNotANumber) {
  auto scene = collision_scene({"contact_duration", "restitution"});
  scene.compare.pair = cases::ParticlePair{0, 1};
  cases::Trace tr;
  for (const char* c : {"time", "p0.x", "p0.y", "p0.z", "p0.vx", "p0.vy", "p0.vz", "c0-1.overlap", "c0-1.fn"}) tr.add_column(c);
  tr.append_row({0, 0, 0, 0, 1, 0, 0, -1, 0});
  tr.append_row({1, 1, 0, 0, 1, 0, 0, -0.5, 0});
  const auto m = comparison::compute_metrics(scene, ok_run("inhouse", tr), nullptr);
  EXPECT_FALSE(m.at("contact_duration").value.has_value());
  EXPECT_NE(m.at("contact_duration").problem.find("never come into contact"), std::string::npos);
}

TEST(Metrics, EngineThatDidNotRunHasNoValues) {
  cases::RunResult r;
  r.engine = "lammps";
  r.status = cases::RunStatus::missing;
  const auto m = comparison::compute_metrics(collision_scene({"max_overlap"}), r, nullptr);
  EXPECT_FALSE(m.at("max_overlap").value.has_value());
  EXPECT_NE(m.at("max_overlap").problem.find("missing"), std::string::npos);
}

TEST(Metrics, NonFiniteValuesBecomeProblems) {
  auto run = ok_run("analytic", collision_trace(5e-6));
  run.exact_metrics["max_overlap"] = std::nan("");
  const auto m = comparison::compute_metrics(collision_scene({"max_overlap"}), run, nullptr);
  EXPECT_FALSE(m.at("max_overlap").value.has_value());
}

}  // namespace

namespace metrics_test {

TEST(Metrics, WallContactRestitutionUsesTheWallNormalAndVelocity) {
  // A sphere falling onto a floor (normal +z) at 2 m/s, rebounding at 1.5 m/s.
  cases::Scene s;
  s.particles.resize(1);
  s.particles[0].radius = 0.01;
  s.particles[0].position = {0.0, 0.0, 0.012};
  s.particles[0].velocity = {0.0, 0.0, -2.0};
  s.walls.push_back({"floor", {0, 0, 0}, {0, 0, 1}, {0, 0, 0}, 0});
  s.compare.subject = 0;
  s.compare.wall_contact = cases::ParticlePair{0, 0};
  s.compare.metrics = {"restitution", "contact_duration", "max_position"};
  cases::Trace tr;
  for (const char* c : {"time", "p0.x", "p0.y", "p0.z", "p0.vx", "p0.vy", "p0.vz", "c0-w0.overlap", "c0-w0.fn"}) tr.add_column(c);
  tr.append_row({0.0, 0, 0, 0.012, 0, 0, -2.0, -0.002, 0});
  tr.append_row({1.0, 0, 0, 0.009, 0, 0, -1.0, 0.001, 1});
  tr.append_row({2.0, 0, 0, 0.009, 0, 0, 1.0, 0.001, 1});
  tr.append_row({3.0, 0, 0, 0.012, 0, 0, 1.5, -0.002, 0});
  const auto m = comparison::compute_metrics(s, test_support::ok_run("inhouse", tr), nullptr);
  EXPECT_NEAR(*m.at("restitution").value, 0.75, 1e-15);
  EXPECT_NEAR(*m.at("contact_duration").value, (3.0 - 2.0 / 3.0) - (2.0 / 3.0), 1e-12);
  // The collision axis points into the wall (−z): the deepest approach is 3 mm.
  EXPECT_NEAR(*m.at("max_position").value, 0.003, 1e-15);
}

}  // namespace
