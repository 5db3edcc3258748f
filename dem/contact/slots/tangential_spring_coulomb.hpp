// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string_view>

#include "dem/contact/laws/coulomb_friction.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// The committed tangential slip carried into the current tangent plane by the model's
/// TangentialHistory rule (eq 3.9; docs/physics-tangential.md).
[[nodiscard]] inline Vec3 carried_slip(const ContactInput& in) noexcept {
  switch (in.policies.tangential_history) {
    case TangentialHistory::increment_project:
      return laws::project_onto_tangent_plane(in.committed.tangential_slip, in.g.normal);
    case TangentialHistory::yade_rotate:
      return laws::yade_rotate(in.committed.tangential_slip, in.committed.normal, in.g.normal,
                               in.g.angular_velocity_sum, in.elapsed);
    case TangentialHistory::project_rescale: break;
  }
  return laws::carry_into_tangent_plane(in.committed.tangential_slip, in.g.normal);
}

/// The spring–dashpot–Coulomb tangential response shared by the history-based tangential
/// sub-models: the committed slip carried into the current tangent plane (by the policy's
/// TangentialHistory rule) plus u_t·elapsed
/// (never accumulated in place, so trial evaluations leave the committed slip untouched),
/// F = −k ς − η_t u_t capped at μ·basis, slip truncated when capped. Writes next.tangential_slip.
[[nodiscard]] inline TangentialResponse spring_coulomb_response(double stiffness, double friction,
                                                                double damping_ratio,
                                                                const ContactInput& in,
                                                                const TangentialInput& t_in,
                                                                ContactHistory& next) noexcept {
  const Vec3& u_t = in.g.tangential_velocity;
  const Vec3 carried = carried_slip(in);
  const double eta_t = damping_ratio * t_in.damping_coefficient;
  const laws::SpringSliderResult r = laws::spring_slider(
      stiffness, eta_t, friction * t_in.limit_basis, carried, u_t, in.elapsed,
      in.policies.unloaded_slider == UnloadedSlider::zero, in.policies.coulomb_test == CoulombTest::spring);
  next.tangential_slip = r.displacement;
  return {r.force, laws::spring_energy(stiffness, r.displacement), r.dissipated};
}

/// Properties every spring–Coulomb tangential sub-model reads besides its stiffness.
inline constexpr std::string_view kFrictionKey = "friction";
/// Tangential dashpot as a fraction of the normal one; required (0 switches it off).
inline constexpr std::string_view kTangentialDampingKey = "tangential_damping_ratio";

/// Tangential sub-model `spring_coulomb` ("complex friction", thesis eq 3.22–3.26): linear
/// spring k_f on the integrated slip ς plus dashpot η_t = ratio·η_n, capped at μ times the
/// friction-limit basis; when capped the stored slip is truncated (Cundall–Strack).
struct SpringCoulombTangential {
  static constexpr std::string_view kKeyword = "spring_coulomb";
  static constexpr std::string_view kDescription =
      "F_t = −k_f ς − η_t u_t, |F_t| ≤ μ·basis, η_t = tangential_damping_ratio·η_n, slip "
      "truncated when sliding (eq 3.22–3.26; set tangential_damping_ratio = 0 for no dashpot)";
  static constexpr std::array<std::string_view, 3> kProperties{"tangential_stiffness", kFrictionKey,
                                                               kTangentialDampingKey};
  static constexpr std::string_view kLammps =
      "`tangential linear_history k_f x_γt μ` (x_γt = tangential_damping_ratio, η_t = x_γt·η_n; "
      "LAMMPS caps at |F_ne + F_damp| = friction_limit 'elastic_damping')";
  static constexpr std::string_view kYade =
      "Ip2_FrictMat_FrictMat_FrictPhys(ks = k_f) + Law2_ScGeom_FrictPhys_CundallStrack, "
      "frictionAngle = atan μ (cap on elastic |F_n| = friction_limit 'elastic'; no tangential "
      "dashpot: tangential_damping_ratio must be 0)";
  static constexpr std::string_view kLiggghts =
      "on linear: `tangential history` with kt per type pair (hooke/stiffness), gammat_abs = ratio · γ_n; LIGGGHTS tests the Coulomb limit on the spring alone";

  double stiffness;      ///< k_f [N/m]
  double friction;       ///< μ [-]
  double damping_ratio;  ///< η_t / η_n [-]

  /// Sub-model for one material pair.
  static SpringCoulombTangential from_pair(const PairProperties& pair) {
    constexpr std::string_view who = "tangential = 'spring_coulomb'";
    return {required_property(pair, &PairProperties::tangential_stiffness, "tangential_stiffness", who),
            required_property(pair, &PairProperties::friction, kFrictionKey, who),
            required_property(pair, &PairProperties::tangential_damping_ratio,
                              kTangentialDampingKey, who)};
  }
  /// Tangential force on p; updates next.tangential_slip.
  [[nodiscard]] TangentialResponse evaluate(const ContactInput& in, const TangentialInput& t_in,
                                            ContactHistory& next) const noexcept {
    return spring_coulomb_response(stiffness, friction, damping_ratio, in, t_in, next);
  }
  /// Energy the spring still holds when the bodies part: ½ k_f |ς|² of the committed slip, lost
  /// with the history [J].
  [[nodiscard]] double released_at_separation(const ContactInput& in) const noexcept {
    return laws::spring_energy(stiffness, in.committed.tangential_slip);
  }
};

}  // namespace dem
