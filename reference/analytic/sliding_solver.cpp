// SPDX-License-Identifier: MIT
#include "reference/analytic/sliding_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <fmt/format.h>

#include "cases/time_step.hpp"
#include "dem/core/vector.hpp"
#include "reference/analytic/collinear_solver.hpp"
#include "reference/analytic/oblique_impact_solver.hpp"
#include "reference/analytic/vector3_math.hpp"
#include "reference/common/core_setup.hpp"

namespace reference::analytic {
namespace {

using dem::Vec3;


/// Relative tolerance of the resting-state checks (static overlap, velocity along the wall).
constexpr double kRestTolerance = 1e-9;

/// The sliding-then-rolling motion in closed form.
class SlidingMotion {
 public:
  SlidingMotion(const SphereWallScene& s, const Vec3& gravity)
      : s_(s), n_(core_vec(s.normal)), x0_(core_vec(s.position)), v0_(core_vec(s.velocity)), w0_(core_vec(s.spin)) {
    g_ = -gravity.dot(n_);
    overlap_ = s.radius - (x0_ - core_vec(s.wall_point)).dot(n_);
    lever_ = s.lever_is_radius ? s.radius : s.radius - 0.5 * overlap_;
    const Vec3 u0 = v0_ - lever_ * w0_.cross(n_);
    slip0_ = u0.norm();
    if (slip0_ > 0.0 && s.friction > 0.0) {
      direction_ = u0 / slip0_;
      deceleration_ = s.friction * g_;
      spin_rate_ = s.friction * s.mass * g_ * lever_ * s.inverse_inertia;
      slide_time_ = slip0_ / (deceleration_ + spin_rate_ * lever_);
    }
  }

  [[nodiscard]] double slide_time() const noexcept { return slide_time_; }
  [[nodiscard]] double deceleration() const noexcept { return deceleration_; }
  [[nodiscard]] const Vec3& slip_direction() const noexcept { return direction_; }
  [[nodiscard]] double static_overlap() const noexcept { return overlap_; }
  [[nodiscard]] double lever() const noexcept { return lever_; }

  /// Position, velocity, spin and total force at time t.
  void at(double t, Vec3& x, Vec3& v, Vec3& w, Vec3& f) const {
    const double ts = std::min(t, slide_time_);
    v = v0_ - deceleration_ * ts * direction_;
    w = w0_ + spin_rate_ * ts * n_.cross(direction_);
    x = x0_ + v0_ * ts - 0.5 * deceleration_ * ts * ts * direction_ + v * (t - ts);
    f = t < slide_time_ ? Vec3(-s_.mass * deceleration_ * direction_) : Vec3::Zero();
  }

 private:
  SphereWallScene s_;
  Vec3 n_, x0_, v0_, w0_;
  double g_ = 0.0;
  double overlap_ = 0.0;
  double lever_ = 0.0;
  double slip0_ = 0.0;
  Vec3 direction_ = Vec3::Zero();
  double deceleration_ = 0.0;
  double spin_rate_ = 0.0;
  double slide_time_ = 0.0;
};

}  // namespace

std::vector<std::string> SlidingSolver::unsupported_reasons(const PreparedScene& prepared) const {
  const cases::Scene& scene = prepared.scene();
  constexpr std::string_view who = "sliding";
  std::vector<std::string> reasons = sphere_wall_reasons(prepared, who);
  if (!reasons.empty()) return reasons;
  const auto reason = [&](const std::string& why) {
    reasons.push_back(fmt::format("analytic ({}): {}", who, why));
  };
  const SphereWallScene s = sphere_wall_scene(prepared);
  const Vec3 n = core_vec(s.normal);
  const Vec3 g = core_vec(scene.gravity);
  const double g_n = -g.dot(n);
  if (!(g_n > 0.0) || (g + g_n * n).norm() > 1e-12 * g.norm()) {
    reason("gravity must point into the wall along its normal (a horizontal plane)");
    return reasons;
  }
  const double overlap = s.radius - (core_vec(s.position) - core_vec(s.wall_point)).dot(n);
  const double resting = s.mass * g_n / s.stiffness;
  if (std::abs(overlap - resting) > kRestTolerance * resting) {
    reason(fmt::format("the sphere must start at its static overlap m g / k_e = {:.17g} m (got "
                       "{:.17g} m), or the normal spring–dashpot oscillates",
                       resting, overlap));
  }
  const Vec3 v = core_vec(s.velocity);
  if (std::abs(v.dot(n)) > kRestTolerance * v.norm()) {
    reason("the initial velocity must lie in the plane of the wall");
  }
  return reasons;
}

cases::RunResult SlidingSolver::run(const PreparedScene& prepared) const {
  const cases::Scene& scene = prepared.scene();
  const SphereWallScene s = sphere_wall_scene(prepared);
  const SlidingMotion motion(s, core_vec(scene.gravity));
  const auto [dt, steps, every, t_end] = sample_grid(prepared);
  const double weight = s.mass * -core_vec(scene.gravity).dot(core_vec(s.normal));

  cases::RunResult result;
  result.status = cases::RunStatus::ok;
  result.trace = cases::trace_layout(scene);
  Vec3 x, v, w, f;
  for (std::uint64_t k = 0; k <= steps; k += every) {
    const double t = static_cast<double>(k) * dt;
    motion.at(t, x, v, w, f);
    std::vector<double> row{t};
    for (std::size_t i = 0; i < scene.output.trace_particles.size(); ++i) {
      for (const Vec3* q : {&x, &v, &w, &f}) row.insert(row.end(), {q->x(), q->y(), q->z()});
    }
    for (std::size_t i = 0; i < scene.output.trace_walls.size(); ++i) {
      row.push_back(motion.static_overlap());
      row.push_back(weight);
    }
    result.trace.append_row(row);
  }
  for (const std::uint64_t k : cases::snapshot_steps(scene.output.snapshot_times, dt, steps)) {
    const double t = static_cast<double>(k) * dt;
    motion.at(t, x, v, w, f);
    result.snapshots.push_back({t, {case_vec(x)}, {case_vec(v)}, {case_vec(w)}});
  }
  // The metric reads |v_t|: its slope is −μ g exactly when v0 lies along the slip direction and
  // keeps its sense while sliding.
  const Vec3 v0 = core_vec(s.velocity);
  const double along = v0.dot(motion.slip_direction());
  const bool collinear = (v0 - along * motion.slip_direction()).norm() <= 1e-12 * v0.norm();
  if (motion.deceleration() > 0.0 && collinear &&
      (along - motion.deceleration() * motion.slide_time()) * along > 0.0) {
    result.exact_metrics["deceleration"] = along > 0.0 ? motion.deceleration() : -motion.deceleration();
  }
  auto& conv = result.conventions;
  conv["solution"] = fmt::format(
      "closed form: normal force m g from the static overlap {:.6g} m; sliding with |F_t| = μ m g "
      "against the slip direction until t = {:.9g} s, then rolling at constant velocity (Coulomb; "
      "the spring's ring-down after sticking is not modelled)",
      motion.static_overlap(), motion.slide_time());
  conv["sampling"] = fmt::format(
      "same time points as the in-house core: t_k = k·{}·Δt with Δt = {:.6g} s", every, dt);
  conv["lever arm"] = s.lever_is_radius ? "r" : fmt::format("r − δ/2 = {:.9g} m", motion.lever());
  conv["rotation"] = s.inverse_inertia > 0.0 ? "integrated, I = 2/5 m r²" : "held at initial values";
  conv["trace velocity"] = "exact velocity at the sample time";
  return result;
}

}  // namespace reference::analytic
