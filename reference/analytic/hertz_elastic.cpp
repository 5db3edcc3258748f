// SPDX-License-Identifier: MIT
#include "reference/analytic/hertz_elastic.hpp"

#include <algorithm>
#include <cmath>

#include <boost/math/special_functions/beta.hpp>

#include "dem/contact/laws/hertz.hpp"

namespace reference::analytic {

HertzElasticContact::HertzElasticContact(double reduced_mass, double effective_modulus,
                                         double reduced_radius, double speed)
    : effective_modulus_(effective_modulus),
      reduced_radius_(reduced_radius),
      speed_(speed),
      max_overlap_(dem::laws::hertz_max_overlap(reduced_mass, effective_modulus, reduced_radius,
                                                speed)),
      duration_(0.8 * boost::math::beta(0.4, 0.5) * max_overlap_ / speed) {}

double HertzElasticContact::max_force() const noexcept {
  return dem::laws::hertz_force(effective_modulus_, reduced_radius_, max_overlap_);
}

HertzElasticContact::State HertzElasticContact::at(double t) const {
  const double half = 0.5 * duration_;
  const double clamped = std::clamp(t, 0.0, duration_);
  // q = 1 − I_w = distance to the peak in units of t_c/2; the second half mirrors the first.
  const double q = std::abs(half - clamped) / half;
  if (q >= 1.0) return {0.0, clamped < half ? speed_ : -speed_};
  double one_minus_w = 0.0;
  const double w = q == 0.0 ? 1.0 : boost::math::ibetac_inv(0.4, 0.5, q, &one_minus_w);
  const double rate = speed_ * std::sqrt(q == 0.0 ? 0.0 : one_minus_w);
  return {max_overlap_ * std::pow(w, 0.4), clamped < half ? rate : -rate};
}

}  // namespace reference::analytic
