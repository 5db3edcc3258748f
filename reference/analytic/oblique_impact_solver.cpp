// SPDX-License-Identifier: MIT
#include "reference/analytic/oblique_impact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include <boost/math/quadrature/gauss.hpp>
#include <fmt/format.h>

#include "cases/time_step.hpp"
#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/core/vector.hpp"
#include "reference/analytic/collinear_solver.hpp"
#include "reference/analytic/linear_oscillator.hpp"
#include "reference/analytic/vector3_math.hpp"
#include "reference/common/core_setup.hpp"
#include "reference/analytic/model_support.hpp"

namespace reference::analytic {
namespace {

using dem::Vec3;


/// Grid points per contact for the gross-sliding and spring-following checks.
constexpr int kCheckPoints = 4000;
/// ∫_a^b f by 30-point Gauss–Legendre quadrature. The integrands are exponentials times sines
/// of the contact's damped frequency ω_d, smooth on each piece; on an interval of ω_d-phase ≤ π
/// the rule's error is below 1e-80 relative (degree-59 exactness), so the result is exact to
/// rounding. Callers keep intervals within one contact piece.
template <class F>
double integrate(const F& f, double a, double b) {
  if (!(b > a)) return 0.0;
  return boost::math::quadrature::gauss<double, 30>::integrate(f, a, b);
}

/// Exact state of the sphere at one instant.
struct SphereState {
  Vec3 position;
  Vec3 velocity;
  Vec3 spin;
  Vec3 force;           ///< total force on the sphere [N]
  double overlap;       ///< r − distance to the wall [m]
  double normal_force;  ///< contact normal force [N] (0 out of contact)
};

/// The impact: closed-form normal motion, tangential impulse and moment by quadrature.
class GrossSlidingImpact {
 public:
  explicit GrossSlidingImpact(const SphereWallScene& s)
      : s_(s),
        n_(core_vec(s.normal)),
        x0_(core_vec(s.position)),
        v0_(core_vec(s.velocity)),
        w0_(core_vec(s.spin)),
        approach_(-v0_.dot(n_)),
        normal_(s.mass, s.damping, s.stiffness, 0.0, approach_) {
    const double distance = (x0_ - core_vec(s.wall_point)).dot(n_);
    distance0_ = distance;
    start_ = (distance - s.radius) / approach_;
    duration_ = dem::laws::linear_contact_duration(s.stiffness, s.mass, s.damping);
    const double decay = s.damping / (2.0 * s.mass);
    frequency_ = std::sqrt(s.stiffness / s.mass - decay * decay);
    kink_ = duration_;
    if (s.damping > 0.0 && s.limit != dem::FrictionLimit::elastic) {
      kink_ = (std::numbers::pi - std::atan2(s.damping * frequency_, s.stiffness - s.damping * decay)) /
              frequency_;
    }
    const Vec3 u0 = tangential_velocity0() - s.radius * w0_.cross(n_);
    slip0_ = u0.norm();
    if (slip0_ > 0.0 && s.friction > 0.0) {
      direction_ = u0 / slip0_;
      mu_ = s.friction;
    }
    end_ = in_contact(duration_, integrals(duration_), true);
  }

  [[nodiscard]] double start() const noexcept { return start_; }
  [[nodiscard]] double duration() const noexcept { return duration_; }
  [[nodiscard]] double approach_speed() const noexcept { return approach_; }
  [[nodiscard]] double initial_slip() const noexcept { return slip0_; }
  [[nodiscard]] const Vec3& slip_direction() const noexcept { return direction_; }
  [[nodiscard]] double friction() const noexcept { return mu_; }
  [[nodiscard]] const Vec3& normal() const noexcept { return n_; }
  /// State at the end of the contact (free flight follows).
  [[nodiscard]] const SphereState& end_state() const noexcept { return end_; }

  /// Overlap and its rate τ after the contact starts.
  [[nodiscard]] AxisKinematics overlap(double tau) const noexcept { return normal_.at(tau); }
  /// Normal force k δ + η δ' [N].
  [[nodiscard]] double normal_force(double tau) const noexcept {
    const AxisKinematics k = normal_.at(tau);
    return s_.stiffness * k.position + s_.damping * k.velocity;
  }
  /// The friction-limit basis (|F_n| or k δ).
  [[nodiscard]] double basis(double tau) const noexcept {
    if (s_.limit == dem::FrictionLimit::elastic) return s_.stiffness * normal_.at(tau).position;
    return std::abs(normal_force(tau));
  }
  /// Its rate of change d basis/dτ.
  [[nodiscard]] double basis_rate(double tau) const noexcept {
    const AxisKinematics k = normal_.at(tau);
    if (s_.limit == dem::FrictionLimit::elastic) return s_.stiffness * k.velocity;
    const double rate = s_.stiffness * k.velocity + s_.damping * k.acceleration;
    return normal_force(tau) >= 0.0 ? rate : -rate;
  }
  /// Largest friction-limit basis over the contact, and whether it falls on the first instant
  /// (where a spring_coulomb spring has not yet stretched to μ·basis). With β = η/(2m),
  /// F(τ) = (v/ω) e^{−βτ} [(k − ηβ) sin ωτ + ηω cos ωτ] is stationary where ωτ + φ = atan2(ω, β)
  /// (its peak; + π for its tensile extreme), φ = atan2(ηω, k − ηβ); k δ peaks at ωτ = atan2(ω, β).
  struct Peak {
    double basis = 0.0;
    bool at_start = false;
  };
  [[nodiscard]] Peak largest_basis() const {
    const double decay = s_.damping / (2.0 * s_.mass);
    const double w = frequency_;
    const double phi = std::atan2(s_.damping * w, s_.stiffness - s_.damping * decay);
    const double rise = std::atan2(w, decay);
    Peak p{basis(0.0), true};
    for (const double tau : {(rise - phi) / w, (rise - phi + std::numbers::pi) / w, rise / w}) {
      const double b = basis(std::clamp(tau, 0.0, duration_));
      if (b > p.basis) p = {b, false};
    }
    return p;
  }
  /// Lever arm of the friction force about the centre.
  [[nodiscard]] double lever(double tau) const noexcept {
    return s_.lever_is_radius ? s_.radius : s_.radius - 0.5 * normal_.at(tau).position;
  }
  /// ∫_a^b g(τ) B(τ) dτ, split where the total normal force changes sign.
  template <class G>
  [[nodiscard]] double weighted(const G& g, double a, double b) const {
    const auto f = [&](double t) { return g(t) * basis(t); };
    if (kink_ > a && kink_ < b) return integrate(f, a, kink_) + integrate(f, kink_, b);
    return integrate(f, a, b);
  }

  /// Tangential impulse, moment and doubly-integrated impulse from the contact start to τ.
  struct Integrals {
    double upto = 0.0;     ///< τ they reach
    double impulse = 0.0;  ///< J = ∫ B
    double moment = 0.0;   ///< K = ∫ ℓ B
    double first = 0.0;    ///< M = ∫ s B(s) ds; the displacement integral is τ J − M
  };
  /// Advances the integrals to τ (≥ their current end).
  void advance(Integrals& i, double tau) const {
    if (mu_ != 0.0 && tau > i.upto) {
      i.impulse += weighted([](double) { return 1.0; }, i.upto, tau);
      i.moment += weighted([&](double t) { return lever(t); }, i.upto, tau);
      i.first += weighted([](double t) { return t; }, i.upto, tau);
    }
    i.upto = std::max(i.upto, tau);
  }
  [[nodiscard]] Integrals integrals(double tau) const {
    Integrals i;
    advance(i, tau);
    return i;
  }

  /// The state at contact time τ ∈ [0, duration] from the integrals up to τ.
  [[nodiscard]] SphereState in_contact(double tau, const Integrals& i, bool ended) const {
    const AxisKinematics k = normal_.at(tau);
    const double delta = ended ? 0.0 : k.position;
    const double t = start_ + tau;
    SphereState out;
    const double free_height = distance0_ - approach_ * t;
    out.position = x0_ + v0_ * t + ((s_.radius - delta) - free_height) * n_ -
                   (mu_ / s_.mass) * (tau * i.impulse - i.first) * direction_;
    out.velocity = tangential_velocity0() - k.velocity * n_ - (mu_ / s_.mass) * i.impulse * direction_;
    out.spin = w0_ + mu_ * i.moment * s_.inverse_inertia * n_.cross(direction_);
    out.overlap = delta;
    out.normal_force = ended ? 0.0 : s_.stiffness * k.position + s_.damping * k.velocity;
    out.force = ended ? Vec3::Zero() : Vec3(out.normal_force * n_ - mu_ * basis(tau) * direction_);
    return out;
  }

  /// State at time t of the run; `running` carries the integrals between calls at increasing t.
  [[nodiscard]] SphereState at(double t, Integrals& running) const {
    if (t <= start_) {
      SphereState out{x0_ + v0_ * t, v0_, w0_, Vec3::Zero(), 0.0, 0.0};
      out.overlap = s_.radius - (distance0_ - approach_ * t);
      return out;
    }
    const double tau = t - start_;
    if (tau < duration_) {
      if (tau < running.upto) running = Integrals{};
      advance(running, tau);
      return in_contact(tau, running, false);
    }
    SphereState end = end_;
    const double flight = tau - duration_;
    end.position += end.velocity * flight;
    end.overlap = -end.velocity.dot(n_) * flight;
    return end;
  }
  /// State at time t of the run.
  [[nodiscard]] SphereState at(double t) const {
    Integrals fresh;
    return at(t, fresh);
  }

  /// Slip speed along the slip direction at contact time τ given the integrals.
  [[nodiscard]] double slip_speed(double tau, const Integrals& i) const {
    const SphereState st = in_contact(tau, i, false);
    const Vec3 u = st.velocity - lever(tau) * st.spin.cross(n_);
    return (u - u.dot(n_) * n_).dot(direction_);
  }

  /// Smallest slip speed over the contact and where it occurs; spring-following shortfall.
  struct Check {
    double min_slip = 0.0;
    double min_slip_time = 0.0;
    double lagging_time = 0.0;    ///< time the spring cannot keep up with a growing cap [s]
    double initial_phase = 0.0;   ///< duration of the initial spring phase [s]
    double initial_deficit = 0.0; ///< tangential impulse that phase withholds, estimate [N s]
  };
  [[nodiscard]] Check check() const {
    Check c;
    c.min_slip = slip0_;
    if (mu_ == 0.0) return c;
    Integrals acc;
    const double h = duration_ / kCheckPoints;
    for (int k = 1; k <= kCheckPoints; ++k) {
      const double b = k * h;
      advance(acc, b);
      const double u = slip_speed(b, acc);
      if (u < c.min_slip) {
        c.min_slip = u;
        c.min_slip_time = b;
      }
      if (s_.tangential_stiffness > 0.0 &&
          u < mu_ * basis_rate(b) / s_.tangential_stiffness) {
        c.lagging_time += h;
      }
    }
    const double jump = basis(0.0);
    if (s_.tangential_stiffness > 0.0 && jump > 0.0) {
      c.initial_phase = mu_ * jump / (s_.tangential_stiffness * slip0_);
      c.initial_deficit = 0.5 * mu_ * jump * c.initial_phase;
    }
    return c;
  }

 private:
  [[nodiscard]] Vec3 tangential_velocity0() const { return v0_ - v0_.dot(n_) * n_; }

  SphereWallScene s_;
  Vec3 n_, x0_, v0_, w0_;
  double approach_;
  LinearOscillator normal_;
  double distance0_ = 0.0;
  double start_ = 0.0;
  double duration_ = 0.0;
  double frequency_ = 0.0;
  double kink_ = 0.0;
  double slip0_ = 0.0;
  double mu_ = 0.0;
  Vec3 direction_ = Vec3::Zero();
  SphereState end_{};
};

/// Appends the state at time t as one trace row (cases::trace_layout order).
void record(const cases::Scene& scene, const SphereWallScene& s, const SphereState& st, double t,
            cases::Trace& trace) {
  std::vector<double> row{t};
  for (const std::size_t i : scene.output.trace_particles) {
    static_cast<void>(i);  // the only particle
    for (const Vec3* v : {&st.position, &st.velocity, &st.spin, &st.force}) {
      row.insert(row.end(), {v->x(), v->y(), v->z()});
    }
  }
  for (const auto& [p, w] : scene.output.trace_walls) {
    static_cast<void>(p);
    const bool compared = w == s.wall;
    row.push_back(compared ? st.overlap : 0.0);
    row.push_back(compared ? st.normal_force : 0.0);
  }
  trace.append_row(row);
}

/// Metrics of the impact in closed form, by the definitions of compare/metrics_motion.
void add_exact_metrics(const GrossSlidingImpact& impact, const SphereWallScene& s,
                       cases::RunResult& result) {
  const double decay = s.damping / (2.0 * s.mass);
  const double frequency = std::sqrt(s.stiffness / s.mass - decay * decay);
  const SphereState& end = impact.end_state();
  const Vec3& n = impact.normal();
  result.exact_metrics["contact_duration"] = impact.duration();
  result.exact_metrics["restitution"] = end.velocity.dot(n) / impact.approach_speed();
  result.exact_metrics["max_overlap"] =
      impact.overlap(std::atan2(frequency, decay) / frequency).position;
  for (int k = 0; k < 3; ++k) {
    const std::string axis(1, static_cast<char>('x' + k));
    result.exact_metrics["velocity_after_" + axis] = end.velocity[k];
    result.exact_metrics["angular_velocity_after_" + axis] = end.spin[k];
  }
  const Vec3 v_t = end.velocity - end.velocity.dot(n) * n;
  result.exact_metrics["rebound_angle"] =
      std::atan2(v_t.norm(), end.velocity.dot(n)) * 180.0 / std::numbers::pi;
  if (impact.initial_slip() > 0.0) {
    const Vec3 x0 = core_vec(s.velocity) - core_vec(s.velocity).dot(n) * n - s.radius * core_vec(s.spin).cross(n);
    const Vec3 t_hat = x0 / x0.norm();
    const Vec3 u_after = v_t - s.radius * end.spin.cross(n);
    result.exact_metrics["tangential_restitution"] = -u_after.dot(t_hat) / x0.norm();
    result.exact_metrics["spin_after"] = end.spin.dot(t_hat.cross(-n));
    // Gross sliding: |F_t| = μ·basis throughout, except where the spring is still stretching at
    // the first instant; a peak there is left to the trace.
    if (const auto peak = impact.largest_basis(); !peak.at_start) {
      result.exact_metrics["tangential_force_max"] = impact.friction() * peak.basis;
    }
  }
}

/// Rotation of the case in the analytic solution's terms.
double inverse_inertia(const cases::Scene& scene, double mass, double radius) {
  return scene.integration.rotation ? 1.0 / (0.4 * mass * radius * radius) : 0.0;
}

}  // namespace

std::vector<std::string> sphere_wall_reasons(const PreparedScene& prepared, std::string_view solver) {
  const cases::Scene& scene = prepared.scene();
  std::vector<std::string> reasons;
  const auto reason = [&](const std::string& why) {
    reasons.push_back(fmt::format("analytic ({}): {}", solver, why));
  };
  // A linear spring with no or a restitution dashpot, not clamped, spring–Coulomb friction whose
  // slip velocity and torque use r − δ/2 or r (not YADE's α-scaled increment).
  ModelSupport model{solver, {"linear"}, {"none", "restitution"}, {"none", "spring_coulomb"}, {"none"}, {"none"}};
  model.wall_lever_arm = {dem::WallLeverArm::contact_point, dem::WallLeverArm::radius};
  reasons = model_reasons(scene.model, model);
  if (scene.particles.size() != 1) {
    reason(fmt::format("{} particles; one mobile sphere against one wall is solved", scene.particles.size()));
  } else {
    const cases::ParticleSpec& p = scene.particles.front();
    if (p.fixed) reason("the only particle is fixed");
    if (!p.motion.empty()) reason("the particle has a prescribed motion");
    if (p.charge != 0.0) reason("the particle is charged");
  }
  if (scene.walls.size() != 1) {
    reason(fmt::format("{} walls; exactly one plane wall is solved", scene.walls.size()));
  } else {
    const auto& v = scene.walls.front().velocity;
    if (v[0] != 0.0 || v[1] != 0.0 || v[2] != 0.0) reason("the wall moves");
  }
  if (scene.fluid) reason("a fluid (drag, buoyancy) has no closed form here");
  if (!reasons.empty()) return reasons;
  try {
    const dem::PairTable& table = prepared.pair_table();
    static_cast<void>(table);
  } catch (const std::exception& e) {
    reason(e.what());
  }
  return reasons;
}

SphereWallScene sphere_wall_scene(const PreparedScene& prepared) {
  const cases::Scene& scene = prepared.scene();
  const cases::ParticleSpec& p = scene.particles.front();
  const cases::WallSpec& w = scene.walls.front();
  const dem::PairTable& table = prepared.pair_table();
  const dem::PairProperties& pair = table.properties(p.material, w.material);
  SphereWallScene s;
  s.radius = p.radius;
  s.mass = 4.0 / 3.0 * std::numbers::pi * scene.materials.at(p.material).density * std::pow(p.radius, 3);
  s.inverse_inertia = inverse_inertia(scene, s.mass, s.radius);
  s.position = p.position;
  s.velocity = p.velocity;
  s.spin = p.angular_velocity;
  s.wall_point = w.point;
  s.normal = w.normal;
  s.wall = 0;
  s.stiffness = *pair.normal_stiffness;
  if (scene.model.damping == "restitution") {
    s.damping = dem::laws::restitution_damping_coefficient(*pair.restitution, s.mass, s.stiffness);
  }
  if (scene.model.tangential == "spring_coulomb") {
    s.friction = *pair.friction;
    s.tangential_stiffness = *pair.tangential_stiffness;
  }
  s.limit = scene.model.friction_limit;
  s.lever_is_radius = scene.model.wall_lever_arm == dem::WallLeverArm::radius;
  return s;
}

std::vector<std::string> ObliqueImpactSolver::unsupported_reasons(const PreparedScene& prepared) const {
  const cases::Scene& scene = prepared.scene();
  constexpr std::string_view who = "oblique impact";
  std::vector<std::string> reasons = sphere_wall_reasons(prepared, who);
  const auto reason = [&](const std::string& why) {
    reasons.push_back(fmt::format("analytic ({}): {}", who, why));
  };
  const auto& g = scene.gravity;
  if (g[0] != 0.0 || g[1] != 0.0 || g[2] != 0.0) reason("gravity must be zero (a free impact)");
  if (!reasons.empty()) return reasons;
  const SphereWallScene s = sphere_wall_scene(prepared);
  const Vec3 n = core_vec(s.normal);
  const double distance = (core_vec(s.position) - core_vec(s.wall_point)).dot(n);
  if (!(distance >= s.radius)) reason("the sphere must start clear of the wall (δ ≤ 0)");
  if (!(-core_vec(s.velocity).dot(n) > 0.0)) reason("the sphere does not approach the wall");
  if (!reasons.empty()) return reasons;
  const GrossSlidingImpact impact(s);
  if (impact.friction() > 0.0 && !s.lever_is_radius) {
    const Vec3 w_n = core_vec(s.spin).cross(n);
    const Vec3 off = w_n - w_n.dot(impact.slip_direction()) * impact.slip_direction();
    if (off.norm() > 1e-12 * (w_n.norm() + 1e-300)) {
      reason("the initial spin turns the slip direction while the lever r − δ/2 changes; only "
             "spins about t × n (or wall_lever_arm = \"radius\") keep it fixed");
      return reasons;
    }
  }
  const auto c = impact.check();
  if (c.min_slip <= 0.0) {
    reason(fmt::format("the slip stops at {:.4g} s into the contact (of {:.4g} s): the contact "
                       "sticks, and only gross sliding has a closed form (solid sphere: needs "
                       "|u_t|/|u_n| > 7/2 μ (1 + e))",
                       c.min_slip_time, impact.duration()));
  }
  return reasons;
}

cases::RunResult ObliqueImpactSolver::run(const PreparedScene& prepared) const {
  const cases::Scene& scene = prepared.scene();
  const SphereWallScene s = sphere_wall_scene(prepared);
  const GrossSlidingImpact impact(s);
  const auto [dt, steps, every, t_end] = sample_grid(prepared);

  cases::RunResult result;
  result.status = cases::RunStatus::ok;
  result.trace = cases::trace_layout(scene);
  GrossSlidingImpact::Integrals running;
  for (std::uint64_t k = 0; k <= steps; k += every) {
    const double t = static_cast<double>(k) * dt;
    record(scene, s, impact.at(t, running), t, result.trace);
  }
  for (const std::uint64_t k : cases::snapshot_steps(scene.output.snapshot_times, dt, steps)) {
    const double t = static_cast<double>(k) * dt;
    const SphereState st = impact.at(t);
    result.snapshots.push_back({t, {case_vec(st.position)}, {case_vec(st.velocity)}, {case_vec(st.spin)}});
  }
  if (impact.start() + impact.duration() < t_end) {
    add_exact_metrics(impact, s, result);
  } else {
    result.warnings.push_back("the contact does not end within the run; no exact metrics");
  }

  const auto c = impact.check();
  auto& conv = result.conventions;
  conv["solution"] =
      "normal: closed form of m δ'' + η δ' + k δ = 0 (eq 3.10–3.11); tangential: |F_t| = μ·basis "
      "against the fixed slip direction from the first instant (Coulomb gross sliding, the k_f → ∞ "
      "limit of spring_coulomb); impulse, moment and displacement by 30-point Gauss–Legendre "
      "quadrature of the closed-form basis on pieces split where F_n changes sign (exact to "
      "rounding: the integrands are exponentials times sines over at most half a period)";
  conv["sampling"] = fmt::format(
      "same time points as the in-house core: t_k = k·{}·Δt with Δt = {:.6g} s", every, dt);
  conv["friction limit basis"] = std::string(dem::to_string(s.limit));
  conv["lever arm"] = s.lever_is_radius ? "r" : "r − δ/2 (common normal)";
  conv["rotation"] = s.inverse_inertia > 0.0 ? "integrated, I = 2/5 m r²" : "held at initial values";
  conv["contact onset"] = "the wall contact acts while δ > 0 (strictly)";
  conv["trace velocity"] = "exact velocity at the sample time";
  if (c.initial_phase > 0.0 && impact.friction() > 0.0) {
    const double total = impact.integrals(impact.duration()).impulse * impact.friction();
    result.warnings.push_back(fmt::format(
        "the basis jumps to {:.4g} N at first touch (dashpot in the friction limit): a "
        "spring_coulomb contact needs ≈ {:.3g} s to stretch its spring to the cap, withholding "
        "≈ {:.3g} N·s ({:.2g} of the tangential impulse) that this solution applies",
        impact.basis(0.0), c.initial_phase, c.initial_deficit, c.initial_deficit / total));
  }
  if (c.lagging_time > 0.0) {
    result.warnings.push_back(fmt::format(
        "for {:.3g} s of the contact the cap grows faster than the slip can stretch a spring of "
        "k_f = {:.4g} N/m (μ dB/dt > k_f u): the spring_coulomb force falls below μ·basis there",
        c.lagging_time, s.tangential_stiffness));
  }
  return result;
}

}  // namespace reference::analytic
