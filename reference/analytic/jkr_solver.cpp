// SPDX-License-Identifier: MIT
#include "reference/analytic/jkr_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <optional>
#include <variant>

#include <fmt/format.h>

#include "cases/time_step.hpp"
#include "dem/contact/laws/jkr.hpp"
#include "dem/contact/pair_table.hpp"
#include "reference/analytic/collinear_solver.hpp"
#include "reference/analytic/vector3_math.hpp"
#include "reference/common/core_setup.hpp"
#include "reference/analytic/model_support.hpp"

namespace reference::analytic {
namespace {

/// What the JKR pull-off rig solves: Hertz–JKR, quasi-static (no dashpot), frictionless, either
/// rupture rule.
const ModelSupport kJkrModel{"JKR pull-off rig", {"hertz"}, {"none"}, {"none"}, {"jkr"}, {"none"}, true};

using cases::Vector3;


/// Position of a particle at time t: at rest, or on its piecewise-constant-velocity motion.
Vector3 position_at(const cases::ParticleSpec& p, double t) {
  Vector3 x = p.position;
  double begin = 0.0;
  for (std::size_t k = 0; k < p.motion.size(); ++k) {
    const bool last = k + 1 == p.motion.size();
    const double span = last ? t - begin : std::clamp(t - begin, 0.0, p.motion[k].duration);
    for (std::size_t c = 0; c < 3; ++c) x[c] += span * p.motion[k].velocity[c];
    if (last || t < begin + p.motion[k].duration) break;
    begin += p.motion[k].duration;
  }
  return x;
}

/// Velocity of a particle at time t.
Vector3 velocity_at(const cases::ParticleSpec& p, double t) {
  if (p.motion.empty()) return {0.0, 0.0, 0.0};
  double end = 0.0;
  for (std::size_t k = 0; k + 1 < p.motion.size(); ++k) {
    end += p.motion[k].duration;
    if (t < end) return p.motion[k].velocity;
  }
  return p.motion.back().velocity;
}

/// Start times of the motion segments of both particles after t = 0, sorted.
std::vector<double> breakpoints(const cases::Scene& scene) {
  std::vector<double> out;
  for (const auto& p : scene.particles) {
    double t = 0.0;
    for (std::size_t k = 0; k + 1 < p.motion.size(); ++k) {
      t += p.motion[k].duration;
      out.push_back(t);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// The rig reduced to one overlap δ(t), piecewise linear, and the JKR constants.
struct Rig {
  const cases::Scene* scene;
  dem::laws::JkrParameters jkr;
  dem::JkrRupture policy;
  double contact_distance;  ///< r_0 + r_1 [m]

  [[nodiscard]] double distance(double t) const {
    return norm(minus(position_at(scene->particles[0], t), position_at(scene->particles[1], t)));
  }
  [[nodiscard]] double overlap(double t) const { return contact_distance - distance(t); }
  [[nodiscard]] double break_overlap() const {
    return policy == dem::JkrRupture::load ? dem::laws::jkr_pulloff_overlap(jkr)
                                           : dem::laws::jkr_rupture_overlap(jkr);
  }
  /// Contact radius at the break, in closed form: a_c (displacement control) or a_f = 9^{1/3} a_c
  /// (load control). Not a(δ_break) solved numerically: δ_c is a fold of δ(a), where a solve
  /// amplifies the rounding of δ to its square root (~1e-8).
  [[nodiscard]] double break_radius() const {
    return policy == dem::JkrRupture::load ? dem::laws::jkr_pulloff_radius(jkr)
                                           : dem::laws::jkr_critical_radius(jkr);
  }
  /// Attached after a monotone stretch that ends at overlap δ, starting `attached`.
  [[nodiscard]] bool attached_after(bool attached, double delta) const {
    if (delta >= 0.0) return true;
    if (!attached) return false;
    return policy == dem::JkrRupture::load ? delta > break_overlap() : delta >= break_overlap();
  }
  [[nodiscard]] double force(double delta) const {
    return dem::laws::jkr_force(dem::laws::jkr_contact_radius(delta, jkr), jkr);
  }
};

Rig make_rig(const PreparedScene& prepared) {
  const cases::Scene& scene = prepared.scene();
  const dem::PairTable& table = prepared.pair_table();
  const auto& a = scene.particles[0];
  const auto& b = scene.particles[1];
  const dem::PairLaw& law = table.law(a.material, b.material);
  const auto& jkr = std::get<dem::JkrCohesion>(law.cohesion);
  const double reduced = a.radius * b.radius / (a.radius + b.radius);
  return Rig{&scene, jkr.parameters(reduced), scene.model.jkr_rupture, a.radius + b.radius};
}

/// The hysteresis state along the run: attached or not at the start of every monotone piece.
class History {
 public:
  History(const Rig& rig, double t_end) : rig_(rig) {
    times_.push_back(0.0);
    for (const double t : breakpoints(*rig.scene)) {
      if (t > 0.0 && t < t_end) times_.push_back(t);
    }
    times_.push_back(t_end);
    bool attached = rig.overlap(0.0) >= 0.0;
    for (std::size_t k = 0; k + 1 < times_.size(); ++k) {
      start_state_.push_back(attached);
      attached = rig.attached_after(attached, rig.overlap(times_[k + 1]));
    }
  }
  /// Attached at time t (the JKR hysteresis rule of docs/physics-cohesion.md applied to the exact,
  /// piecewise-monotone δ).
  [[nodiscard]] bool attached(double t) const {
    const auto it = std::upper_bound(times_.begin(), times_.end() - 1, t);
    const std::size_t piece = it == times_.begin() ? 0 : static_cast<std::size_t>(it - times_.begin()) - 1;
    const std::size_t k = std::min(piece, start_state_.size() - 1);
    return rig_.attached_after(start_state_[k], rig_.overlap(t));
  }
  /// Piece boundaries, from 0 to the end of the run.
  [[nodiscard]] const std::vector<double>& times() const noexcept { return times_; }
  /// Attached at the start of piece k.
  [[nodiscard]] bool start_state(std::size_t k) const { return start_state_[k]; }

 private:
  const Rig& rig_;
  std::vector<double> times_;
  std::vector<bool> start_state_;
};

/// Exact figures of the force–separation curve over the run.
struct Figures {
  std::optional<double> pulloff_force;  ///< largest tension on the attached curve
  std::optional<double> rupture_overlap;
  std::optional<double> rupture_force;
  std::optional<double> separation_work;
};

Figures exact_figures(const Rig& rig, const History& history) {
  Figures f;
  const double delta_f = dem::laws::jkr_pulloff_overlap(rig.jkr);
  const double delta_break = rig.break_overlap();
  double deepest = -std::numeric_limits<double>::infinity();  // of the current attached stretch
  const auto& times = history.times();
  for (std::size_t k = 0; k + 1 < times.size(); ++k) {
    const double d0 = rig.overlap(times[k]);
    const double d1 = rig.overlap(times[k + 1]);
    bool attached = history.start_state(k);
    double lo = 0.0, hi = 0.0;  // δ range covered while attached in this piece
    bool covered = false;
    if (!attached && d1 >= 0.0) {  // forms at δ = 0 on the way in (or at t = 0)
      attached = true;
      deepest = std::max(0.0, d0);
      lo = std::max(0.0, d0);
      hi = d1;
      covered = true;
    } else if (attached) {
      const bool breaks = !rig.attached_after(true, d1);
      lo = breaks ? delta_break : std::min(d0, d1);
      hi = std::max(d0, d1);
      covered = true;
      if (breaks) {
        deepest = std::max(deepest, d0);
        f.rupture_overlap = delta_break;
        f.rupture_force = dem::laws::jkr_force(rig.break_radius(), rig.jkr);
        f.separation_work = dem::laws::jkr_energy(dem::laws::jkr_contact_radius(deepest, rig.jkr), rig.jkr) -
                            dem::laws::jkr_energy(rig.break_radius(), rig.jkr);
      }
    }
    if (covered) {
      deepest = std::max({deepest, lo, hi});
      const double tension = -rig.force(std::clamp(delta_f, lo, hi));
      if (tension > 0.0 && (!f.pulloff_force || tension > *f.pulloff_force)) f.pulloff_force = tension;
    }
    if (!rig.attached_after(attached, d1)) deepest = -std::numeric_limits<double>::infinity();
  }
  return f;
}

/// Appends the exact state at time t as one trace row.
void record(const Rig& rig, const History& history, double t, cases::Trace& trace) {
  const cases::Scene& scene = *rig.scene;
  const double delta = rig.overlap(t);
  const double fn = history.attached(t) ? rig.force(delta) : 0.0;
  const Vector3 x0 = position_at(scene.particles[0], t);
  const Vector3 x1 = position_at(scene.particles[1], t);
  const Vector3 x01 = minus(x0, x1);
  const Vector3 n = scaled(x01, 1.0 / norm(x01));
  std::vector<double> row;
  row.reserve(trace.columns().size());
  row.push_back(t);
  for (const std::size_t i : scene.output.trace_particles) {
    const auto& p = scene.particles[i];
    const Vector3 x = i == 0 ? x0 : x1;
    const Vector3 v = velocity_at(p, t);
    const Vector3 force = scaled(n, i == 0 ? fn : -fn);  // force on 0 is F n, n from 1 to 0
    row.insert(row.end(), x.begin(), x.end());
    row.insert(row.end(), v.begin(), v.end());
    row.insert(row.end(), {0.0, 0.0, 0.0});
    row.insert(row.end(), force.begin(), force.end());
  }
  for (std::size_t k = 0; k < scene.output.trace_pairs.size(); ++k) {
    row.push_back(delta);
    row.push_back(fn);
  }
  trace.append_row(row);
}

/// The conventions of a run, for reports.
std::map<std::string, std::string> conventions(const Rig& rig, double dt, std::uint64_t every) {
  const auto& p = rig.jkr;
  std::map<std::string, std::string> c;
  c["solution"] = "exact JKR curve: a(δ) by TOMS 748 on the stable branch a ≥ a_c, F(a) eq 3.34";
  c["sampling"] = fmt::format(
      "same time points as the in-house core: t_k = k·{}·Δt with Δt = {:.6g} s", every, dt);
  c["geometry"] = fmt::format(
      "displacement control, no inertia: E* = {:.6g} Pa, R* = {:.6g} m, γ = {:.6g} J/m² "
      "(per surface)",
      p.effective_modulus, p.reduced_radius, p.surface_energy);
  c["hysteresis"] = fmt::format(
      "forms when δ reaches 0 (F = −8/9 F_po), breaks at {} = {:.9g} m",
      rig.policy == dem::JkrRupture::load ? "δ_f (load-controlled pull-off)"
                                          : "δ_c (displacement-controlled rupture)",
      rig.break_overlap());
  c["closed forms"] = fmt::format(
      "F_po = 3πγR* = {:.9g} N, δ_c = {:.9g} m, δ_f = {:.9g} m, a_c = {:.6g} m, a_0 = {:.6g} m",
      dem::laws::jkr_pulloff_force(p), dem::laws::jkr_rupture_overlap(p),
      dem::laws::jkr_pulloff_overlap(p), dem::laws::jkr_critical_radius(p),
      dem::laws::jkr_zero_load_radius(p));
  c["separation work"] = "U(a(δ_max)) − U(a_rupture), U the JKR energy (elastic + surface, "
                         "zero for separated surfaces)";
  return c;
}


/// Reasons against the layout: two fixed spheres, one moving along the line of centres.
void check_jkr_layout(const cases::Scene& scene, std::vector<std::string>& reasons) {
  if (scene.particles.size() != 2) {
    reasons.push_back(fmt::format("analytic (JKR pull-off rig): needs exactly 2 particles, got {}",
                                  scene.particles.size()));
    return;
  }
  if (!scene.walls.empty()) reasons.push_back("analytic (JKR pull-off rig): walls are not part of the rig");
  for (std::size_t i = 0; i < 2; ++i) {
    if (!scene.particles[i].fixed) {
      reasons.push_back(fmt::format(
          "analytic (JKR pull-off rig): particle {} is mobile; the rig is displacement-controlled "
          "(both spheres fixed, one with a prescribed motion)",
          i));
    }
    if (scene.particles[i].material >= scene.materials.size()) {
      reasons.push_back(fmt::format("analytic (JKR pull-off rig): particle {} names no material", i));
    }
  }
  const Vector3 x01 = minus(scene.particles[0].position, scene.particles[1].position);
  const double d = norm(x01);
  if (!(d > 0.0)) {
    reasons.push_back("analytic (JKR pull-off rig): the two centres coincide");
    return;
  }
  const Vector3 axis = scaled(x01, 1.0 / d);
  bool moves = false;
  for (std::size_t i = 0; i < 2; ++i) {
    for (const auto& seg : scene.particles[i].motion) {
      moves = moves || norm(seg.velocity) > 0.0;
      if (off_line(seg.velocity, axis) > kCollinearTolerance * norm(seg.velocity)) {
        reasons.push_back(fmt::format(
            "analytic (JKR pull-off rig): the motion of particle {} leaves the line of centres",
            i));
      }
    }
  }
  if (!moves) reasons.push_back("analytic (JKR pull-off rig): no particle has a prescribed motion");
}

}  // namespace

std::vector<std::string> JkrPulloffSolver::unsupported_reasons(const PreparedScene& prepared) const {
  const cases::Scene& scene = prepared.scene();
  std::vector<std::string> reasons;
  for (std::string& r : model_reasons(scene.model, kJkrModel)) reasons.push_back(std::move(r));
  if (!reasons.empty()) return reasons;
  check_jkr_layout(scene, reasons);
  if (!reasons.empty()) return reasons;
  try {
    const Rig rig = make_rig(prepared);
    const double t_end = sample_grid(prepared).t_end;
    for (const double t : breakpoints(scene)) {
      if (!(rig.distance(std::min(t, t_end)) > 0.0)) {
        reasons.push_back("analytic (JKR pull-off rig): the centres meet during the motion");
      }
    }
    if (!(rig.distance(t_end) > 0.0)) {
      reasons.push_back("analytic (JKR pull-off rig): the centres meet during the motion");
    }
  } catch (const std::exception& e) {
    reasons.push_back(std::string("analytic (JKR pull-off rig): ") + e.what());
  }
  return reasons;
}

cases::RunResult JkrPulloffSolver::run(const PreparedScene& prepared) const {
  const cases::Scene& scene = prepared.scene();
  const Rig rig = make_rig(prepared);
  const auto [dt, steps, every, t_end] = sample_grid(prepared);
  const History history(rig, t_end);

  cases::RunResult result;
  result.status = cases::RunStatus::ok;
  result.trace = cases::trace_layout(scene);
  for (std::uint64_t n = 0; n <= steps; n += every) {
    record(rig, history, static_cast<double>(n) * dt, result.trace);
  }
  for (const std::uint64_t n : cases::snapshot_steps(scene.output.snapshot_times, dt, steps)) {
    const double t = static_cast<double>(n) * dt;
    cases::Snapshot snap;
    snap.time = t;
    for (const auto& p : scene.particles) {
      snap.position.push_back(position_at(p, t));
      snap.velocity.push_back(velocity_at(p, t));
      snap.angular_velocity.push_back({0.0, 0.0, 0.0});
    }
    result.snapshots.push_back(std::move(snap));
  }
  result.conventions = conventions(rig, dt, every);
  const Figures f = exact_figures(rig, history);
  if (f.pulloff_force) result.exact_metrics["pulloff_force"] = *f.pulloff_force;
  if (f.rupture_overlap) {
    result.exact_metrics["rupture_separation"] = -*f.rupture_overlap;
    result.exact_metrics["force_at_rupture"] = *f.rupture_force;
    result.exact_metrics["separation_work"] = *f.separation_work;
  } else {
    result.warnings.push_back(fmt::format(
        "the JKR contact does not break by the end of the run (t = {:.6g} s); no exact rupture "
        "metrics",
        t_end));
  }
  if (f.pulloff_force && std::abs(*f.pulloff_force - dem::laws::jkr_pulloff_force(rig.jkr)) >
                             1e-12 * dem::laws::jkr_pulloff_force(rig.jkr)) {
    result.warnings.push_back(
        "the displacement-controlled curve does not pass the load-controlled pull-off point "
        "δ_f while attached: the largest tension differs from 3πγR*");
  }
  return result;
}

}  // namespace reference::analytic
