// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>

#include "cases/scene.hpp"
#include "cases/trace.hpp"

// Metrics of the tangential motion of the compared contact (oblique impacts, sliding), computed
// from trace columns only, the same way for every engine (docs/metrics.md, docs/physics-tangential.md).
namespace comparison::motion {

/// Value of one motion metric, or why there is none (never NaN).
struct MotionMetric {
  std::optional<double> value;
  std::string problem;  ///< set when value is empty

  /// The value, or throws Problem(problem): lets compute_metrics dispatch in one line.
  template <class Problem>
  [[nodiscard]] double value_or_throw() const {
    if (!value) throw Problem(problem);
    return *value;
  }
};

/// Fraction of the subject–partner contact-point tangential velocity that survives the first
/// contact, with a sign: −u_t,after·t̂ / |u_t,before|, t̂ = u_t,before/|u_t,before|. u_t is the
/// tangential part of u_c = (v_p + ω_p × a_p) − (v_q + ω_q × a_q), branch vectors at touch
/// a_p = −r_p n, a_q = r_q n, rows last_before / first_after of the contact. −1 frictionless,
/// 0 rolling without slip after the contact, > 0 slip reversed.
MotionMetric tangential_restitution(const cases::Scene& scene, const cases::Trace& trace);

/// Angle [degrees] between the relative centre velocity after the first contact and the contact
/// normal n (from the partner to the subject): atan2(|v_t|, v·n). 0° straight back, 90° grazing.
MotionMetric rebound_angle(const cases::Scene& scene, const cases::Trace& trace);

/// Subject's angular velocity after the first contact about t̂ × n_in [rad/s], t̂ the direction
/// of the contact-point slip before the contact and n_in the normal into the partner: positive
/// for the spin sliding friction imparts (the sense of rolling along t̂).
MotionMetric spin_after(const cases::Scene& scene, const cases::Trace& trace);

/// Component `axis` (0 x, 1 y, 2 z) of the subject's own velocity [m/s] (`angular` false) or
/// angular velocity [rad/s] (`angular` true) at the first sample after its first contact with
/// the compared partner ends: the end state of an impact, in the case's frame.
MotionMetric state_after(const cases::Scene& scene, const cases::Trace& trace, bool angular, int axis);

/// The end-state metric called `name` (velocity_after_x … angular_velocity_after_z), or empty
/// when `name` is not one of them.
std::optional<MotionMetric> end_state_metric(const std::string& name, const cases::Scene& scene,
                                             const cases::Trace& trace);

/// Largest tangential contact force [N] of the subject's first contact with the compared
/// partner: max over the rows in contact of |F − (F·n) n|, F the subject's traced total force
/// less its weight m g, n the contact normal at that row (the maximum over the samples, no
/// refinement). The traced force is the contact force only when the compared contact is the
/// subject's one interaction, so the scene must hold just the subject and its partner, and no
/// fluid; otherwise the metric has a problem instead of a value.
MotionMetric tangential_force_max(const cases::Scene& scene, const cases::Trace& trace);

/// Relative slip speed below which a contact counts as no longer sliding, as a fraction of
/// the slip speed at the first row of the contact.
inline constexpr double kSlidingThreshold = 1e-2;

/// Deceleration [m/s²] of the subject's tangential speed during the sliding phase of the
/// compared contact: minus the least-squares slope of |v_t| (centre velocity relative to the
/// partner, tangential to n) against time over the rows from the first row in contact while the
/// contact stays in contact and its contact-point slip speed (branch vectors r − δ/2) exceeds
/// kSlidingThreshold times its value at that first row. Needs at least 3 such rows.
MotionMetric deceleration(const cases::Scene& scene, const cases::Trace& trace);

}  // namespace comparison::motion
