// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <string_view>

#include "dem/contact/laws/hertz.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Normal sub-model `hertz`: F = 4/3 E* √R* δ^{3/2} while δ > 0 (thesis eq 3.12–3.13), R* from
/// the contact's geometry (r against a plane wall).
struct HertzNormal {
  static constexpr std::string_view kKeyword = "hertz";
  static constexpr std::string_view kDescription =
      "Hertz F = 4/3 E* √R* δ^{3/2} (eq 3.12–3.13); tangent stiffness 2 E* √(R* δ)";
  static constexpr std::array<std::string_view, 1> kProperties{"effective_modulus"};
  static constexpr std::string_view kLammps =
      "pair granular `hertz/material E η ν` on an explicit pair_coeff for every type pair, with "
      "E = 2(1−ν²)·E* (this build reads E* = E/(2(1−ν²)) whatever the pair; auto-mixed i≠j pairs "
      "silently become a linear spring); fix wall/gran granular: E = 2(1−ν)·E* (missing square in "
      "this build)";
  static constexpr std::string_view kYade =
      "FrictMat(young, poisson) + Ip2_FrictMat_FrictMat_MindlinPhys + "
      "Law2_ScGeom_MindlinPhys_Mindlin (k_no = 4/3 E*√R*, E* as ours); sphere–wall contacts use "
      "R* = r/2 there, not r: model a wall as a large fixed sphere or scale the moduli by √2";
  static constexpr std::string_view kLiggghts =
      "`model hertz`: k_n = 4/3 Y* √(R* δ), Y* mixed by LIGGGHTS from per-type `youngsModulus` and `poissonsRatio` (checked against the pair's E*)";

  double effective_modulus;  ///< E* [Pa]

  /// Sub-model for one material pair.
  static HertzNormal from_pair(const PairProperties& pair) {
    return {required_property(pair, &PairProperties::effective_modulus, "effective_modulus",
                              "normal = 'hertz'")};
  }
  /// Elastic response; zero out of contact.
  [[nodiscard]] NormalResponse evaluate(const ContactInput& in, ContactHistory&) const noexcept {
    const double delta = in.g.overlap;
    if (delta <= 0.0) return {};
    const double r = in.g.reduced_radius;
    return {laws::hertz_force(effective_modulus, r, delta),
            laws::hertz_stiffness(effective_modulus, r, delta),
            laws::hertz_energy(effective_modulus, r, delta), true};
  }
  /// Acts only while the bodies overlap.
  [[nodiscard]] double range(const PairExtent& e) const noexcept { return e.contact_distance; }
  /// Tangent stiffness 2 E* √(R* δ_max) at the largest overlap of an elastic impact at the
  /// scale's speed, δ_max = (15 m* v² / (16 E* √R*))^{2/5} (docs/physics.md). The linear contact
  /// time π√(m*/k) built from it is 0.78 of the true Hertz duration, so step limits err safe.
  [[nodiscard]] double collision_stiffness(const CollisionScale& s) const noexcept {
    const double peak = laws::hertz_max_overlap(s.reduced_mass, effective_modulus,
                                                s.reduced_radius, s.impact_speed);
    return laws::hertz_stiffness(effective_modulus, s.reduced_radius, peak);
  }
};

}  // namespace dem
