// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "dem/core/vector.hpp"

namespace dem::laws {

/// A stored tangential (or rolling) displacement ς carried into the current tangent plane with
/// unit normal n: the part along n is removed and the rest rescaled to the old magnitude |ς|
/// (LAMMPS pair granular history rule, Luding 2008 eq 17). For a normal that turned by θ this
/// equals the rigid rotation of ς to O(θ²) and preserves |ς| exactly. A displacement parallel
/// to n has no direction in the plane and becomes zero. Units of ς are kept.
[[nodiscard]] inline Vec3 carry_into_tangent_plane(const Vec3& displacement,
                                                   const Vec3& normal) noexcept {
  const double along = displacement.dot(normal);
  if (along == 0.0) return displacement;
  const Vec3 projected = displacement - along * normal;
  const double projected_norm = projected.norm();
  if (!(projected_norm > 0.0)) return Vec3::Zero();
  return projected * (displacement.norm() / projected_norm);
}

/// The part of a stored displacement ς that lies in the tangent plane with unit normal n,
/// ς − (ς·n) n, without rescaling (LAMMPS gran/hooke/history shear rule: |ς| shrinks by O(θ²)
/// when the normal turns by θ).
[[nodiscard]] inline Vec3 project_onto_tangent_plane(const Vec3& displacement,
                                                     const Vec3& normal) noexcept {
  return displacement - displacement.dot(normal) * normal;
}

/// A stored tangential displacement ς turned YADE's way (ScGeom::precompute and rotate,
/// docs/physics-tangential.md): first by the turn of the normal, ς − ς × (n_old × n), then by the
/// mean spin about the old normal over `elapsed`, ς − ς × (½ elapsed n_old·(ω_p + ω_q)) n_old,
/// each to first order and without re-projecting onto the tangent plane. A new contact
/// (n_old = 0) keeps ς. `spin_sum` is ω_p + ω_q [rad/s].
[[nodiscard]] inline Vec3 yade_rotate(const Vec3& displacement, const Vec3& previous_normal, const Vec3& normal,
                                      const Vec3& spin_sum, double elapsed) noexcept {
  if (previous_normal.isZero(0.0)) return displacement;
  const Vec3 turned = displacement - displacement.cross(previous_normal.cross(normal));
  const Vec3 twist = (elapsed * 0.5 * previous_normal.dot(spin_sum)) * previous_normal;
  return turned - turned.cross(twist);
}

/// Result of a spring–dashpot–slider: force, stored displacement and the dissipated work.
struct SpringSliderResult {
  Vec3 force = Vec3::Zero();         ///< −k ς − γ v, or its Coulomb-capped value [N]
  Vec3 displacement = Vec3::Zero();  ///< stored elastic displacement after truncation [m]
  bool sliding = false;              ///< the cap was reached (the slider slipped)
  double dissipated = 0.0;           ///< work dissipated over `elapsed` [J], ≥ 0
};

/// Work the relative motion does on a sliding slider over one step, by the trapezoid rule with the
/// forces on p at the step's two ends, −½(F_start + F_end)·v elapsed: velocity Verlet takes every
/// force's work so, and the energy ledger then books a contact that slides throughout to round-off
/// (docs/physics.md, "Energy ledger"). F_start is the spring's force on the carried displacement
/// plus the dashpot's on v [N]; v the relative velocity [m/s]; elapsed [s].
[[nodiscard]] inline double sliding_step_work(const Vec3& start_force, const Vec3& end_force, const Vec3& velocity,
                                              double elapsed) noexcept {
  return -0.5 * (start_force + end_force).dot(velocity) * elapsed;
}

/// The spring-alone Coulomb test (CoulombTest::spring, LIGGGHTS' tangential history): the spring
/// force F_s [N] scaled to `cap` [N] when |F_s| > cap, or empty while it holds (the dashpot is then
/// added uncapped).
[[nodiscard]] inline std::optional<Vec3> spring_over_cap(const Vec3& spring, double cap) noexcept {
  const double magnitude = spring.norm();
  if (!(magnitude > cap)) return std::nullopt;
  return Vec3(spring * (cap / magnitude));
}

/// Linear spring in parallel with a dashpot, in series with a Coulomb slider (thesis eq
/// 3.22–3.26; Cundall & Strack 1979). The stored displacement is ς = carried + v·elapsed
/// (`carried` is the committed displacement already in the current tangent plane; nothing is
/// accumulated in place) and the force on p is F = −k ς − γ v. When |F| > limit the force is
/// scaled back to `limit` along its own direction and the stored displacement truncated so that
/// the spring carries the capped force minus the unchanged dashpot part,
/// ς_new = −(F_capped + γ v)/k (LAMMPS pair granular rule; with γ = 0 this is k|ς_new| = limit).
/// When γ|v| > limit this leaves the spring pointing along the slip, as in LAMMPS.
/// With `zero_when_unloaded` (UnloadedSlider::zero) a slider whose displacement carried + v·elapsed
/// is exactly zero (|·| = 0) and whose dashpot alone exceeds the limit returns no force at all and
/// keeps the zero displacement (LAMMPS pair granular, fix wall/gran, gran/hooke/history).
/// Dissipation over `elapsed`: stuck, the dashpot's γ|v|² elapsed; sliding, the step's work
/// (sliding_step_work) minus the change of the spring energy ½k|ς|² (clamped at ≥ 0).
/// With `spring_test` (CoulombTest::spring, LIGGGHTS' tangential history) the spring force alone
/// is tested: when k|ς| > limit the force is the spring's scaled to the limit, without the dashpot,
/// and ς = −F/k; otherwise F = −k ς − γ v, which may exceed the limit.
/// stiffness k [N/m] ≥ 0 (k = 0 stores no displacement), damping γ [kg/s] ≥ 0, limit [N] ≥ 0,
/// displacements [m], v the relative velocity of the contact [m/s], elapsed [s].
[[nodiscard]] inline SpringSliderResult spring_slider(double stiffness, double damping,
                                                      double limit, const Vec3& carried,
                                                      const Vec3& velocity, double elapsed,
                                                      bool zero_when_unloaded, bool spring_test = false) noexcept {
  SpringSliderResult r;
  const Vec3 start = stiffness > 0.0 ? carried : Vec3::Zero();
  const Vec3 integrated = carried + velocity * elapsed;
  r.displacement = stiffness > 0.0 ? integrated : Vec3::Zero();
  if (spring_test) {
    const Vec3 spring = -stiffness * r.displacement;
    const std::optional<Vec3> capped = spring_over_cap(spring, std::max(limit, 0.0));
    if (!capped) {
      r.force = spring - damping * velocity;
      r.dissipated = damping * velocity.squaredNorm() * elapsed;
      return r;
    }
    r.sliding = true;
    r.force = *capped;
    r.displacement = -r.force / stiffness;  // |spring| > cap ≥ 0 needs k > 0
    const double work = sliding_step_work(-stiffness * start, r.force, velocity, elapsed);
    const double stored = 0.5 * stiffness * (r.displacement.squaredNorm() - start.squaredNorm());
    r.dissipated = std::max(work - stored, 0.0);
    return r;
  }
  r.force = -stiffness * r.displacement - damping * velocity;
  const double magnitude = r.force.norm();
  const double cap = std::max(limit, 0.0);
  if (!(magnitude > cap)) {
    r.dissipated = damping * velocity.squaredNorm() * elapsed;
    return r;
  }
  r.sliding = true;
  if (zero_when_unloaded && integrated.norm() == 0.0) {
    r.force = Vec3::Zero();
    return r;
  }
  r.force *= cap / magnitude;
  if (stiffness > 0.0) r.displacement = -(r.force + damping * velocity) / stiffness;
  const double work = sliding_step_work(-stiffness * start - damping * velocity, r.force, velocity, elapsed);
  const double stored = 0.5 * stiffness * (r.displacement.squaredNorm() - start.squaredNorm());
  r.dissipated = std::max(work - stored, 0.0);
  return r;
}

/// Energy of a linear spring of stiffness k [N/m] stretched by ς [m]: ½ k |ς|² [J].
[[nodiscard]] inline double spring_energy(double stiffness, const Vec3& displacement) noexcept {
  return 0.5 * stiffness * displacement.squaredNorm();
}

/// Energy of an incremental spring whose force history is F = −c σ (σ [m²], c the stiffness per
/// unit contact radius [N/m²]) at today's stiffness k = c a [N/m]: |c σ|²/(2k) [J] (YADE's
/// Hertz–Mindlin form; docs/physics.md "Energy ledger"); 0 for k ≤ 0.
[[nodiscard]] inline double incremental_spring_energy(double c, double stiffness, const Vec3& sigma) noexcept {
  return stiffness > 0.0 ? 0.5 * c * c * sigma.squaredNorm() / stiffness : 0.0;
}

}  // namespace dem::laws
