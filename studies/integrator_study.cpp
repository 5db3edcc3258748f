// SPDX-License-Identifier: MIT
#include "studies/integrator_study.hpp"

#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "cases/case_library.hpp"
#include "cases/case_loader.hpp"
#include "compare/metrics.hpp"
#include "reference/common/engine.hpp"
#include "reference/registry.hpp"

namespace studies {
namespace {

/// Logarithmically spaced values from a to b inclusive.
std::vector<double> log_space(double a, double b, std::size_t n) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = a * std::pow(b / a, static_cast<double>(i) / static_cast<double>(n - 1));
  }
  return v;
}

/// The two canonical scenes the study varies.
struct BaseScenes {
  cases::Scene collision;
  cases::Scene sandwich;
};

/// Subject index and its partner in the compared pair of a base scene.
std::pair<std::size_t, std::size_t> subject_and_partner(const cases::Scene& s) {
  if (!s.compare.subject || !s.compare.pair) {
    throw std::runtime_error(s.source_path + ": the study needs compare.subject and compare.pair");
  }
  const auto [p, q] = *s.compare.pair;
  const std::size_t subject = *s.compare.subject;
  return {subject, p == subject ? q : p};
}

/// Contact duration π√(m/k) of the subject against a fixed partner (undamped linear law).
double collision_time(const cases::Scene& s, double stiffness) {
  const auto& p = s.particles[subject_and_partner(s).first];
  const double m = 4.0 / 3.0 * std::numbers::pi * s.materials[p.material].density * std::pow(p.radius, 3);
  return std::numbers::pi * std::sqrt(m / stiffness);
}

/// Common settings of every study run: scheme, Δt, exact start-up, stiffness, one trace row
/// per step, only the amplitude error.
cases::Scene configured(const cases::Scene& base, dem::SchemeId scheme, double dt, double stiffness) {
  cases::Scene s = base;
  s.source_path = base.source_path + " (varied by the integrator study)";
  s.integration.scheme = scheme;
  s.integration.timestep = dt;
  s.integration.startup = dem::StartupPolicy::exact;
  s.integration.rotation = false;
  for (auto& m : s.materials) m.normal_stiffness = stiffness;
  s.output.trace_every = 1;
  s.output.snapshot_times.clear();
  s.output.trace_particles = {subject_and_partner(s).first};
  s.output.trace_pairs = {*s.compare.pair};
  s.compare.metrics = {"amplitude_error"};
  s.compare.engines = {"inhouse", "analytic"};
  s.compare.reference = "analytic";
  return s;
}

/// Single collision with N_FM steps of free motion before contact (docs/integrator-study.md): the
/// partner is placed at x_q = x_p + |u| N_FM Δt + r_p + r_q along the velocity, and the run
/// lasts until the subject is back at its start.
cases::Scene collision_scene(const cases::Scene& base, dem::SchemeId scheme, double dt, double nfm,
                             double stiffness, double speed) {
  cases::Scene s = configured(base, scheme, dt, stiffness);
  const auto [ip, iq] = subject_and_partner(s);
  auto& p = s.particles[ip];
  auto& q = s.particles[iq];
  p.velocity = {speed, 0.0, 0.0};
  q.position = {p.position[0] + speed * nfm * dt + p.radius + q.radius, p.position[1], p.position[2]};
  s.integration.duration = 2.0 * nfm * dt + 1.02 * collision_time(s, stiffness);
  return s;
}

/// Sandwich (fig 4.15): one full oscillation between the two touching fixed neighbours.
cases::Scene sandwich_scene(const cases::Scene& base, dem::SchemeId scheme, double dt,
                            double stiffness, double speed) {
  cases::Scene s = configured(base, scheme, dt, stiffness);
  s.particles[subject_and_partner(s).first].velocity = {speed, 0.0, 0.0};
  s.integration.duration = 2.0 * collision_time(s, stiffness);
  return s;
}

/// Runs a scene on the core and the analytic engine and measures εx_amp.
ErrorPoint measure(double x, const cases::Scene& scene) {
  const auto inhouse = reference::make_engine("inhouse");
  const auto analytic = reference::make_engine("analytic");
  const reference::RunOptions options{};
  const cases::RunResult exact = reference::run_engine(*analytic, scene, options);
  const cases::RunResult numeric = reference::run_engine(*inhouse, scene, options);
  const comparison::MetricSet m = comparison::compute_metrics(scene, numeric, &exact);
  const comparison::MetricValue& v = m.at("amplitude_error");
  ErrorPoint point{x, v.value, v.problem};
  if (!v.value) {
    point.problem = fmt::format("{}; inhouse: {} {}; analytic: {} {}", v.problem,
                                cases::to_string(numeric.status), numeric.reason,
                                cases::to_string(exact.status), exact.reason);
  }
  return point;
}

/// Runs every job, `threads` at a time; results keep the jobs' order (deterministic).
std::vector<ErrorPoint> run_all(const std::vector<std::function<ErrorPoint()>>& jobs, unsigned threads) {
  std::vector<ErrorPoint> out(jobs.size());
  std::atomic<std::size_t> next{0};
  const auto worker = [&] {
    for (std::size_t i = next++; i < jobs.size(); i = next++) out[i] = jobs[i]();
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  return out;
}

/// Least-squares slope of log ε against log x over the points above the floor, with its
/// standard error (large when the errors scatter instead of following a power law).
void fit(SchemeSweep& s, double floor) {
  std::vector<std::pair<double, double>> xy;
  for (const auto& p : s.points) {
    if (!p.amplitude_error || !(*p.amplitude_error > floor) || !(p.x > 0.0)) continue;
    xy.emplace_back(std::log(p.x), std::log(*p.amplitude_error));
  }
  s.fitted_points = xy.size();
  if (xy.size() < 2) return;
  const double n = static_cast<double>(xy.size());
  double mx = 0, my = 0;
  for (const auto& [x, y] : xy) { mx += x / n; my += y / n; }
  double sxx = 0, sxy = 0;
  for (const auto& [x, y] : xy) { sxx += (x - mx) * (x - mx); sxy += (x - mx) * (y - my); }
  if (!(sxx > 0.0)) return;
  const double slope = sxy / sxx;
  double residual = 0;
  for (const auto& [x, y] : xy) residual += std::pow(y - my - slope * (x - mx), 2);
  s.slope = slope;
  s.slope_error = xy.size() > 2 ? std::sqrt(residual / (n - 2.0) / sxx) : 0.0;
}

/// A planned sweep: for each scheme and each x, the scene to run.
struct SweepPlan {
  Sweep sweep;
  std::vector<double> xs;
  std::function<cases::Scene(dem::SchemeId, double)> scene_at;
};

}  // namespace

IntegratorStudyOptions default_options() {
  IntegratorStudyOptions o;
  o.timesteps = log_space(5e-7, 5e-5, 13);
  o.stiffnesses = log_space(1e1, 1e5, 9);
  o.velocities = log_space(0.1, 100.0, 7);
  for (int i = 0; i <= 40; ++i) o.nfm_values.push_back(0.05 * i);
  return o;
}

IntegratorStudy run_integrator_study(const IntegratorStudyOptions& given) {
  IntegratorStudy study;
  study.options = given;
  IntegratorStudyOptions& o = study.options;
  const IntegratorStudyOptions d = default_options();
  if (o.timesteps.empty()) o.timesteps = d.timesteps;
  if (o.stiffnesses.empty()) o.stiffnesses = d.stiffnesses;
  if (o.velocities.empty()) o.velocities = d.velocities;
  if (o.nfm_values.empty()) o.nfm_values = d.nfm_values;
  if (o.threads == 0) o.threads = std::max(1U, std::thread::hardware_concurrency());

  const BaseScenes base{cases::load_case(cases::suite_case(o.suite, "single_collision")),
                        cases::load_case(cases::suite_case(o.suite, "sandwich"))};
  const double k0 = *base.collision.materials.front().normal_stiffness;
  const double u0 = base.collision.particles[subject_and_partner(base.collision).first].velocity[0];
  const double dt0 = o.base_timestep;

  std::vector<SweepPlan> plans;
  for (const auto& [key, nfm] : {std::pair{"nfm_10", 10.0}, std::pair{"nfm_10_5", 10.5}}) {
    const std::string label = nfm == 10.0 ? "N_FM = 10" : "N_FM = 10.5";
    plans.push_back({{std::string("dt_") + key, "Amplitude error against time step, " + label, "time step Δt (s)", {}},
                     o.timesteps,
                     [&, nfm](dem::SchemeId s, double dt) { return collision_scene(base.collision, s, dt, nfm, k0, u0); }});
    plans.push_back({{std::string("k_") + key, "Amplitude error against contact stiffness, " + label, "stiffness k_e (N/m)", {}},
                     o.stiffnesses,
                     [&, nfm](dem::SchemeId s, double k) { return collision_scene(base.collision, s, dt0, nfm, k, u0); }});
    plans.push_back({{std::string("u_") + key, "Amplitude error against collision velocity, " + label, "velocity |u| (m/s)", {}},
                     o.velocities,
                     [&, nfm](dem::SchemeId s, double u) { return collision_scene(base.collision, s, dt0, nfm, k0, u); }});
  }
  plans.push_back({{"dt_sandwich", "Amplitude error against time step, sandwich (no free motion)", "time step Δt (s)", {}},
                   o.timesteps,
                   [&](dem::SchemeId s, double dt) { return sandwich_scene(base.sandwich, s, dt, k0, u0); }});
  plans.push_back({{"nfm", "Amplitude error against steps of free motion before contact", "N_FM", {}},
                   o.nfm_values,
                   [&](dem::SchemeId s, double nfm) { return collision_scene(base.collision, s, dt0, nfm, k0, u0); }});

  std::vector<std::function<ErrorPoint()>> jobs;
  for (const auto& plan : plans) {
    for (const dem::SchemeId scheme : dem::thesis_schemes()) {
      for (const double x : plan.xs) {
        jobs.emplace_back([&plan, scheme, x] { return measure(x, plan.scene_at(scheme, x)); });
      }
    }
  }
  // Practical comparison at N_FM = 10.5: RK2 at 20 steps per collision, AB2/BD2 at 40.
  const double tc = collision_time(base.collision, k0);
  const std::array<std::pair<dem::SchemeId, double>, 3> practical{
      {{dem::SchemeId::rk2, 20.0}, {dem::SchemeId::ab2, 40.0}, {dem::SchemeId::bd2, 40.0}}};
  for (const auto& [scheme, steps] : practical) {
    jobs.emplace_back([&, scheme = scheme, steps = steps] {
      return measure(steps, collision_scene(base.collision, scheme, tc / steps, 10.5, k0, u0));
    });
  }

  const std::vector<ErrorPoint> results = run_all(jobs, o.threads);
  std::size_t r = 0;
  for (auto& plan : plans) {
    for (const dem::SchemeId scheme : dem::thesis_schemes()) {
      SchemeSweep s{scheme, {}, std::nullopt, 0.0, 0};
      for (std::size_t i = 0; i < plan.xs.size(); ++i) {
        s.points.push_back(results[r++]);
        if (!s.points.back().amplitude_error) {
          study.problems.push_back(fmt::format("{} {} at {:.6g}: {}", plan.sweep.key,
                                               dem::scheme_info(scheme).keyword, s.points.back().x,
                                               s.points.back().problem));
        }
      }
      if (plan.sweep.key != "nfm") fit(s, o.fit_floor);
      plan.sweep.schemes.push_back(std::move(s));
    }
    study.sweeps.push_back(std::move(plan.sweep));
  }
  const ErrorPoint& rk2 = results[r];
  const ErrorPoint& ab2 = results[r + 1];
  const ErrorPoint& bd2 = results[r + 2];
  if (rk2.amplitude_error && ab2.amplitude_error && bd2.amplitude_error) {
    study.resolution = ResolutionComparison{*rk2.amplitude_error, *ab2.amplitude_error, *bd2.amplitude_error};
  } else {
    study.problems.push_back("practical resolution comparison failed: " + rk2.problem + ab2.problem + bd2.problem);
  }
  return study;
}

const Sweep* find_sweep(const IntegratorStudy& study, const std::string& key) {
  for (const auto& s : study.sweeps) {
    if (s.key == key) return &s;
  }
  return nullptr;
}

std::optional<double> fitted_order(const IntegratorStudy& study, const std::string& key,
                                   dem::SchemeId scheme) {
  const Sweep* sweep = find_sweep(study, key);
  if (sweep == nullptr) return std::nullopt;
  for (const auto& s : sweep->schemes) {
    if (s.scheme == scheme) return s.slope;
  }
  return std::nullopt;
}

}  // namespace studies
