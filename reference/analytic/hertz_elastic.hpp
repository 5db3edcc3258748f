// SPDX-License-Identifier: MIT
#pragma once

namespace reference::analytic {

/// Closed-form elastic Hertz contact m* δ'' = −k_n δ^{3/2}, k_n = 4/3 E* √R*, from first touch
/// δ(0) = 0, δ'(0) = v. Energy conservation gives δ'² = v² (1 − (δ/δ_max)^{5/2}) and
/// t(δ) = (t_c/2) I_w(2/5, 1/2), w = (δ/δ_max)^{5/2}, with I the regularised incomplete beta
/// function and t_c = (4/5) B(2/5, 1/2) δ_max / v; the motion is symmetric about t_c/2. So
/// δ(t) = δ_max w^{2/5}, w = I⁻¹(2/5, 1/2; 2t/t_c), inverted with Boost.Math (ibetac_inv, so
/// that 1 − w keeps full precision near the peak).
class HertzElasticContact {
 public:
  /// Contact of reduced mass m* [kg], E* [Pa], R* [m] at approach speed v > 0 [m/s].
  HertzElasticContact(double reduced_mass, double effective_modulus, double reduced_radius,
                      double speed);
  /// t_c [s].
  [[nodiscard]] double duration() const noexcept { return duration_; }
  /// δ_max = (15 m* v² / (16 E* √R*))^{2/5} [m].
  [[nodiscard]] double max_overlap() const noexcept { return max_overlap_; }
  /// F(δ_max) = 4/3 E* √R* δ_max^{3/2} [N].
  [[nodiscard]] double max_force() const noexcept;
  /// Overlap δ(t) [m] and rate δ'(t) [m/s] for 0 ≤ t ≤ t_c (t since first touch).
  struct State {
    double overlap;
    double overlap_rate;
  };
  /// State at time t ∈ [0, t_c].
  [[nodiscard]] State at(double t) const;

 private:
  double effective_modulus_;
  double reduced_radius_;
  double speed_;
  double max_overlap_;
  double duration_;
};

}  // namespace reference::analytic
