// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cmath>
#include <string_view>

#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Velocity scale α = D/(D − δ) that YADE's ScGeom::getIncidentVel (avoidGranularRatcheting)
/// puts on the relative translational velocity: D = r_p + r_q for a sphere pair, and 2r against
/// a plane wall (Ig2_Wall_Sphere_ScGeom gives the wall the sphere's radius). Pure.
[[nodiscard]] inline double yade_incident_velocity_scale(const ContactGeometry& g) noexcept {
  return laws::incident_velocity_scale(g.against_wall ? 2.0 * g.contact_distance : g.contact_distance,
                                       g.overlap);
}

/// Damping sub-model `yade_frictvisco`: the restitution dashpot of eq 3.10–3.11 as YADE 2023.02a's
/// Law2_ScGeom_FrictViscoPhys_CundallStrackVisco applies it, F = −α η (u_c·n) with
/// η = β(ε) √(m* k) (= 2 betan √(m̄ k_n), betan = β/2) and α = yade_incident_velocity_scale.
/// Unclamped. Only for matched runs against YADE: the rebound is below ε by ≈ |ln ε|·δ/(D − δ).
struct YadeFrictViscoDamping {
  static constexpr std::string_view kKeyword = "yade_frictvisco";
  static constexpr std::string_view kDescription =
      "YADE FrictViscoPhys dashpot −α η (u_c·n), η = −2 ln ε √(m* k/(π² + ln² ε)), "
      "α = (r_p + r_q)/(r_p + r_q − δ) (2r/(2r − δ) against a wall)";
  static constexpr std::array<std::string_view, 1> kProperties{"restitution"};
  static constexpr std::string_view kLammps =
      "none: LAMMPS has no α-scaled dashpot (use `restitution`)";
  static constexpr std::string_view kYade =
      "FrictViscoMat(betan = β/2) + Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys(kn, kRatio) + "
      "Law2_ScGeom_FrictViscoPhys_CundallStrackVisco, exactly (the law of `restitution` in YADE)";
  static constexpr std::string_view kLiggghts =
      "none: YADE's own law";

  double restitution;  ///< ε ∈ (0, 1]
  double factor;       ///< β(ε) = η / √(m* k)

  /// Sub-model for one material pair.
  static YadeFrictViscoDamping from_pair(const PairProperties& pair) {
    const double e = required_property(pair, &PairProperties::restitution, "restitution",
                                       "damping = 'yade_frictvisco'");
    return {e, laws::restitution_damping_factor(e)};
  }
  /// Effective dashpot coefficient α η [kg/s] multiplying −u_c·n for this contact.
  [[nodiscard]] double coefficient(const ContactGeometry& g,
                                   const NormalResponse& normal) const noexcept {
    return yade_incident_velocity_scale(g) * factor * std::sqrt(g.reduced_mass * normal.stiffness);
  }
};

}  // namespace dem
