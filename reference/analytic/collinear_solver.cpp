// SPDX-License-Identifier: MIT
#include "reference/analytic/collinear_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include <fmt/format.h>

#include "cases/time_step.hpp"
#include "reference/analytic/collinear_motion.hpp"
#include "reference/analytic/collinear_scene.hpp"
#include "reference/analytic/contact_episode.hpp"
#include "reference/analytic/scene_support.hpp"
#include "reference/common/core_setup.hpp"

namespace reference::analytic {
namespace {


/// Natural periods a first contact may last before the search gives up on it ending.
constexpr double kContactHorizonPeriods = 1e4;

/// Appends the exact state at time t as one trace row.
void record(const cases::Scene& scene, const CollinearScene& reduced, const AxisSample& sample,
            double t, cases::Trace& trace) {
  const cases::Snapshot snap = analytic::snapshot_at(scene, reduced, sample, t);
  const std::vector<cases::Vector3> force = analytic::forces_at(scene, reduced, sample);
  std::vector<double> row;
  row.reserve(trace.columns().size());
  row.push_back(t);
  for (const std::size_t i : scene.output.trace_particles) {
    for (const auto* field : {&snap.position.at(i), &snap.velocity.at(i),
                              &snap.angular_velocity.at(i), &force.at(i)}) {
      row.insert(row.end(), field->begin(), field->end());
    }
  }
  for (const auto& [p, q] : scene.output.trace_pairs) {
    if (const auto k = analytic::partner_of_pair(reduced, p, q)) {
      row.push_back(sample.overlap[*k]);
      row.push_back(sample.normal_force[*k]);
    } else {
      // Not a tracked contact (two fixed spheres): apart or not, the core exerts no force.
      const cases::Vector3& xp = snap.position.at(p);
      const cases::Vector3& xq = snap.position.at(q);
      const double distance = std::hypot(xp[0] - xq[0], xp[1] - xq[1], xp[2] - xq[2]);
      row.push_back(scene.particles.at(p).radius + scene.particles.at(q).radius - distance);
      row.push_back(0.0);
    }
  }
  trace.append_row(row);
}

}  // namespace

namespace {

/// Longest natural period 2π √(m/k) of any single contact, the time scale of the contacts.
double longest_period(const analytic::AxisProblem& problem) {
  double longest = 0.0;
  for (const auto& p : problem.partners) {
    longest = std::max(longest, analytic::LinearOscillator(problem.mass, 0.0, p.stiffness, 0.0, 0.0)
                                    .natural_period());
  }
  return longest;
}

/// Exact figures of the first contact of the compared pair, with what they mean.
void add_exact_metrics(const cases::Scene& scene, const CollinearScene& reduced, double t_end,
                       cases::RunResult& result) {
  if (!scene.compare.pair) return;
  const auto [p, q] = *scene.compare.pair;
  const auto partner = analytic::partner_of_pair(reduced, p, q);
  if (!partner) {
    result.warnings.push_back(fmt::format(
        "compare.pair ({}, {}) is not a contact of the mobile sphere(s); no exact metrics", p, q));
    return;
  }
  const double horizon = kContactHorizonPeriods * longest_period(reduced.problem);
  const auto episode = analytic::first_contact(reduced.problem, *partner, t_end, horizon);
  if (!episode) {
    result.warnings.push_back(fmt::format(
        "compare.pair ({}, {}): no contact starts by the end of the run (t = {:.6g} s), or it "
        "never ends; no exact metrics",
        p, q, t_end));
    return;
  }
  const analytic::ContactFigures f = analytic::contact_figures(reduced.problem, *episode);
  result.exact_metrics["contact_duration"] = f.duration;
  if (f.restitution) result.exact_metrics["restitution"] = *f.restitution;
  result.exact_metrics["max_overlap"] = f.max_overlap;
  result.exact_metrics["max_force"] = f.max_force;
  result.conventions["exact metrics"] =
      f.closed_form
          ? fmt::format("first contact of pair ({}, {}) at t = {:.9g} s, single spring: closed "
                        "forms of m* δ'' + η δ' + k δ = 0 (eq 3.10–3.11, 3.40); peak force by "
                        "Brent's method",
                        p, q, episode->start)
          : fmt::format("first contact of pair ({}, {}) at t = {:.9g} s, other contacts act "
                        "meanwhile: measured on the exact piecewise solution",
                        p, q, episode->start);
}

/// The conventions of an analytic run, for reports.
std::map<std::string, std::string> conventions(const CollinearScene& reduced, double dt,
                                               std::uint64_t every) {
  std::map<std::string, std::string> c;
  c["solution"] = "exact piecewise closed form, events located to double precision (TOMS 748)";
  c["sampling"] = fmt::format(
      "same time points as the in-house core: t_k = k·{}·Δt with Δt = {:.6g} s", every, dt);
  c["geometry"] =
      reduced.two_mobile
          ? fmt::format("two mobile spheres head-on: separation with m* = {:.6g} kg, uniform "
                        "centre-of-mass motion",
                        reduced.problem.mass)
          : fmt::format("one mobile sphere (m = {:.6g} kg) among {} fixed spheres on its line "
                        "of motion",
                        reduced.problem.mass, reduced.problem.partners.size());
  c["contact onset"] = "a pair interacts while its overlap δ > 0 (strictly)";
  c["normal force"] =
      "k δ − η (u_c·n) with η = β(ε) √(m* k) (eq 3.10–3.11), not clamped at zero";
  c["trace velocity"] = "exact velocity at the sample time";
  c["fixed sphere force"] = "minus the contact force it exerts";
  return c;
}

}  // namespace

std::vector<std::string> CollinearSolver::unsupported_reasons(const PreparedScene& prepared) const {
  return analytic::unsupported_reasons(prepared);
}

cases::RunResult CollinearSolver::run(const PreparedScene& prepared) const {
  const cases::Scene& scene = prepared.scene();
  const CollinearScene reduced = analytic::reduce_scene(prepared);
  const auto [dt, steps, every, t_end] = sample_grid(prepared);
  const analytic::AxisSolution solution(reduced.problem, 0.0, t_end);

  cases::RunResult result;
  result.status = cases::RunStatus::ok;
  result.trace = cases::trace_layout(scene);
  for (std::uint64_t n = 0; n <= steps; n += every) {
    const double t = static_cast<double>(n) * dt;
    record(scene, reduced, solution.at(t), t, result.trace);
  }
  for (const std::uint64_t n : cases::snapshot_steps(scene.output.snapshot_times, dt, steps)) {
    const double t = static_cast<double>(n) * dt;
    result.snapshots.push_back(analytic::snapshot_at(scene, reduced, solution.at(t), t));
  }
  result.conventions = conventions(reduced, dt, every);
  add_exact_metrics(scene, reduced, t_end, result);
  return result;
}

std::vector<cases::Snapshot> collinear_exact_states(const PreparedScene& prepared,
                                                    const std::vector<double>& times) {
  const cases::Scene& scene = prepared.scene();
  const CollinearScene reduced = analytic::reduce_scene(prepared);
  double t_min = 0.0;
  double t_max = 0.0;
  for (const double t : times) {
    if (!std::isfinite(t)) throw std::invalid_argument("analytic: exact_states needs finite times");
    t_min = std::min(t_min, t);
    t_max = std::max(t_max, t);
  }
  const analytic::AxisSolution solution(reduced.problem, t_min, t_max);
  std::vector<cases::Snapshot> out;
  out.reserve(times.size());
  for (const double t : times) out.push_back(analytic::snapshot_at(scene, reduced, solution.at(t), t));
  return out;
}

}  // namespace reference::analytic
