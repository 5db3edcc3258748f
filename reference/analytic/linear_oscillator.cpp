// SPDX-License-Identifier: MIT
#include "reference/analytic/linear_oscillator.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace reference::analytic {

LinearOscillator::LinearOscillator(double mass, double damping, double stiffness, double y0,
                                   double v0) noexcept
    : kind_(Kind::free), y0_(y0), v0_(v0) {
  if (stiffness <= 0.0) return;
  decay_ = damping / (2.0 * mass);
  omega_sq_ = stiffness / mass;
  const double omega = std::sqrt(omega_sq_);
  if (decay_ < omega) {
    kind_ = Kind::underdamped;
    rate_ = std::sqrt((omega - decay_) * (omega + decay_));
  } else if (decay_ == omega) {
    kind_ = Kind::critical;
  } else {
    kind_ = Kind::overdamped;
    rate_ = std::sqrt((decay_ - omega) * (decay_ + omega));
  }
}

LinearOscillator::Basis LinearOscillator::basis(double tau) const noexcept {
  switch (kind_) {
    case Kind::free:
      return {1.0, tau};
    case Kind::underdamped: {
      const double envelope = std::exp(-decay_ * tau);
      const double phase = rate_ * tau;
      return {envelope * std::cos(phase), envelope * std::sin(phase) / rate_};
    }
    case Kind::critical: {
      const double envelope = std::exp(-decay_ * tau);
      return {envelope, envelope * tau};
    }
    case Kind::overdamped: {
      // e^{−γτ} cosh(μτ) and e^{−γτ} sinh(μτ) written with the growing exponential factored
      // out, so neither overflows nor cancels for any τ.
      const double a = std::abs(rate_ * tau);
      const double scale = 0.5 * std::exp(-decay_ * tau + a);
      const double fade = std::exp(-2.0 * a);
      const double sinh_part = -std::expm1(-2.0 * a) * (tau < 0.0 ? -1.0 : 1.0);
      return {scale * (1.0 + fade), scale * sinh_part / rate_};
    }
  }
  return {1.0, tau};
}

AxisKinematics LinearOscillator::at(double tau) const noexcept {
  if (kind_ == Kind::free) return {y0_ + v0_ * tau, v0_, 0.0};
  const Basis b = basis(tau);
  AxisKinematics k;
  k.position = y0_ * b.even + (v0_ + decay_ * y0_) * b.odd;
  k.velocity = v0_ * b.even - (decay_ * v0_ + omega_sq_ * y0_) * b.odd;
  k.acceleration = -2.0 * decay_ * k.velocity - omega_sq_ * k.position;
  return k;
}

double LinearOscillator::natural_period() const noexcept {
  if (kind_ == Kind::free) return std::numeric_limits<double>::infinity();
  return 2.0 * std::numbers::pi / std::sqrt(omega_sq_);
}

}  // namespace reference::analytic
