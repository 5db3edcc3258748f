// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string_view>

#include "dem/contact/laws/coulomb_friction.hpp"
#include "dem/contact/laws/rolling_resistance.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Rolling sub-model `spring_dashpot_slider` (as LAMMPS pair granular `rolling sds k_r γ_r μ_r`):
/// rolling displacement ξ_r = ∫ v_roll dt with v_roll = R* (ω_p − ω_q) × n, stored in
/// ContactHistory::rolling_slip and carried into the tangent plane like the tangential slip;
/// pseudo-force F_r = −k_r ξ_r − γ_r v_roll capped at μ_r·basis (ξ_r truncated as the tangential
/// slip is); torque τ_p = R* n × F_r on p and −τ_p on q.
struct SpringDashpotSliderRolling {
  static constexpr std::string_view kKeyword = "spring_dashpot_slider";
  static constexpr std::string_view kDescription =
      "F_r = −k_r ξ_r − γ_r v_roll, |F_r| ≤ μ_r·basis, τ_p = R* n × F_r, v_roll = R* ω_rel × n "
      "(LAMMPS rolling sds)";
  static constexpr std::array<std::string_view, 3> kProperties{"rolling_stiffness", "rolling_damping",
                                                               "rolling_friction"};
  static constexpr std::string_view kLammps = "`rolling sds k_r γ_r μ_r` (pair granular and fix wall/gran)";
  static constexpr std::string_view kYade =
      "none: CohFrictMat's moment law has no dashpot and a different stiffness definition";
  static constexpr std::string_view kLiggghts =
      "none: `rolling_friction epsd2` is a torque spring k_t R*² (the tangential stiffness) fed by the tangent "
      "spin, capped at μ_r |F_n| R*, not turned with the contact, without a dashpot";

  double stiffness;         ///< k_r [N/m]
  double damping;           ///< γ_r [kg/s]
  double rolling_friction;  ///< μ_r [-]

  /// Sub-model for one material pair.
  static SpringDashpotSliderRolling from_pair(const PairProperties& pair) {
    constexpr std::string_view who = "rolling = 'spring_dashpot_slider'";
    return {required_property(pair, &PairProperties::rolling_stiffness, "rolling_stiffness", who),
            required_property(pair, &PairProperties::rolling_damping, "rolling_damping", who),
            required_property(pair, &PairProperties::rolling_friction, "rolling_friction", who)};
  }
  /// Torques on p and q; updates next.rolling_slip.
  [[nodiscard]] RollingResponse evaluate(const ContactInput& in, const RollingInput& normal,
                                         ContactHistory& next) const noexcept {
    const double r = in.g.reduced_radius;
    const Vec3 v_roll = laws::rolling_velocity(r, in.g.relative_angular_velocity, in.g.normal);
    const Vec3 carried = laws::carry_into_tangent_plane(in.committed.rolling_slip, in.g.normal);
    const laws::SpringSliderResult s = laws::spring_slider(
        stiffness, damping, rolling_friction * normal.limit_basis, carried, v_roll, in.elapsed,
        in.policies.unloaded_slider == UnloadedSlider::zero);
    next.rolling_slip = s.displacement;
    const Vec3 torque = laws::rolling_torque(r, in.g.normal, s.force);
    return {torque, -torque, s.dissipated, laws::spring_energy(stiffness, s.displacement)};
  }
  /// Energy the rolling spring still holds when the bodies part: ½ k_r |ξ_r|² of the committed
  /// rolling slip, lost with the history [J].
  [[nodiscard]] double released_at_separation(const ContactInput& in) const noexcept {
    return laws::spring_energy(stiffness, in.committed.rolling_slip);
  }
};

}  // namespace dem
