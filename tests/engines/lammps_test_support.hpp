// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <system_error>
#include <vector>

#include "cases/case_loader.hpp"
#include "cases/run_result.hpp"
#include "reference/common/engine.hpp"
#include "support/process.hpp"
#include "test_scratch.hpp"

// Helpers of the tests that run the real LAMMPS binary (ctest -L reference).
namespace demwb_lammps_test {

/// True when `lmp` is in PATH; tests skip otherwise.
inline bool lammps_installed() { return support::find_program("lmp").has_value(); }

/// A canonical case from the source tree, e.g. canonical("single_collision").
inline cases::Scene canonical(const std::string& name) {
  return cases::load_case(std::filesystem::path(DEMWB_SOURCE_DIR) / "cases" / "canonical" /
                          (name + ".toml"));
}

/// Run options with a scratch work directory per test and `run` (under the running test's name, see
/// current_test_folder), emptied first (the last run's files stay for inspection).
inline reference::RunOptions scratch(const std::string& run) {
  reference::RunOptions o;
  o.work_dir = std::filesystem::temp_directory_path() / "demwb-lammps-tests" /
               demwb_engine_test::current_test_folder() / run;
  std::error_code ignored;
  std::filesystem::remove_all(o.work_dir, ignored);
  o.timeout_s = 60.0;
  return o;
}

/// Largest |value| of a column.
inline double largest(const std::vector<double>& v) {
  double m = 0.0;
  for (const double x : v) m = std::max(m, std::abs(x));
  return m;
}

/// Scale a column's differences are measured against (the brief's "positions relative to max
/// overlap; velocities relative to impact speed"): time → the duration; positions and overlaps
/// → the largest overlap; velocities → the subject's initial speed; angular velocities → that
/// speed over its radius; forces → the largest pair force.
inline double column_scale(const std::string& column, const cases::Scene& scene,
                           const cases::Trace& reference_trace) {
  double overlap = 0.0;
  double force = 0.0;
  for (std::size_t c = 0; c < reference_trace.columns().size(); ++c) {
    const std::string& name = reference_trace.columns()[c];
    if (name.ends_with(".overlap")) overlap = std::max(overlap, largest(reference_trace.values(c)));
    if (name.ends_with(".fn")) force = std::max(force, largest(reference_trace.values(c)));
  }
  const cases::ParticleSpec& subject = scene.particles.at(scene.compare.subject.value_or(0));
  const double speed = std::sqrt(subject.velocity[0] * subject.velocity[0] +
                                 subject.velocity[1] * subject.velocity[1] +
                                 subject.velocity[2] * subject.velocity[2]);
  const std::string q = column.substr(column.find('.') + 1);
  if (column == "time") return scene.integration.duration;
  if (q == "x" || q == "y" || q == "z" || q == "overlap") return overlap;
  if (q == "vx" || q == "vy" || q == "vz") return speed;
  if (q == "wx" || q == "wy" || q == "wz") return speed / subject.radius;
  return force;  // fx, fy, fz, fn
}

/// Per column: the largest |a − b| over all rows divided by column_scale (b is the reference).
inline std::map<std::string, double> scaled_differences(const cases::Scene& scene,
                                                        const cases::Trace& a,
                                                        const cases::Trace& b) {
  std::map<std::string, double> out;
  for (std::size_t c = 0; c < b.columns().size(); ++c) {
    const std::string& name = b.columns()[c];
    const std::vector<double>* va = a.column(name);
    if (va == nullptr || va->size() != b.values(c).size()) {
      out[name] = INFINITY;
      continue;
    }
    double worst = 0.0;
    for (std::size_t r = 0; r < va->size(); ++r) {
      worst = std::max(worst, std::abs((*va)[r] - b.values(c)[r]));
    }
    out[name] = worst / column_scale(name, scene, b);
  }
  return out;
}

}  // namespace demwb_lammps_test
