// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <array>
#include <string_view>

#include "dem/contact/laws/rolling_resistance.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Rolling sub-model `constant_torque` (constant directional torque, "type A", Ai et al. 2011):
/// τ_p = −μ_r R* F ω̂_r with F the friction-limit basis and ω_r the tangent-plane part of the
/// relative angular velocity ω_p − ω_q (ω_q = 0 for a wall); q receives −τ_p, a pure couple, so
/// angular momentum about the contact point is conserved. Zero when ω_r = 0.
struct ConstantTorqueRolling {
  static constexpr std::string_view kKeyword = "constant_torque";
  static constexpr std::string_view kDescription =
      "τ_r = −μ_r R* |F_n| ω̂_r, ω_r = tangent-plane part of ω_p − ω_q (constant directional "
      "torque; bounded O(Δt) chatter once ω_r reaches 0)";
  static constexpr std::array<std::string_view, 1> kProperties{"rolling_friction"};
  static constexpr std::string_view kLammps =
      "none: LAMMPS has only `rolling sds`; its sliding limit μ_r R* |F_n| is the same torque";
  static constexpr std::string_view kYade =
      "none in the installed build (CohFrictMat rolling is elastic–plastic, not constant)";
  static constexpr std::string_view kLiggghts =
      "not mapped yet: `rolling_friction cdt` is μ_r k_n δ R* (elastic force only) against ω_p − ω_q";

  double rolling_friction;  ///< μ_r [-]

  /// Sub-model for one material pair.
  static ConstantTorqueRolling from_pair(const PairProperties& pair) {
    return {required_property(pair, &PairProperties::rolling_friction, "rolling_friction",
                              "rolling = 'constant_torque'")};
  }
  /// Torques on p and q; dissipation μ_r R* F |ω_r| · elapsed.
  [[nodiscard]] RollingResponse evaluate(const ContactInput& in, double basis,
                                         ContactHistory&) const noexcept {
    const Vec3 torque = laws::constant_rolling_torque(rolling_friction, in.g.reduced_radius, basis,
                                                      in.g.relative_angular_velocity, in.g.normal);
    const double power = -torque.dot(in.g.relative_angular_velocity);
    return {torque, -torque, std::max(power, 0.0) * in.elapsed};
  }
};

}  // namespace dem
