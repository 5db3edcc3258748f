// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cmath>
#include <string_view>

#include "dem/contact/laws/langston_potential.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Normal sub-model `potential`: Langston's continuous potential φ = ε_p (d/|x|)^a with
/// F = a ε_p/|x| (d/|x|)^a for |x| < d_crit (thesis eq 3.17–3.19), ε_p = d m* g / a. The
/// characteristic length d is the contact distance r_p + r_q of the pair (r against a plane
/// wall), so the force equals the weight m* g where the bodies touch; d_crit = d · ratio. It
/// acts before the bodies touch (range d_crit); damping still acts only while δ > 0.
struct PotentialNormal {
  static constexpr std::string_view kKeyword = "potential";
  static constexpr std::string_view kDescription =
      "Langston potential F = a ε_p/|x| (d/|x|)^a for |x| < d_crit, ε_p = d m* g / a, "
      "d = r_p + r_q (eq 3.17–3.19)";
  static constexpr std::array<std::string_view, 3> kProperties{
      "potential_exponent", "potential_critical_ratio", "potential_gravity"};
  static constexpr std::string_view kLammps =
      "none: pair granular has no continuous potential; a per-type-pair `pair_style table` "
      "F(r) inside hybrid/overlay could tabulate it (not verified)";
  static constexpr std::string_view kYade = "none: no Langston potential law in YADE 2023.02a";
  static constexpr std::string_view kLiggghts =
      "none: LIGGGHTS has no Langston potential";

  double exponent;        ///< a [-]
  double critical_ratio;  ///< d_crit / d [-], > 1
  double gravity;         ///< g in ε_p = d m* g / a [m/s²]

  /// Sub-model for one material pair.
  static PotentialNormal from_pair(const PairProperties& pair) {
    constexpr std::string_view who = "normal = 'potential'";
    return {required_property(pair, &PairProperties::potential_exponent, "potential_exponent", who),
            required_property(pair, &PairProperties::potential_critical_ratio,
                              "potential_critical_ratio", who),
            required_property(pair, &PairProperties::potential_gravity, "potential_gravity", who)};
  }
  /// Potential response; active while |x| < d_crit. Stiffness is dF/dδ = (a + 1) F/|x|.
  [[nodiscard]] NormalResponse evaluate(const ContactInput& in, ContactHistory&) const noexcept {
    const double d = in.g.contact_distance;
    const double d_crit = critical_ratio * d;
    if (in.g.distance >= d_crit) return {};
    const double scale = laws::langston_energy_scale(d, in.g.reduced_mass, gravity, exponent);
    const laws::PotentialResponse r =
        laws::langston_potential(exponent, scale, d, d_crit, in.g.distance);
    return {r.force, r.stiffness, r.energy, true};
  }
  /// Acts out to d_crit = ratio · (r_p + r_q).
  [[nodiscard]] double range(const PairExtent& e) const noexcept {
    return critical_ratio * e.contact_distance;
  }
  /// Tangent stiffness at the closest approach of an impact at the scale's speed (potential
  /// energy = ½ m* v²). CollisionScale has no contact distance, so d = 4 R* (equal spheres, the
  /// smallest d for this R* and hence the stiffest estimate).
  [[nodiscard]] double collision_stiffness(const CollisionScale& s) const noexcept {
    const double d = 4.0 * s.reduced_radius;
    const double scale = laws::langston_energy_scale(d, s.reduced_mass, gravity, exponent);
    const double floor = std::pow(1.0 / critical_ratio, exponent);
    const double kinetic = 0.5 * s.reduced_mass * s.impact_speed * s.impact_speed;
    const double closest = d * std::pow(kinetic / scale + floor, -1.0 / exponent);
    return laws::langston_potential(exponent, scale, d, critical_ratio * d, closest).stiffness;
  }
};

}  // namespace dem
