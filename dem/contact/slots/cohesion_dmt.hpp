// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string_view>

#include "dem/contact/laws/dmt.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Cohesion sub-model `dmt`: a constant attraction −4πγR* added to the (Hertz) normal force
/// while δ ≥ 0, so F = 4/3 E*√R* δ^{3/2} − 4πγR* with normal = "hertz"
/// (docs/physics-cohesion.md). The force jumps at δ = 0 (no attraction outside contact, no
/// hysteresis); the pull-off force is 4πγR*, reported for FrictionLimit::jkr_shifted as LAMMPS
/// does for `dmt`.
struct DmtCohesion {
  static constexpr std::string_view kKeyword = "dmt";
  static constexpr std::string_view kDescription =
      "DMT adhesion −4πγR* while δ ≥ 0, added to the normal force (use normal = 'hertz')";
  static constexpr std::array<std::string_view, 1> kProperties{"surface_energy"};
  static constexpr std::string_view kLammps =
      "pair granular `dmt E η ν γ` with E = 2(1−ν²)E* per pair_coeff (F = F_Hertz − 4πγR*)";
  static constexpr std::string_view kYade =
      "MindlinPhys/Law2_ScGeom_MindlinPhys_Mindlin with gamma = γ (per surface): pull-off 4πγR*";
  static constexpr std::string_view kLiggghts =
      "none: LIGGGHTS' sjkr/sjkr2 pull with k·A (k an energy density, A the contact area), not 4πγR*";

  double surface_energy;  ///< γ per surface [J/m²]

  /// Sub-model for one material pair.
  static DmtCohesion from_pair(const PairProperties& pair) {
    return {required_property(pair, &PairProperties::surface_energy, "surface_energy",
                              "cohesion = 'dmt'")};
  }
  /// −4πγR* while δ ≥ 0.
  [[nodiscard]] CohesionResponse evaluate(const ContactInput& in, const NormalResponse&,
                                          ContactHistory&) const noexcept {
    const double overlap = in.g.overlap;
    if (!(overlap >= 0.0)) return {};
    const double r = in.g.reduced_radius;
    return {laws::dmt_adhesion_force(surface_energy, r),
            laws::dmt_adhesion_energy(surface_energy, r, overlap), true, true,
            laws::dmt_pulloff_force(surface_energy, r)};
  }
  /// Acts only in contact.
  [[nodiscard]] double range(const PairExtent& e) const noexcept { return e.contact_distance; }
};

}  // namespace dem
