// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string_view>

#include "dem/contact/laws/nonlinear_dashpots.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Damping sub-model `lammps_tsuji`: LAMMPS `damping tsuji` as it is, η = α_L(e) √(m* k_n) with
/// LAMMPS' polynomial α_L and k_n = F_el/δ (LAMMPS' knfac: 4/3 E* a for hertz/material, k for
/// hooke). Not restitution-exact: Hertz with nominal e = 0.5 rebounds with 0.6161.
struct LammpsTsujiDamping {
  static constexpr std::string_view kKeyword = "lammps_tsuji";
  static constexpr std::string_view kDescription =
      "LAMMPS `damping tsuji`: η = α_L(ε) √(m* F_el/δ), α_L = 1.2728 − 4.2783ε + … + 4.8218ε⁶ "
      "(gives 0.616 for ε = 0.5 with hertz)";
  static constexpr std::array<std::string_view, 1> kProperties{"restitution"};
  static constexpr std::string_view kLammps =
      "`damping tsuji` with the pair_coeff damping value ε (nominal restitution), no "
      "limit_damping";
  static constexpr std::string_view kYade =
      "no exact counterpart (YADE Mindlin clips F_n ≥ 0); betan = α_L/(2√1.5) gives the same "
      "dashpot with clamp_tensile = true";
  static constexpr std::string_view kLiggghts =
      "not mapped yet: LAMMPS' polynomial α(ε) would need the e whose LIGGGHTS Hertz dashpot equals it";

  double restitution;  ///< nominal ε passed to LAMMPS
  double factor;       ///< α_L(ε) [-]

  /// Sub-model for one material pair.
  static LammpsTsujiDamping from_pair(const PairProperties& pair) {
    const double e = required_property(pair, &PairProperties::restitution, "restitution",
                                       "damping = 'lammps_tsuji'");
    return {e, laws::lammps_tsuji_factor(e)};
  }
  /// Dashpot coefficient η [kg/s] for this contact: α_L √(m* F_el/δ), F_el/δ = (4/3) E* √(R*δ)
  /// on Hertz.
  [[nodiscard]] double coefficient(const ContactGeometry& g,
                                   const NormalResponse& normal) const noexcept {
    return laws::tsuji_damping_coefficient(
        factor, g.reduced_mass, laws::secant_stiffness(normal.force, g.overlap, normal.stiffness));
  }
  /// As LAMMPS under JKR: the stiffness is (4/3) E* a with the JKR contact radius a (also in a
  /// neck at δ < 0), not the Hertz secant; without a contact radius, as above.
  [[nodiscard]] double coefficient(const ContactGeometry& g, const NormalResponse& normal,
                                   const CohesionResponse& cohesion) const noexcept {
    if (cohesion.contact_radius > 0.0) {
      return laws::tsuji_damping_coefficient(factor, g.reduced_mass, cohesion.radius_stiffness);
    }
    return coefficient(g, normal);
  }
};

}  // namespace dem
