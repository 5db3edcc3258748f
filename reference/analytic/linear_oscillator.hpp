// SPDX-License-Identifier: MIT
#pragma once

namespace reference::analytic {

/// Position, velocity and acceleration of one coordinate at one instant (SI units).
struct AxisKinematics {
  double position = 0.0;      ///< [m]
  double velocity = 0.0;      ///< [m/s]
  double acceleration = 0.0;  ///< [m/s²]
};

/// Exact motion of m y'' + C y' + K y = 0 from y(0) = y0, y'(0) = v0: the deviation from
/// equilibrium while a fixed set of linear spring–dashpot contacts acts (thesis eq 3.10 summed
/// over the contacts, C = Σ η_i, K = Σ k_i). Covers free flight (K = C = 0), under-, critically
/// and over-damped motion; τ may be negative (the motion continued backwards in time).
class LinearOscillator {
 public:
  /// Motion with mass m > 0 [kg], damping C ≥ 0 [kg/s], stiffness K ≥ 0 [N/m] (K = 0 requires
  /// C = 0: free flight), initial deviation y0 [m] and rate v0 [m/s].
  LinearOscillator(double mass, double damping, double stiffness, double y0, double v0) noexcept;

  /// y, y', y'' at time τ [s] after the start of the motion.
  [[nodiscard]] AxisKinematics at(double tau) const noexcept;
  /// Undamped natural period 2π √(m/K) [s]; +∞ in free flight.
  [[nodiscard]] double natural_period() const noexcept;
  /// True when no spring acts (y'' ≡ 0).
  [[nodiscard]] bool free() const noexcept { return kind_ == Kind::free; }

 private:
  enum class Kind { free, underdamped, critical, overdamped };
  /// e^{−γτ}·c(τ) and e^{−γτ}·s(τ) where c, s are cos/sin(ω_d τ)/ω_d, cosh/sinh(μτ)/μ or 1/τ.
  struct Basis {
    double even;
    double odd;
  };
  [[nodiscard]] Basis basis(double tau) const noexcept;

  Kind kind_;
  double y0_;
  double v0_;
  double decay_ = 0.0;        ///< γ = C / 2m [1/s]
  double omega_sq_ = 0.0;     ///< ω² = K / m [1/s²]
  double rate_ = 0.0;         ///< ω_d = √(ω² − γ²) (under-) or μ = √(γ² − ω²) (over-damped)
};

}  // namespace reference::analytic
