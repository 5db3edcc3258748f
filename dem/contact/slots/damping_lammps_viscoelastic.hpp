// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string_view>

#include "dem/contact/laws/nonlinear_dashpots.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Damping sub-model `lammps_viscoelastic`: η = η₀ a m*, a = √(R* δ), LAMMPS `damping
/// viscoelastic` (its default when no damping keyword is given). Restitution depends on speed.
struct LammpsViscoelasticDamping {
  static constexpr std::string_view kKeyword = "lammps_viscoelastic";
  static constexpr std::string_view kDescription =
      "dashpot η = η₀ √(R* δ) m*, η₀ = viscoelastic_damping (LAMMPS `damping viscoelastic`)";
  static constexpr std::array<std::string_view, 1> kProperties{"viscoelastic_damping"};
  static constexpr std::string_view kLammps =
      "`damping viscoelastic` with the pair_coeff damping value η₀ [1/(m·s)] (also LAMMPS' "
      "default: always name the damping model explicitly)";
  static constexpr std::string_view kYade = "none: no √δ dashpot in YADE's Hertz–Mindlin";
  static constexpr std::string_view kLiggghts =
      "on Hertz, `model hertz/stiffness`: γ_n = gamman √(R* δ) m* with gamman = η₀ per type pair (k_n = 4/3 E*, "
      "k_t = 8 G* per type pair)";

  double rate_per_length;  ///< η₀ [1/(m·s)]

  /// Sub-model for one material pair.
  static LammpsViscoelasticDamping from_pair(const PairProperties& pair) {
    return {required_property(pair, &PairProperties::viscoelastic_damping, "viscoelastic_damping",
                              "damping = 'lammps_viscoelastic'")};
  }
  /// Dashpot coefficient η [kg/s] for this contact (0 when δ ≤ 0).
  [[nodiscard]] double coefficient(const ContactGeometry& g, const NormalResponse&) const noexcept {
    return laws::lammps_viscoelastic_damping_coefficient(rate_per_length, g.reduced_radius,
                                                         g.overlap, g.reduced_mass);
  }
  /// As LAMMPS under JKR: η = η₀ a m* with the JKR contact radius a (also in a neck at δ < 0);
  /// without a contact radius, as above.
  [[nodiscard]] double coefficient(const ContactGeometry& g, const NormalResponse& normal,
                                   const CohesionResponse& cohesion) const noexcept {
    if (cohesion.contact_radius > 0.0) {
      return laws::lammps_viscoelastic_damping_at_radius(rate_per_length, cohesion.contact_radius, g.reduced_mass);
    }
    return coefficient(g, normal);
  }
};

}  // namespace dem
