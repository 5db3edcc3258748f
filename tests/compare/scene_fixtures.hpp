// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <numbers>

#include "cases/run_result.hpp"

namespace test_support {

/// Scene of a sphere (index 0, mobile) hitting a fixed sphere (index 1) along +x, with the
/// compared pair (0, 1) and the given metrics.
inline cases::Scene collision_scene(std::vector<std::string> metrics) {
  cases::Scene s;
  s.name = "synthetic";
  s.particles.resize(2);
  s.particles[0].radius = 0.01;
  s.particles[0].velocity = {4.0, 0.0, 0.0};
  s.particles[1].radius = 0.1;
  s.particles[1].position = {0.1102, 0.0, 0.0};
  s.particles[1].fixed = true;
  s.compare.engines = {"inhouse", "analytic"};
  s.compare.reference = "analytic";
  s.compare.subject = 0;
  s.compare.pair = cases::ParticlePair{0, 1};
  s.compare.metrics = std::move(metrics);
  return s;
}

/// Exact trace of collision_scene for a linear spring (ω = √(k/m)) sampled every dt:
/// free flight, a half sine of overlap, free flight back, with restitution e.
inline cases::Trace collision_trace(double dt, double e = 1.0, double time_shift = 0.0) {
  const double u = 4.0, gap = 0.1102 - 0.11, omega = 4886.025119, t0 = gap / u;
  const double tc = std::numbers::pi / omega;
  cases::Trace tr;
  tr.add_column("time");
  for (const char* q : {"x", "y", "z", "vx", "vy", "vz"}) tr.add_column(cases::particle_column(0, q));
  tr.add_column(cases::pair_column(0, 1, "overlap"));
  tr.add_column(cases::pair_column(0, 1, "fn"));
  for (int k = 0; k * dt < 2 * t0 + 1.5 * tc; ++k) {
    const double t = k * dt + time_shift;
    double x, v;
    if (t < t0) {
      x = u * t; v = u;
    } else if (t < t0 + tc) {
      const double s = t - t0;
      x = gap + u / omega * std::sin(omega * s);
      v = u * std::cos(omega * s);
    } else {
      x = gap - e * u * (t - t0 - tc);
      v = -e * u;
    }
    const double overlap = x - gap;
    tr.append_row({t, x, 0, 0, v, 0, 0, overlap, overlap > 0 ? 1e5 * overlap : 0.0});
  }
  return tr;
}

/// A successful run of `engine` with `trace`.
inline cases::RunResult ok_run(const std::string& engine, cases::Trace trace) {
  cases::RunResult r;
  r.engine = engine;
  r.status = cases::RunStatus::ok;
  r.trace = std::move(trace);
  return r;
}

}  // namespace test_support
