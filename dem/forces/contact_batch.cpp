// SPDX-License-Identifier: MIT
#include "dem/forces/contact_batch.hpp"

#include <cmath>
#include <limits>

#include "dem/contact/laws/hertz.hpp"
#include "dem/contact/laws/linear_spring.hpp"

namespace dem {
namespace {

// Every line below restates one step of pair_geometry and evaluate_contact_in (with
// LinearNormal or HertzNormal, LammpsMassVelocityDamping, SpringCoulombTangential, NoCohesion,
// NoRolling) in the same operation order, so that each result is rounded exactly as there.
// Branches become selects: a lane computes both sides and keeps one, which is what lets the
// compiler evaluate four lanes per instruction. No fused multiply–add: the file is compiled
// with -ffp-contract=off, and the AVX2 clone does not enable FMA.

/// A lane's 3-vector.
struct V3 {
  double x, y, z;
};
[[gnu::always_inline]] inline V3 operator+(V3 a, V3 b) noexcept { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
[[gnu::always_inline]] inline V3 operator-(V3 a, V3 b) noexcept { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
[[gnu::always_inline]] inline V3 operator-(V3 a) noexcept { return {-a.x, -a.y, -a.z}; }
[[gnu::always_inline]] inline V3 operator*(double s, V3 a) noexcept { return {s * a.x, s * a.y, s * a.z}; }
[[gnu::always_inline]] inline V3 operator*(V3 a, double s) noexcept { return {a.x * s, a.y * s, a.z * s}; }
[[gnu::always_inline]] inline V3 operator/(V3 a, double s) noexcept { return {a.x / s, a.y / s, a.z / s}; }
/// (a·b) summed left to right, as Eigen's fixed-size dot.
[[gnu::always_inline]] inline double dot(V3 a, V3 b) noexcept { return a.x * b.x + a.y * b.y + a.z * b.z; }
[[gnu::always_inline]] inline V3 cross(V3 a, V3 b) noexcept {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
[[gnu::always_inline]] inline V3 select(bool c, V3 a, V3 b) noexcept {
  return {c ? a.x : b.x, c ? a.y : b.y, c ? a.z : b.z};
}

/// The loop over lanes for one normal law and one tangential-history rule. The other policies
/// enter as numbers, so that no select depends on a condition that is the same for every lane
/// (which the vectoriser cannot mask): the lever arm r − f δ with f = ½ or 0 (exactly r − δ/2,
/// or r), the Coulomb basis |F_e + d F_d| with d = 1 or 0, the tensile clamp as F_e + F_d below
/// 0 or below −∞ (never), the unloaded-slider drop as |ς| ≤ 0 or ≤ −1 (never).
template <BatchNormal Normal, bool IncrementProject>
[[gnu::always_inline]] inline void evaluate_lanes(ContactBatch& b, std::uint32_t n, const BatchPolicies& p,
                                                  double elapsed) noexcept {
  const double arm_factor = p.lever_arm_radius ? 0.0 : 0.5;
  const double basis_damping = p.limit_elastic ? 0.0 : 1.0;
  const double clamp_below = p.clamp_tensile ? 0.0 : -std::numeric_limits<double>::infinity();
  // |ς|² at or below this drops a capped force: 0 under UnloadedSlider::zero, never (−1) else.
  const double unloaded_below = p.zero_when_unloaded ? 0.0 : -1.0;
  for (std::uint32_t g = 0; g < n; ++g) {
    const double k_normal = b.normal[g];
    const double rate = b.rate[g];
    const double kt = b.kt[g];
    const double mu = b.mu[g];
    const double ratio = b.ratio[g];
    const double rp = b.rp[g];
    const double rq = b.rq[g];

    // pair_geometry.
    const V3 x{b.dx[g], b.dy[g], b.dz[g]};
    const double distance = std::sqrt(dot(x, x));
    const V3 normal = select(distance > 0.0, x / distance, V3{1.0, 0.0, 0.0});
    const double overlap = rp + rq - distance;
    const double half = arm_factor * overlap;
    const V3 branch_p = -(rp - half) * normal;
    const V3 branch_q = (rq - half) * normal;
    const V3 up{b.upx[g], b.upy[g], b.upz[g]};
    const V3 uq{b.uqx[g], b.uqy[g], b.uqz[g]};
    const V3 wp{b.wpx[g], b.wpy[g], b.wpz[g]};
    const V3 wq{b.wqx[g], b.wqy[g], b.wqz[g]};
    const V3 contact_velocity = (up + cross(wp, branch_p)) - (uq + cross(wq, branch_q));
    const double normal_speed = dot(contact_velocity, normal);
    const V3 tangential_velocity = contact_velocity - normal_speed * normal;
    const double reduced_mass = 1.0 / (b.mp[g] + b.mq[g]);

    // Normal spring (zero force where the lane is not in contact; such lanes are discarded).
    double elastic = 0.0;
    if constexpr (Normal == BatchNormal::linear) {
      elastic = laws::linear_spring_force(k_normal, overlap);
    } else {
      elastic = laws::hertz_force(k_normal, rp * rq / (rp + rq), overlap);
    }
    // Mass-scaled dashpot; none between two fixed spheres (m* = ∞).
    const double eta = std::isfinite(reduced_mass) ? rate * reduced_mass : 0.0;
    double damping = -eta * normal_speed;
    damping = elastic + damping < clamp_below ? -elastic : damping;
    const double normal_force = elastic + damping + 0.0;
    const double basis = std::abs(elastic + basis_damping * damping);

    // Spring–Coulomb friction on the slip carried into the tangent plane.
    const V3 slip{b.sx[g], b.sy[g], b.sz[g]};
    const double along = dot(slip, normal);
    const V3 projected = slip - along * normal;
    const double projected_norm = std::sqrt(dot(projected, projected));
    const double slip_norm = std::sqrt(dot(slip, slip));
    const V3 rescaled = select(projected_norm > 0.0, projected * (slip_norm / projected_norm), V3{0.0, 0.0, 0.0});
    V3 carried = projected;
    if constexpr (!IncrementProject) carried = select(along == 0.0, slip, rescaled);
    const double eta_t = ratio * eta;
    const double limit = mu * basis;
    const bool spring = kt > 0.0;
    const V3 integrated = carried + tangential_velocity * elapsed;
    const V3 stored = select(spring, integrated, V3{0.0, 0.0, 0.0});
    const V3 trial = -kt * stored - eta_t * tangential_velocity;
    const double magnitude = std::sqrt(dot(trial, trial));
    const double cap = limit < 0.0 ? 0.0 : limit;
    const bool sliding = magnitude > cap;
    // UnloadedSlider::zero: a capped slider with nothing stored gives no force and keeps ς = 0.
    // |ς|² = 0 exactly when |ς| = 0. `&`, not `&&`: a short circuit stops GCC vectorising the loop.
    const bool dropped = sliding & (dot(integrated, integrated) <= unloaded_below);
    const V3 capped = trial * (cap / magnitude);
    const V3 friction = select(sliding, select(dropped, V3{0.0, 0.0, 0.0}, capped), trial);
    const V3 truncated = -(capped + eta_t * tangential_velocity) / kt;
    const V3 next_slip = select(sliding && spring && !dropped, truncated, stored);

    // Assembly (NoRolling adds zero torques, kept for the sign of zero).
    const V3 force = normal_force * normal + friction;
    const V3 torque_p = cross(branch_p, friction) + V3{0.0, 0.0, 0.0};
    const V3 torque_q = cross(branch_q, -friction) + V3{0.0, 0.0, 0.0};
    b.overlap[g] = overlap;
    b.fx[g] = force.x;
    b.fy[g] = force.y;
    b.fz[g] = force.z;
    b.tpx[g] = torque_p.x;
    b.tpy[g] = torque_p.y;
    b.tpz[g] = torque_p.z;
    b.tqx[g] = torque_q.x;
    b.tqy[g] = torque_q.y;
    b.tqz[g] = torque_q.z;
    b.sx[g] = next_slip.x;
    b.sy[g] = next_slip.y;
    b.sz[g] = next_slip.z;
  }
}

}  // namespace

// One clone for AVX2 (four lanes per instruction), one for the baseline instruction set; the
// loader picks by the processor it runs on.
[[gnu::target_clones("avx2", "default")]] void evaluate_contact_batch(ContactBatch& batch, std::uint32_t n,
                                                                      const BatchPolicies& policies,
                                                                      double elapsed) noexcept {
  const bool linear = policies.normal == BatchNormal::linear;
  if (policies.increment_project) {
    if (linear) {
      evaluate_lanes<BatchNormal::linear, true>(batch, n, policies, elapsed);
    } else {
      evaluate_lanes<BatchNormal::hertz, true>(batch, n, policies, elapsed);
    }
  } else if (linear) {
    evaluate_lanes<BatchNormal::linear, false>(batch, n, policies, elapsed);
  } else {
    evaluate_lanes<BatchNormal::hertz, false>(batch, n, policies, elapsed);
  }
}

}  // namespace dem
