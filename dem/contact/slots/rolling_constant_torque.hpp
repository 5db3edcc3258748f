// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

#include "dem/contact/laws/rolling_resistance.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Rolling sub-model `constant_torque` (constant directional torque, "type A", Ai et al. 2011):
/// τ_p = −μ_r R* F ω̂_r with F the friction-limit basis and ω_r the tangent-plane part of the
/// relative angular velocity ω_p − ω_q (ω_q = 0 for a wall); q receives −τ_p, a pure couple, so
/// angular momentum about the contact point is conserved. Zero when ω_r = 0. Under
/// ConstantTorqueForm::projected it is LIGGGHTS' form instead (laws::projected_rolling_torque).
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
      "`rolling_friction cdt`: μ_r R* k_n δ (the elastic force) along the unit vector of ω_p − ω_q, its "
      "tangent part (constant_torque_form = 'projected')";

  double rolling_friction;  ///< μ_r [-]

  /// Sub-model for one material pair.
  static ConstantTorqueRolling from_pair(const PairProperties& pair) {
    return {required_property(pair, &PairProperties::rolling_friction, "rolling_friction",
                              "rolling = 'constant_torque'")};
  }
  /// Torques on p and q; dissipation −τ_p·(ω_p − ω_q) · elapsed (μ_r R* F |ω_r| in the tangent form,
  /// μ_r R* F_el |ω_r|²/|ω_p − ω_q| in the projected one).
  [[nodiscard]] RollingResponse evaluate(const ContactInput& in, const RollingInput& normal,
                                         ContactHistory&) const noexcept {
    const Vec3 torque =
        in.policies.constant_torque_form == ConstantTorqueForm::projected
            ? laws::projected_rolling_torque(rolling_friction, in.g.reduced_radius, std::abs(normal.elastic_force),
                                             in.g.relative_angular_velocity, in.g.normal)
            : laws::constant_rolling_torque(rolling_friction, in.g.reduced_radius, normal.limit_basis,
                                            in.g.relative_angular_velocity, in.g.normal);
    const double power = -torque.dot(in.g.relative_angular_velocity);
    return {torque, -torque, std::max(power, 0.0) * in.elapsed};
  }
};

}  // namespace dem
