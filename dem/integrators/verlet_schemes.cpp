// SPDX-License-Identifier: MIT
// The reference codes' own schemes, for matched comparisons (PHYSICS.md §7, §10).
#include "dem/integrators/scheme_factories.hpp"
#include "dem/integrators/state_algebra.hpp"

namespace dem::detail {
namespace {

/// Velocity Verlet as LAMMPS `fix nve/sphere` performs it: half kick, drift, forces at the new
/// positions with the half-step velocities, half kick.
class VelocityVerlet final : public Scheme {
 public:
  explicit VelocityVerlet(const SchemeSettings& s) : rotation_(s.rotation) {}
  void step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f) override {
    state.velocity += 0.5 * dt * acc.linear;
    if (rotation_) state.angular_velocity += 0.5 * dt * acc.angular;
    const Derivative drift{state.velocity, Vec3Array::Zero(3, state.velocity.cols()),
                           state.angular_velocity,
                           Vec3Array::Zero(3, state.angular_velocity.cols())};
    KinematicState next;
    advance(state, dt, drift, rotation_, next);
    state = std::move(next);
    f.commit(state, dt, acc);  // forces see v(t + Δt/2), as in LAMMPS
    state.velocity += 0.5 * dt * acc.linear;
    if (rotation_) state.angular_velocity += 0.5 * dt * acc.angular;
    ++diagnostics_.force_evaluations;
  }

 private:
  bool rotation_;
};

/// Leapfrog with half-step velocities as YADE's NewtonIntegrator performs it:
/// v_{n+½} = v_{n−½} + Δt a(x_n, v_{n−½}); x_{n+1} = x_n + Δt v_{n+½}. The state's velocity
/// is the half-step one, v(t − Δt/2).
class Leapfrog final : public Scheme {
 public:
  explicit Leapfrog(const SchemeSettings& s)
      : rotation_(s.rotation), first_kick_half_(s.leapfrog_start == LeapfrogStart::half_kick) {}
  void step(KinematicState& state, Accelerations& acc, double dt, ForceEvaluator& f) override {
    const double kick = first_kick_half_ ? 0.5 * dt : dt;
    first_kick_half_ = false;
    state.velocity += kick * acc.linear;
    if (rotation_) state.angular_velocity += kick * acc.angular;
    const Derivative drift{state.velocity, Vec3Array::Zero(3, state.velocity.cols()),
                           state.angular_velocity,
                           Vec3Array::Zero(3, state.angular_velocity.cols())};
    KinematicState next;
    advance(state, dt, drift, rotation_, next);
    state = std::move(next);
    f.commit(state, dt, acc);
    ++diagnostics_.force_evaluations;
  }

 private:
  bool rotation_;
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
