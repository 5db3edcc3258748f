// SPDX-License-Identifier: MIT
// The reference codes' own schemes, for matched comparisons (docs/integrators.md), written as
// fused passes over the spheres, in place, with no allocation: the schemes of many-body runs.
#include <cstdint>

#include "dem/core/parallel_for.hpp"
#include "dem/integrators/scheme_factories.hpp"
#include "dem/integrators/state_algebra.hpp"

namespace dem::detail {
namespace {

/// Shared passes of the two kick–drift schemes.
class KickDrift : public Scheme {
 public:
  explicit KickDrift(const SchemeSettings& s) : rotation_(s.rotation), orientation_(s.orientation) {}

 protected:
  /// One pass: u += kick·a (and ω += kick·α), then x += drift·u for every sphere that is not
  /// fixed, turning its orientation by drift·ω.
  void kick_and_drift(KinematicState& state, const Accelerations& acc, double kick, double drift) {
    const auto n = static_cast<std::int64_t>(state.position.cols());
    const bool rotation = rotation_;
    const bool orientation = rotation_ && orientation_;
    // Raw pointers and scalars captured by value: the pass stays as tight as a plain loop (with
    // references into the state the chute's integration pass was 25 % slower).
    double* const x = state.position.data();
    double* const u = state.velocity.data();
    double* const w = state.angular_velocity.data();
    const double* const a = acc.linear.data();
    const double* const alpha = acc.angular.data();
    Quat* const turn = state.orientation.data();
    parallel_for(threads_, n, [=, this](std::int64_t i) {
      const std::int64_t c = 3 * i;
      for (int k = 0; k < 3; ++k) u[c + k] += kick * a[c + k];
      if (rotation) {
        for (int k = 0; k < 3; ++k) w[c + k] += kick * alpha[c + k];
      }
      if (is_fixed(static_cast<std::size_t>(i))) return;
      for (int k = 0; k < 3; ++k) x[c + k] += drift * u[c + k];
      if (!orientation) return;
      const Vec3 theta = drift * Vec3(w[c], w[c + 1], w[c + 2]);
      const double angle = theta.norm();
      Quat& q = turn[i];
      if (angle > 0.0) q = (Quat(Eigen::AngleAxisd(angle, theta / angle)) * q).normalized();
    });
    state.time += drift;
  }
  /// True when the scheme integrates spins.
  [[nodiscard]] bool rotation() const noexcept { return rotation_; }
  /// True when the scheme turns orientations (which the evaluator's fused step does not).
  [[nodiscard]] bool turns_orientations() const noexcept { return rotation_ && orientation_; }

 private:
  bool rotation_;
  bool orientation_;
};

/// Velocity Verlet as LAMMPS `fix nve/sphere` performs it: half kick, drift, forces at the new
/// positions with the half-step velocities, half kick.
class VelocityVerlet final : public KickDrift {
 public:
  explicit VelocityVerlet(const SchemeSettings& s) : KickDrift(s) {}
  [[nodiscard]] double start_weight() const noexcept override { return 0.5; }
  [[nodiscard]] bool books_work_exactly() const noexcept override { return true; }
  void step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f) override {
    // An evaluator may fuse the kick and drift into its own pass over the spheres.
    if (!turns_orientations() && f.verlet_step(state, acc, dt, rotation())) {
      ++diagnostics_.force_evaluations;
      return;
    }
    kick_and_drift(state, acc, 0.5 * dt, dt);
    f.weigh(0.5, 0.5);
    // Forces see v(t + Δt/2), as in LAMMPS; the closing half kick rides on the evaluation's
    // last pass over the spheres.
    f.commit_and_kick(state, dt, acc, 0.5 * dt, rotation());
    ++diagnostics_.force_evaluations;
  }
};

/// Leapfrog with half-step velocities as YADE's NewtonIntegrator performs it:
/// v_{n+½} = v_{n−½} + Δt a(x_n, v_{n−½}); x_{n+1} = x_n + Δt v_{n+½}. The state's velocity
/// is the half-step one, v(t − Δt/2).
class Leapfrog final : public KickDrift {
 public:
  explicit Leapfrog(const SchemeSettings& s)
      : KickDrift(s), first_kick_half_(s.leapfrog_start == LeapfrogStart::half_kick) {}
  [[nodiscard]] double start_weight() const noexcept override { return first_kick_half_ ? 0.5 : 1.0; }
  [[nodiscard]] bool books_work_exactly() const noexcept override { return true; }
  void step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f) override {
    const double kick = first_kick_half_ ? 0.5 * dt : dt;
    first_kick_half_ = false;
    kick_and_drift(state, acc, kick, dt);
    f.weigh(0.0, 1.0);  // F_{n+1} kicks the next step in full
    f.commit(state, dt, acc);
    ++diagnostics_.force_evaluations;
  }

 private:
  bool first_kick_half_;
};

}  // namespace

std::unique_ptr<Scheme> make_velocity_verlet(const SchemeSettings& s) {
  return std::make_unique<VelocityVerlet>(s);
}
std::unique_ptr<Scheme> make_leapfrog(const SchemeSettings& s) {
  return std::make_unique<Leapfrog>(s);
}

}  // namespace dem::detail
