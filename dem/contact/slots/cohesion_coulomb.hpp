// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string_view>

#include "dem/contact/laws/coulomb.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Cohesion sub-model `coulomb`: electrostatic force between the particles' charges, thesis eq
/// 3.36, F = q_p q_q/(4π ε_r ε_0 |x_pq|²) (like charges repel), for centre distances below the
/// cut-off; zero for walls (no charge). Not a contact: no damping, no friction. The energy is
/// shifted to vanish at the cut-off.
struct CoulombCohesion {
  static constexpr std::string_view kKeyword = "coulomb";
  static constexpr std::string_view kDescription =
      "Coulomb force q_p q_q/(4π ε_r ε_0 |x|²) within a cut-off (eq 3.36)";
  static constexpr std::array<std::string_view, 2> kProperties{"relative_permittivity",
                                                               "coulomb_cutoff"};
  static constexpr std::string_view kLammps =
      "pair_style hybrid/overlay granular coul/cut r_c with dielectric ε_r and per-atom charges "
      "(atom_style hybrid sphere charge); not verified on this build";
  static constexpr std::string_view kYade = "no electrostatic law in YADE";
  static constexpr std::string_view kLiggghts =
      "none: pair gran has no electrostatics";

  double permittivity;  ///< ε_r [-]
  double cutoff;        ///< r_c [m], centre distance beyond which no force acts

  /// Sub-model for one material pair.
  static CoulombCohesion from_pair(const PairProperties& pair) {
    return {required_property(pair, &PairProperties::relative_permittivity,
                              "relative_permittivity", "cohesion = 'coulomb'"),
            required_property(pair, &PairProperties::coulomb_cutoff, "coulomb_cutoff",
                              "cohesion = 'coulomb'")};
  }
  /// Coulomb force inside the cut-off between charged particles.
  [[nodiscard]] CohesionResponse evaluate(const ContactInput& in, const NormalResponse&,
                                          ContactHistory&) const noexcept {
    const double q = in.g.charge_product;
    const double d = in.g.distance;
    if (q == 0.0 || !(d > 0.0) || !(d < cutoff)) return {};
    return {laws::coulomb_force(q, permittivity, d),
            laws::coulomb_energy(q, permittivity, d, cutoff), true, false, 0.0};
  }
  /// The cut-off.
  [[nodiscard]] double range(const PairExtent&) const noexcept { return cutoff; }
};

}  // namespace dem
