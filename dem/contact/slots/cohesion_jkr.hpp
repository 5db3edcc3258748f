// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cmath>
#include <string_view>

#include "dem/contact/laws/hertz.hpp"
#include "dem/contact/laws/jkr.hpp"
#include "dem/contact/slots/property_access.hpp"
#include "dem/contact/slots/responses.hpp"

namespace dem {

/// Overlap below which an attached JKR contact breaks, per policy (docs/physics-cohesion.md): δ_c
/// of the displacement-controlled rupture, or δ_f of the load-controlled pull-off (as LAMMPS) [m],
/// from the contact's critical radius a_c.
[[nodiscard]] inline double jkr_break_overlap(const laws::JkrParameters& p, double critical_radius,
                                              JkrRupture policy) noexcept {
  return policy == JkrRupture::load ? laws::jkr_pulloff_overlap_at(critical_radius, p)
                                    : laws::jkr_rupture_overlap_at(critical_radius, p);
}

/// True when a JKR contact that was `attached` at the last commit is attached at overlap δ:
/// it forms when δ reaches 0 and, once formed, holds down to δ_c (`displacement`, inclusive) or
/// while δ > δ_f (`load`, as LAMMPS' r < r_p + r_q − δ_f).
[[nodiscard]] inline bool jkr_attached(bool attached, double overlap, const laws::JkrParameters& p,
                                       double critical_radius, JkrRupture policy) noexcept {
  if (overlap >= 0.0) return true;
  if (!attached) return false;
  const double limit = jkr_break_overlap(p, critical_radius, policy);
  return policy == JkrRupture::load ? overlap > limit : overlap >= limit;
}

/// Cohesion sub-model `jkr` (thesis eq 3.34–3.35; docs/physics-cohesion.md). The JKR force
/// *replaces* the normal force: this slot returns F_JKR(δ) minus the elastic force the normal slot
/// already gave (Hertz, so normal = "hertz" is required for a physically consistent damping and
/// energy split), so the elastic + cohesive sum is exactly F_JKR, and likewise for the energy. The
/// contact radius a(δ) is solved on the stable branch. Hysteresis per pair
/// (ContactHistory::attached): no force on approach until δ reaches 0, then the force jumps to the
/// JKR value −8/9 F_po; the neck holds into δ < 0 until the rupture set by
/// ContactPolicies::jkr_rupture (δ_c by default, δ_f for `load`). An attached neck is a contact
/// (damping and friction act on it).
struct JkrCohesion {
  static constexpr std::string_view kKeyword = "jkr";
  static constexpr std::string_view kDescription =
      "JKR adhesion, F = 4πa²(aE*/(3πR*) − √(γE*/(πa))) with hysteresis (eq 3.34–3.35); needs "
      "normal = 'hertz'";
  static constexpr std::array<std::string_view, 2> kProperties{"effective_modulus",
                                                               "surface_energy"};
  static constexpr std::string_view kLammps =
      "pair granular `jkr E η ν γ` with E = 2(1−ν²)E* per pair_coeff and `tangential "
      "linear_history 0 0 0` at least (linear_nohistory crashes); breaks at δ_f: jkr_rupture = "
      "'load' reproduces it";
  static constexpr std::string_view kYade = "no JKR law in YADE";
  static constexpr std::string_view kLiggghts =
      "none: sjkr/sjkr2 are a simplified JKR (k·A while the bodies overlap): no neck beyond contact, no hysteresis";

  double modulus;         ///< E* [Pa]
  double surface_energy;  ///< γ per surface [J/m²]

  /// Sub-model for one material pair.
  static JkrCohesion from_pair(const PairProperties& pair) {
    return {required_property(pair, &PairProperties::effective_modulus, "effective_modulus",
                              "cohesion = 'jkr' (from youngs_modulus and poisson_ratio)"),
            required_property(pair, &PairProperties::surface_energy, "surface_energy",
                              "cohesion = 'jkr'")};
  }
  /// The JKR constants of a contact of reduced radius R*.
  [[nodiscard]] laws::JkrParameters parameters(double reduced_radius) const noexcept {
    return {modulus, reduced_radius, surface_energy};
  }
  /// True when the pair adheres (γ > 0). With γ = 0 JKR is Hertz: no neck, no pull-off, the
  /// contact radius √(R*δ); that is how a non-adhesive wall sits in a JKR model.
  [[nodiscard]] bool adhesive() const noexcept { return surface_energy > 0.0; }
  /// F_JKR − F_elastic while attached; updates `next.attached`. Reports the contact radius a and
  /// (4/3) E* a for the dashpots that read them (LAMMPS' under JKR).
  [[nodiscard]] CohesionResponse evaluate(const ContactInput& in, const NormalResponse& elastic,
                                          ContactHistory& next) const noexcept {
    if (!adhesive()) {
      next.attached = false;
      return {};
    }
    const laws::JkrParameters p = parameters(in.g.reduced_radius);
    const double overlap = in.g.overlap;
    const double a_c = laws::jkr_critical_radius(p);  // one cube root serves the break and a(δ)
    next.attached = jkr_attached(in.committed.attached, overlap, p, a_c, in.policies.jkr_rupture);
    if (!next.attached) {
      // A neck that breaks lets go of the energy it held at the break overlap.
      CohesionResponse broken;
      if (in.committed.attached) {
        const double limit = jkr_break_overlap(p, a_c, in.policies.jkr_rupture);
        broken.released = laws::jkr_energy_at_ratio(laws::jkr_radius_ratio(limit, p, a_c), a_c, p);
      }
      return broken;
    }
    const double y = laws::jkr_radius_ratio(overlap, p, a_c);  // √(a/a_c)
    const double a = a_c * y * y;
    // A neck that snaps in at δ = 0 drops to U(0) = −1.2πγa₀² from nothing.
    const double released =
        in.committed.attached ? 0.0 : -laws::jkr_energy_at_ratio(laws::jkr_radius_ratio(0.0, p, a_c), a_c, p);
    return {laws::jkr_force_at_ratio(y, p) - elastic.force,
            laws::jkr_energy_at_ratio(y, a_c, p) - elastic.energy,
            true,
            true,
            laws::jkr_pulloff_force(p),
            a,
            laws::hertz_secant_stiffness_at_radius(modulus, a),
            released};
  }
  /// Reaches |δ_c| beyond touching (δ_f < δ_c in magnitude, so this covers both policies); a
  /// non-adhesive pair reaches the touching distance.
  [[nodiscard]] double range(const PairExtent& e) const noexcept {
    if (!adhesive()) return e.contact_distance;
    return e.contact_distance - laws::jkr_rupture_overlap(parameters(e.reduced_radius));
  }
};

}  // namespace dem
