// SPDX-License-Identifier: MIT
#include "dem/forces/contact_batch.hpp"

#include <cmath>
#include <limits>

#include "dem/contact/laws/hertz.hpp"
#include "dem/contact/laws/linear_spring.hpp"
#include "dem/contact/laws/mindlin_stiffness.hpp"
#include "dem/contact/laws/nonlinear_dashpots.hpp"

namespace dem {
namespace {

// Every line below restates one step of pair_geometry and evaluate_contact_in (with
// LinearNormal or HertzNormal, LammpsMassVelocityDamping, SpringCoulombTangential, NoCohesion,
// NoRolling; or HertzNormal, TsujiDamping, Mindlin8GTangential in either form,
// NoCohesion, NoRolling) in the same operation order, so that each result is rounded exactly as there.
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

/// The pair geometry of one lane (pair_geometry's arithmetic). Fields filled by lane_geometry
/// one by one: a returned aggregate stops GCC vectorising the lane loop.
struct LaneGeometry {
  V3 normal;                ///< unit normal from q to p
  double overlap;           ///< δ [m]
  V3 branch_p, branch_q;    ///< centre-to-contact vectors [m]
  V3 tangential_velocity;   ///< [m/s]
  double normal_speed;      ///< contact velocity along the normal [m/s]
  double reduced_mass;      ///< m* [kg], ∞ between two fixed spheres
  double reduced_radius;    ///< R* = r_p r_q / (r_p + r_q) [m]
};

/// pair_geometry for lane g into `geo`; `arm_factor` ½ or 0 gives the lever arm r − δ/2 or r.
/// `RadiusVelocity` (PairLeverArm::radius_velocity): the contact-point velocity takes the radii
/// r, the torques the lever arms.
template <bool RadiusVelocity = false>
[[gnu::always_inline]] inline void lane_geometry(const ContactBatch& b, std::uint32_t g, double arm_factor,
                                                 LaneGeometry& geo) noexcept {
  const double rp = b.rp[g];
  const double rq = b.rq[g];
  const V3 x{b.dx[g], b.dy[g], b.dz[g]};
  const double distance = std::sqrt(dot(x, x));
  geo.normal = select(distance > 0.0, x / distance, V3{1.0, 0.0, 0.0});
  geo.overlap = rp + rq - distance;
  const double half = arm_factor * geo.overlap;
  geo.branch_p = -(rp - half) * geo.normal;
  geo.branch_q = (rq - half) * geo.normal;
  const V3 up{b.upx[g], b.upy[g], b.upz[g]};
  const V3 uq{b.uqx[g], b.uqy[g], b.uqz[g]};
  const V3 wp{b.wpx[g], b.wpy[g], b.wpz[g]};
  const V3 wq{b.wqx[g], b.wqy[g], b.wqz[g]};
  V3 contact_velocity;
  if constexpr (RadiusVelocity) {
    contact_velocity = (up - rp * cross(wp, geo.normal)) - (uq + rq * cross(wq, geo.normal));
  } else {
    contact_velocity = (up + cross(wp, geo.branch_p)) - (uq + cross(wq, geo.branch_q));
  }
  geo.normal_speed = dot(contact_velocity, geo.normal);
  geo.tangential_velocity = contact_velocity - geo.normal_speed * geo.normal;
  geo.reduced_mass = 1.0 / (b.mp[g] + b.mq[g]);
  geo.reduced_radius = rp * rq / (rp + rq);
}

/// The committed slip of lane g carried into the current tangent plane (carried_slip under
/// TangentialHistory::increment_project, or project_rescale).
template <bool IncrementProject>
[[gnu::always_inline]] inline V3 lane_carried_slip(const ContactBatch& b, std::uint32_t g, V3 normal) noexcept {
  const V3 slip{b.sx[g], b.sy[g], b.sz[g]};
  const double along = dot(slip, normal);
  const V3 projected = slip - along * normal;
  if constexpr (IncrementProject) return projected;
  const double projected_norm = std::sqrt(dot(projected, projected));
  const double slip_norm = std::sqrt(dot(slip, slip));
  const V3 rescaled = select(projected_norm > 0.0, projected * (slip_norm / projected_norm), V3{0.0, 0.0, 0.0});
  return select(along == 0.0, slip, rescaled);
}

/// Writes lane g's outputs: the assembled force on p (normal force along n plus friction), the
/// torques of the friction about both centres (NoRolling adds zero torques, kept for the sign of
/// zero) and the proposed slip.
[[gnu::always_inline]] inline void store_lane(ContactBatch& b, std::uint32_t g, const LaneGeometry& geo,
                                              double normal_force, V3 friction, V3 next_slip) noexcept {
  const V3 force = normal_force * geo.normal + friction;
  const V3 torque_p = cross(geo.branch_p, friction) + V3{0.0, 0.0, 0.0};
  const V3 torque_q = cross(geo.branch_q, -friction) + V3{0.0, 0.0, 0.0};
  b.overlap[g] = geo.overlap;
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

/// The yes/no policies as the numbers the lane loops read (see evaluate_lanes).
struct PolicyNumbers {
  double arm_factor;      ///< lever arm r − f δ: f = ½, or 0 under PairLeverArm::radius
  double basis_damping;   ///< Coulomb basis |F_e + d F_d|: d = 0 under FrictionLimit::elastic, else 1
  double clamp_below;     ///< the tensile clamp acts when F_e + F_d is below this: 0, or −∞ (never)
  double unloaded_below;  ///< |ς|² at or below this drops a capped force: 0 under UnloadedSlider::zero, −1 (never) else
};

/// The policies' numbers.
[[nodiscard]] inline PolicyNumbers policy_numbers(const BatchPolicies& p) noexcept {
  return {p.lever_arm_radius ? 0.0 : 0.5, p.limit_elastic ? 0.0 : 1.0,
          p.clamp_tensile ? 0.0 : -std::numeric_limits<double>::infinity(), p.zero_when_unloaded ? 0.0 : -1.0};
}

/// A lane's normal force, spring F_e plus dashpot −η u_n (the dashpot reduced to −F_e where the
/// clamp applies), and the Coulomb basis |F_e + d F_d| (evaluate_contact_in's order).
[[gnu::always_inline]] inline void normal_force_and_basis(double elastic, double eta, double normal_speed,
                                                          const PolicyNumbers& k, double& normal_force,
                                                          double& basis) noexcept {
  double damping = -eta * normal_speed;
  damping = elastic + damping < k.clamp_below ? -elastic : damping;
  normal_force = elastic + damping + 0.0;
  basis = std::abs(elastic + k.basis_damping * damping);
}

/// Coulomb's cap on a trial tangential force: `sliding` when |trial| exceeds the cap, `capped` the
/// trial scaled to the cap, `dropped` when UnloadedSlider::zero removes the force of a slider with
/// nothing stored (|ς|² = 0 exactly when |ς| = 0), `friction` the force that acts.
[[gnu::always_inline]] inline void coulomb_cap(V3 trial, V3 integrated, double cap, const PolicyNumbers& k,
                                               bool& sliding, bool& dropped, V3& capped, V3& friction) noexcept {
  const double magnitude = std::sqrt(dot(trial, trial));
  sliding = magnitude > cap;
  // `&`, not `&&`: a short circuit stops GCC vectorising the loop.
  dropped = sliding & (dot(integrated, integrated) <= k.unloaded_below);
  capped = trial * (cap / magnitude);
  friction = select(sliding, select(dropped, V3{0.0, 0.0, 0.0}, capped), trial);
}

/// The spring–Coulomb slider of one lane (laws::spring_slider's arithmetic): a spring k_t on the
/// slip ς = carried + u_t Δt (none stored when k_t = 0) and the dashpot η_t u_t, capped at `cap`;
/// `friction` the force that acts, `next_slip` the slip to commit (truncated when sliding).
[[gnu::always_inline]] inline void lane_spring_slider(double kt, double eta_t, V3 carried, V3 tangential_velocity,
                                                      double elapsed, double cap, const PolicyNumbers& k,
                                                      V3& friction, V3& next_slip) noexcept {
  const bool spring = kt > 0.0;
  const V3 integrated = carried + tangential_velocity * elapsed;
  const V3 stored = select(spring, integrated, V3{0.0, 0.0, 0.0});
  const V3 trial = -kt * stored - eta_t * tangential_velocity;
  bool sliding = false;
  bool dropped = false;
  V3 capped;
  coulomb_cap(trial, integrated, cap, k, sliding, dropped, capped, friction);
  const V3 truncated = -(capped + eta_t * tangential_velocity) / kt;
  next_slip = select(sliding && spring && !dropped, truncated, stored);
}

/// The loop over lanes for one normal law and one tangential-history rule. The other policies
/// enter as numbers, so that no select depends on a condition that is the same for every lane
/// (which the vectoriser cannot mask): the lever arm r − f δ with f = ½ or 0 (exactly r − δ/2,
/// or r), the Coulomb basis |F_e + d F_d| with d = 1 or 0, the tensile clamp as F_e + F_d below
/// 0 or below −∞ (never), the unloaded-slider drop as |ς| ≤ 0 or ≤ −1 (never).
template <BatchLawKind Normal, bool IncrementProject>
[[gnu::always_inline]] inline void evaluate_lanes(ContactBatch& b, std::uint32_t n, const BatchPolicies& p,
                                                  double elapsed) noexcept {
  const PolicyNumbers k = policy_numbers(p);
  for (std::uint32_t g = 0; g < n; ++g) {
    const double k_normal = b.normal[g];
    const double rate = b.rate[g];
    const double kt = b.kt[g];
    const double mu = b.mu[g];
    const double ratio = b.ratio[g];
    LaneGeometry geo;
    lane_geometry(b, g, k.arm_factor, geo);
    const double overlap = geo.overlap;

    // Normal spring (zero force where the lane is not in contact; such lanes are discarded).
    double elastic = 0.0;
    if constexpr (Normal == BatchLawKind::linear) {
      elastic = laws::linear_spring_force(k_normal, overlap);
    } else {
      elastic = laws::hertz_force(k_normal, geo.reduced_radius, overlap);
    }
    // Mass-scaled dashpot; none between two fixed spheres (m* = ∞).
    const double eta = std::isfinite(geo.reduced_mass) ? rate * geo.reduced_mass : 0.0;
    double normal_force = 0.0;
    double basis = 0.0;
    normal_force_and_basis(elastic, eta, geo.normal_speed, k, normal_force, basis);

    // Spring–Coulomb friction on the slip carried into the tangent plane.
    const V3 carried = lane_carried_slip<IncrementProject>(b, g, geo.normal);
    const V3 tangential_velocity = geo.tangential_velocity;
    const double eta_t = ratio * eta;
    const double limit = mu * basis;
    const double cap = limit < 0.0 ? 0.0 : limit;
    // UnloadedSlider::zero: a capped slider with nothing stored gives no force and keeps ς = 0.
    V3 friction;
    V3 next_slip;
    lane_spring_slider(kt, eta_t, carried, tangential_velocity, elapsed, cap, k, friction, next_slip);
    store_lane(b, g, geo, normal_force, friction, next_slip);
  }
}

/// The loop over lanes for Hertz with Tsuji's dashpot and Mindlin friction (the arithmetic of
/// HertzNormal, TsujiDamping and incremental_mindlin_response, or under `Total` of
/// total_mindlin_response), for one tangential-history rule and one contact-velocity rule
/// (lane_geometry); the other policies enter as numbers, as in evaluate_lanes.
template <bool IncrementProject, bool RadiusVelocity, bool Total>
[[gnu::always_inline]] inline void evaluate_mindlin_lanes(ContactBatch& b, std::uint32_t n, const BatchPolicies& p,
                                                          double elapsed) noexcept {
  const PolicyNumbers k = policy_numbers(p);
  for (std::uint32_t g = 0; g < n; ++g) {
    const double modulus = b.normal[g];
    const double alpha = b.rate[g];
    const double c = b.kt[g];
    const double mu = b.mu[g];
    const double ratio = b.ratio[g];
    LaneGeometry geo;
    lane_geometry<RadiusVelocity>(b, g, k.arm_factor, geo);
    const double overlap = geo.overlap;
    const double reduced_radius = geo.reduced_radius;

    // Hertz spring and its tangent stiffness (both zero out of contact).
    const double elastic = laws::hertz_force(modulus, reduced_radius, overlap);
    const double tangent = laws::hertz_stiffness(modulus, reduced_radius, overlap);
    // Tsuji's dashpot on the secant stiffness F/δ; none between two fixed spheres (m* = ∞).
    const double secant = laws::secant_stiffness(elastic, overlap, tangent);
    const double coefficient = laws::tsuji_damping_coefficient(alpha, geo.reduced_mass, secant);
    const double eta = std::isfinite(geo.reduced_mass) ? coefficient : 0.0;
    double normal_force = 0.0;
    double basis = 0.0;
    normal_force_and_basis(elastic, eta, geo.normal_speed, k, normal_force, basis);

    const double a = laws::mindlin_contact_radius(reduced_radius, overlap);
    const V3 tangential_velocity = geo.tangential_velocity;
    const V3 start = lane_carried_slip<IncrementProject>(b, g, geo.normal);
    const double eta_t = ratio * eta;
    const double limit = mu * basis;
    const double cap = limit < 0.0 ? 0.0 : limit;
    V3 friction;
    V3 next_slip;
    if constexpr (Total) {
      // Total form: the spring–Coulomb slider at k_t = c a on the whole slip ς ← ς + u_t Δt
      // (c a is 8 G* a to the bit, since c = 8 G* · 1).
      lane_spring_slider(c * a, eta_t, start, tangential_velocity, elapsed, cap, k, friction, next_slip);
    } else {
      // Incremental: σ ← σ + a u_t Δt at the contact radius a = √(R* δ), F = −c σ − η_t u_t.
      bool sliding = false;
      bool dropped = false;
      V3 capped;
      const V3 integrated = start + (a * elapsed) * tangential_velocity;
      const V3 trial = -c * integrated - eta_t * tangential_velocity;
      coulomb_cap(trial, integrated, cap, k, sliding, dropped, capped, friction);
      const V3 truncated = select(c > 0.0, -(capped + eta_t * tangential_velocity) / c, V3{0.0, 0.0, 0.0});
      next_slip = select(sliding & !dropped, truncated, integrated);
    }
    store_lane(b, g, geo, normal_force, friction, next_slip);
  }
}

/// The Mindlin lane loop of one form, chosen by the history and contact-velocity rules.
template <bool Total>
[[gnu::always_inline]] inline void evaluate_mindlin_form(ContactBatch& batch, std::uint32_t n,
                                                         const BatchPolicies& policies, double elapsed) noexcept {
  if (policies.increment_project) {
    if (policies.radius_velocity) {
      evaluate_mindlin_lanes<true, true, Total>(batch, n, policies, elapsed);
    } else {
      evaluate_mindlin_lanes<true, false, Total>(batch, n, policies, elapsed);
    }
  } else if (policies.radius_velocity) {
    evaluate_mindlin_lanes<false, true, Total>(batch, n, policies, elapsed);
  } else {
    evaluate_mindlin_lanes<false, false, Total>(batch, n, policies, elapsed);
  }
}

}  // namespace

// One clone for AVX2 (four lanes per instruction), one for the baseline instruction set; the
// loader picks by the processor it runs on.
[[gnu::target_clones("avx2", "default")]] void evaluate_contact_batch(ContactBatch& batch, std::uint32_t n,
                                                                      const BatchPolicies& policies,
                                                                      double elapsed) noexcept {
  if (policies.kind == BatchLawKind::hertz_mindlin) {
    if (policies.mindlin_total) {
      evaluate_mindlin_form<true>(batch, n, policies, elapsed);
    } else {
      evaluate_mindlin_form<false>(batch, n, policies, elapsed);
    }
    return;
  }
  const bool linear = policies.kind == BatchLawKind::linear;
  if (policies.increment_project) {
    if (linear) {
      evaluate_lanes<BatchLawKind::linear, true>(batch, n, policies, elapsed);
    } else {
      evaluate_lanes<BatchLawKind::hertz, true>(batch, n, policies, elapsed);
    }
  } else if (linear) {
    evaluate_lanes<BatchLawKind::linear, false>(batch, n, policies, elapsed);
  } else {
    evaluate_lanes<BatchLawKind::hertz, false>(batch, n, policies, elapsed);
  }
}

}  // namespace dem
