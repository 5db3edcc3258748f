// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "cases/run_result.hpp"
#include "reference/yade/yade_engine.hpp"
#include "test_scratch.hpp"

// Helpers of the tests that run the real YADE (label `reference`).
namespace demwb_yade_test {

/// A canonical case file loaded from the source tree.
inline cases::Scene canonical(const char* file) {
  return cases::load_case(std::filesystem::path(DEMWB_SOURCE_DIR) / "cases/canonical" / file);
}

/// A fresh scratch directory for run `name` of the running test (under its name, see
/// current_test_folder).
inline std::filesystem::path scratch(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / "demwb-yade-tests" / demwb_engine_test::current_test_folder() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Skips the test when YADE is not installed here.
#define DEMWB_REQUIRE_YADE()                                                   \
  do {                                                                         \
    if (!reference::YadeEngine{}.version()) GTEST_SKIP() << "YADE not installed"; \
  } while (false)

/// Largest |a − b| / scale over one column of two traces with the same rows.
inline double max_scaled_difference(const std::vector<double>& a, const std::vector<double>& b,
                                    double scale) {
  double worst = 0.0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
    worst = std::max(worst, std::abs(a[k] - b[k]) / scale);
  }
  return worst;
}

/// Largest absolute value in a column.
inline double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (const double x : v) m = std::max(m, std::abs(x));
  return m;
}

/// The scale a trace column's differences are measured against: positions and overlaps
/// against the largest overlap, velocities against the impact speed, angular velocities
/// against impact speed / smallest radius, forces against the largest normal force, time
/// against the duration.
struct ColumnScales {
  double length;
  double speed;
  double angular_speed;
  double force;
  double time;

  /// Scale of the column named `name`.
  [[nodiscard]] double of(const std::string& name) const {
    const auto dot = name.rfind('.');
    const std::string q = dot == std::string::npos ? name : name.substr(dot + 1);
    if (q == "time") return time;
    if (q == "x" || q == "y" || q == "z" || q == "overlap") return length;
    if (q == "vx" || q == "vy" || q == "vz") return speed;
    if (q == "wx" || q == "wy" || q == "wz") return angular_speed;
    return force;  // fx fy fz fn
  }
};

/// Scales of a collision scene from the reference run `ref`.
inline ColumnScales collision_scales(const cases::Scene& scene, const cases::RunResult& ref) {
  ColumnScales s{0.0, 0.0, 0.0, 0.0, scene.integration.duration};
  double r_min = scene.particles.front().radius;
  for (const auto& p : scene.particles) {
    r_min = std::min(r_min, p.radius);
    s.speed = std::max(s.speed, std::hypot(p.velocity[0], p.velocity[1], p.velocity[2]));
  }
  for (const auto& name : ref.trace.columns()) {
    if (name.ends_with(".overlap")) s.length = std::max(s.length, max_abs(*ref.trace.column(name)));
    if (name.ends_with(".fn")) s.force = std::max(s.force, max_abs(*ref.trace.column(name)));
  }
  s.angular_speed = s.speed / r_min;
  return s;
}

/// Per column, the largest scaled difference between two runs with identical columns and rows.
inline std::vector<std::pair<std::string, double>> column_differences(const cases::RunResult& a,
                                                                      const cases::RunResult& b,
                                                                      const ColumnScales& scales) {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& name : a.trace.columns()) {
    out.emplace_back(name, max_scaled_difference(*a.trace.column(name), *b.trace.column(name),
                                                 scales.of(name)));
  }
  return out;
}

}  // namespace demwb_yade_test
