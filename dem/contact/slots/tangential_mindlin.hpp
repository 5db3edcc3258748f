// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <array>
#include <string_view>

#include "dem/contact/laws/coulomb_friction.hpp"
#include "dem/contact/laws/mindlin_stiffness.hpp"
#include "dem/contact/slots/tangential_spring_coulomb.hpp"

namespace dem {

/// The contact radius a of Mindlin's stiffness under the model's MindlinRadius policy: the
/// cohesion law's radius (an attached JKR neck) under `contact_radius` when it sets one, else
/// √(R* δ) [m].
[[nodiscard]] inline double mindlin_radius(const ContactInput& in, const TangentialInput& t_in) noexcept {
  if (in.policies.mindlin_radius == MindlinRadius::contact_radius && t_in.contact_radius > 0.0) {
    return t_in.contact_radius;
  }
  return laws::mindlin_contact_radius(in.g.reduced_radius, in.g.overlap);
}

/// The incremental Mindlin response (MindlinForm::incremental, YADE's Hertz–Mindlin): each slip
/// increment u_t Δt is loaded at the stiffness k_t = c a of its own step, F = F_old − c a u_t Δt,
/// rather than the whole slip at today's stiffness. The history holds σ = −F_spring / c [m²]
/// (carried by the TangentialHistory rule like a slip), so σ ← σ + a u_t Δt; with the dashpot
/// η_t u_t, the Coulomb cap (either CoulombTest) and the unloaded-slider rule as
/// spring_coulomb_response. The spring
/// energy is |F_spring|²/(2 k_t). `c` is the stiffness per unit contact radius [N/m²], a [m].
[[nodiscard]] inline TangentialResponse incremental_mindlin_response(double c, double a, double friction,
                                                                     double damping_ratio, const ContactInput& in,
                                                                     const TangentialInput& t_in,
                                                                     ContactHistory& next) noexcept {
  const Vec3& u_t = in.g.tangential_velocity;
  const Vec3 start = carried_slip(in);
  const Vec3 integrated = start + (a * in.elapsed) * u_t;
  const double eta_t = damping_ratio * t_in.damping_coefficient;
  const double cap = std::max(friction * t_in.limit_basis, 0.0);
  const double k_t = c * a;
  const auto energy = [&](const Vec3& sigma) { return laws::incremental_spring_energy(c, k_t, sigma); };
  next.tangential_stiffness = k_t;
  // The carried spring's energy at the last commit's stiffness less at today's: what the change
  // of k_t alone did to it (the ledger's stiffness_change; no stiffness kept: no ledger).
  const double k_then = in.committed.tangential_stiffness;
  const double restiffened = k_then > 0.0 ? laws::incremental_spring_energy(c, k_then, start) - energy(start) : 0.0;
  if (in.policies.coulomb_test == CoulombTest::spring) {
    // The spring alone against the limit; sliding drops the dashpot (CoulombTest::spring).
    const Vec3 spring = -c * integrated;
    const std::optional<Vec3> capped = laws::spring_over_cap(spring, cap);
    if (!capped) {
      next.tangential_slip = integrated;
      return {spring - eta_t * u_t, energy(integrated), eta_t * u_t.squaredNorm() * in.elapsed, restiffened};
    }
    const Vec3 sigma = -*capped / c;  // |spring| > cap ≥ 0 needs c > 0
    next.tangential_slip = sigma;
    const double work = laws::sliding_step_work(-c * start, *capped, u_t, in.elapsed);
    return {*capped, energy(sigma), std::max(work - (energy(sigma) - energy(start)), 0.0), restiffened};
  }
  Vec3 force = -c * integrated - eta_t * u_t;
  const double magnitude = force.norm();
  if (!(magnitude > cap)) {
    next.tangential_slip = integrated;
    return {force, energy(integrated), eta_t * u_t.squaredNorm() * in.elapsed, restiffened};
  }
  if (in.policies.unloaded_slider == UnloadedSlider::zero && integrated.norm() == 0.0) {
    next.tangential_slip = integrated;
    return {Vec3::Zero(), 0.0, 0.0, restiffened};
  }
  force *= cap / magnitude;
  const Vec3 sigma = c > 0.0 ? Vec3(-(force + eta_t * u_t) / c) : Vec3::Zero();
  next.tangential_slip = sigma;
  const double work = laws::sliding_step_work(-c * start - eta_t * u_t, force, u_t, in.elapsed);
  return {force, energy(sigma), std::max(work - (energy(sigma) - energy(start)), 0.0), restiffened};
}

/// The total-form Mindlin response: spring_coulomb_response at k_t = k, keeping k in the history
/// and booking the carried spring's energy change from the last commit's stiffness to k,
/// ½ (k_then − k) |ς|² (the ledger's stiffness_change; nothing when no stiffness was kept).
[[nodiscard]] inline TangentialResponse total_mindlin_response(double k, double friction, double damping_ratio,
                                                               const ContactInput& in, const TangentialInput& t_in,
                                                               ContactHistory& next) noexcept {
  TangentialResponse r = spring_coulomb_response(k, friction, damping_ratio, in, t_in, next);
  next.tangential_stiffness = k;
  const double k_then = in.committed.tangential_stiffness;
  if (k_then > 0.0) {
    const Vec3 carried = carried_slip(in);
    r.stiffness_change = laws::spring_energy(k_then, carried) - laws::spring_energy(k, carried);
  }
  return r;
}

/// Energy a Mindlin spring held at the last commit, at that commit's stiffness k_then [J]: the
/// spring energy a contact that parts takes with it. Incremental form |c σ|²/(2 k_then) (c the
/// stiffness per unit contact radius), total form ½ k_then |ς|²; zero when no stiffness was kept.
[[nodiscard]] inline double mindlin_committed_energy(double c, const ContactInput& in) noexcept {
  const double k_then = in.committed.tangential_stiffness;
  const Vec3& slip = in.committed.tangential_slip;
  return in.policies.mindlin_form == MindlinForm::incremental ? laws::incremental_spring_energy(c, k_then, slip)
                                                               : laws::spring_energy(std::max(k_then, 0.0), slip);
}

/// Mixed parameters of a Mindlin tangential sub-model.
struct MindlinParameters {
  double shear_modulus;  ///< G* [Pa] (eq 3.25)
  double friction;       ///< μ [-]
  double damping_ratio;  ///< η_t / η_n [-]

  /// Parameters for one material pair; `who` names the sub-model in errors.
  static MindlinParameters from_pair(const PairProperties& pair, std::string_view who) {
    return {required_property(pair, &PairProperties::effective_shear_modulus,
                              "effective_shear_modulus", who),
            required_property(pair, &PairProperties::friction, kFrictionKey, who),
            required_property(pair, &PairProperties::tangential_damping_ratio,
                              kTangentialDampingKey, who)};
  }
};

/// Tangential sub-model `mindlin`: the spring–Coulomb law with the thesis' Mindlin stiffness
/// k_f = 16/3 G* √(R* δ) (eq 3.25). The stored slip is a displacement and the force is
/// −k_f(δ) ς at the current overlap (LAMMPS `mindlin`, not `mindlin_rescale`): the spring
/// force follows k_f when δ changes at constant slip.
struct MindlinTangential {
  static constexpr std::string_view kKeyword = "mindlin";
  static constexpr std::string_view kDescription =
      "spring_coulomb with k_f = 16/3 G* √(R* δ) (eq 3.25), displacement history (as LAMMPS "
      "`mindlin`, no unloading rescale)";
  static constexpr std::array<std::string_view, 3> kProperties{"effective_shear_modulus", kFrictionKey,
                                                               kTangentialDampingKey};
  static constexpr std::string_view kLammps =
      "`tangential mindlin k_t x_γt μ` (`mindlin/force` under mindlin_form 'incremental') with k_t = "
      "16/3 G* passed explicitly (LAMMPS' NULL means 8 G*)";
  static constexpr std::string_view kYade =
      "none: YADE's Mindlin uses 8 G* and an incremental force history (use mindlin_8g)";
  static constexpr std::string_view kLiggghts =
      "none: LIGGGHTS' Hertz tangential stiffness is 8 G* √(R* δ) (use mindlin_8g)";

  MindlinParameters p;

  /// Sub-model for one material pair.
  static MindlinTangential from_pair(const PairProperties& pair) {
    return {MindlinParameters::from_pair(pair, "tangential = 'mindlin'")};
  }
  /// The stiffness per unit contact radius, k_f / a = 16/3 G* [N/m²] (the incremental form's c).
  [[nodiscard]] double stiffness_per_radius() const noexcept {
    return laws::mindlin_thesis_stiffness_at_radius(p.shear_modulus, 1.0);
  }
  /// Tangential force on p; updates next.tangential_slip.
  [[nodiscard]] TangentialResponse evaluate(const ContactInput& in, const TangentialInput& t_in,
                                            ContactHistory& next) const noexcept {
    const double a = mindlin_radius(in, t_in);
    if (in.policies.mindlin_form == MindlinForm::incremental) {
      return incremental_mindlin_response(stiffness_per_radius(), a,
                                          p.friction, p.damping_ratio, in, t_in, next);
    }
    const double k = laws::mindlin_thesis_stiffness_at_radius(p.shear_modulus, a);
    return total_mindlin_response(k, p.friction, p.damping_ratio, in, t_in, next);
  }
  /// Energy the spring still holds when the bodies part (mindlin_committed_energy) [J].
  [[nodiscard]] double released_at_separation(const ContactInput& in) const noexcept {
    return mindlin_committed_energy(stiffness_per_radius(), in);
  }
};

/// Tangential sub-model `mindlin_8g`: the spring–Coulomb law with Mindlin's initial stiffness
/// k_t = 8 G* √(R* δ), the form LAMMPS `mindlin` and YADE Hertz–Mindlin use (matched runs).
struct Mindlin8GTangential {
  static constexpr std::string_view kKeyword = "mindlin_8g";
  static constexpr std::string_view kDescription =
      "spring_coulomb with k_t = 8 G* √(R* δ) (Mindlin; LAMMPS `mindlin`), displacement history";
  static constexpr std::array<std::string_view, 3> kProperties{"effective_shear_modulus", kFrictionKey,
                                                               kTangentialDampingKey};
  static constexpr std::string_view kLammps =
      "`tangential mindlin 8G* x_γt μ` (`mindlin/force` under mindlin_form 'incremental'), k_t "
      "passed explicitly: NULL is wrong for fix wall/gran in this build";
  static constexpr std::string_view kYade =
      "Ip2_FrictMat_FrictMat_MindlinPhys + Law2_ScGeom_MindlinPhys_Mindlin (incremental force "
      "history: differs while δ changes at constant slip)";
  static constexpr std::string_view kLiggghts =
      "`model hertz` + `tangential history`: k_t = 8 G* √(R* δ) on the whole slip; its dashpot is LIGGGHTS' own, 2 √(G*/E*) times the normal one (or `tangential_damping off`)";

  MindlinParameters p;

  /// Sub-model for one material pair.
  static Mindlin8GTangential from_pair(const PairProperties& pair) {
    return {MindlinParameters::from_pair(pair, "tangential = 'mindlin_8g'")};
  }
  /// The stiffness per unit contact radius, k_t / a = 8 G* [N/m²] (the incremental form's c).
  [[nodiscard]] double stiffness_per_radius() const noexcept {
    return laws::mindlin_stiffness_at_radius(p.shear_modulus, 1.0);
  }
  /// Tangential force on p; updates next.tangential_slip.
  [[nodiscard]] TangentialResponse evaluate(const ContactInput& in, const TangentialInput& t_in,
                                            ContactHistory& next) const noexcept {
    const double a = mindlin_radius(in, t_in);
    if (in.policies.mindlin_form == MindlinForm::incremental) {
      return incremental_mindlin_response(stiffness_per_radius(), a, p.friction,
                                          p.damping_ratio, in, t_in, next);
    }
    const double k = laws::mindlin_stiffness_at_radius(p.shear_modulus, a);
    return total_mindlin_response(k, p.friction, p.damping_ratio, in, t_in, next);
  }
  /// Energy the spring still holds when the bodies part (mindlin_committed_energy) [J].
  [[nodiscard]] double released_at_separation(const ContactInput& in) const noexcept {
    return mindlin_committed_energy(stiffness_per_radius(), in);
  }
};

}  // namespace dem
