// SPDX-License-Identifier: MIT
#include "reference/analytic/linear_cohesion_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <numbers>
#include <optional>
#include <variant>

#include <boost/math/tools/toms748_solve.hpp>
#include <fmt/format.h>

#include "cases/time_step.hpp"
#include "dem/contact/contact_model.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/particles/particles.hpp"
#include "reference/analytic/collinear_solver.hpp"
#include "reference/analytic/vector3_math.hpp"
#include "reference/common/core_setup.hpp"
#include "reference/analytic/model_support.hpp"

namespace reference::analytic {
namespace {

/// What the linear-cohesion pair solves: a linear spring with no or a restitution dashpot, not
/// clamped, linear cohesion, frictionless, no rolling resistance.
const ModelSupport kLinearCohesionModel{"linear cohesion pair", {"linear"}, {"none", "restitution"}, {"none"}, {"linear"}, {"none"}};

using cases::Vector3;

/// Most regions a run may pass through before the solution gives up (it settles long before).
constexpr std::size_t kMaxPieces = 100000;

/// Exact motion of m y'' + c y' + k y = 0 from (y0, v0), for any sign of k (k < 0: the
/// unstable attraction of linear cohesion).
class Mode {
 public:
  Mode(double m, double c, double k, double y0, double v0) : y0_(y0), v0_(v0) {
    const double disc = c * c - 4.0 * m * k;
    if (k == 0.0 && c == 0.0) {
      kind_ = Kind::free;
    } else if (disc < 0.0) {
      kind_ = Kind::oscillating;
      decay_ = c / (2.0 * m);
      rate_ = std::sqrt(-disc) / (2.0 * m);
    } else if (disc > 0.0) {
      kind_ = Kind::real;
      l1_ = (-c + std::sqrt(disc)) / (2.0 * m);
      l2_ = (-c - std::sqrt(disc)) / (2.0 * m);
    } else {
      kind_ = Kind::critical;
      l1_ = -c / (2.0 * m);
    }
  }
  /// y and y' at τ.
  [[nodiscard]] std::pair<double, double> at(double tau) const noexcept {
    switch (kind_) {
      case Kind::free: return {y0_ + v0_ * tau, v0_};
      case Kind::oscillating: {
        const double e = std::exp(-decay_ * tau);
        const double cs = std::cos(rate_ * tau), sn = std::sin(rate_ * tau);
        const double b = (v0_ + decay_ * y0_) / rate_;
        return {e * (y0_ * cs + b * sn), e * (v0_ * cs - (decay_ * b + rate_ * y0_) * sn)};
      }
      case Kind::real: {
        const double c1 = (v0_ - l2_ * y0_) / (l1_ - l2_);
        const double c2 = (l1_ * y0_ - v0_) / (l1_ - l2_);
        const double e1 = std::exp(l1_ * tau), e2 = std::exp(l2_ * tau);
        return {c1 * e1 + c2 * e2, l1_ * c1 * e1 + l2_ * c2 * e2};
      }
      case Kind::critical: {
        const double b = v0_ - l1_ * y0_;
        const double e = std::exp(l1_ * tau);
        return {(y0_ + b * tau) * e, (b + l1_ * (y0_ + b * tau)) * e};
      }
    }
    return {y0_, v0_};
  }
  /// Shortest time scale of the motion [s] (for scanning), +∞ in free flight.
  [[nodiscard]] double time_scale() const noexcept {
    switch (kind_) {
      case Kind::free: return std::numeric_limits<double>::infinity();
      case Kind::oscillating: return 1.0 / std::hypot(rate_, decay_);
      case Kind::real: return 1.0 / std::max(std::abs(l1_), std::abs(l2_));
      case Kind::critical: return 1.0 / std::abs(l1_);
    }
    return 1.0;
  }

 private:
  enum class Kind { free, oscillating, real, critical };
  Kind kind_ = Kind::free;
  double y0_, v0_;
  double decay_ = 0.0, rate_ = 0.0, l1_ = 0.0, l2_ = 0.0;
};

/// Where the pair is: effect spheres apart, only effect spheres overlapping, bodies touching.
enum class Region { apart, cohesive, contact };

/// The pair's constants along its line of centres.
struct Pair {
  double mass;          ///< m* = mass of the mobile sphere [kg]
  double k_e, k_c;      ///< [N/m]
  double eta;           ///< dashpot in contact [kg/s]
  double gap;           ///< Δ = δ̂ − δ [m]
  double contact_distance;
  Vector3 fixed_position;
  Vector3 axis;         ///< unit vector from the fixed sphere to the mobile one at t = 0
  std::size_t mobile, fixed;

  [[nodiscard]] double equilibrium() const { return k_c * gap / (k_e - k_c); }
  /// Normal force at overlap δ and rate δ' (repulsive positive).
  [[nodiscard]] double force(double delta, double rate) const {
    if (delta > 0.0) return k_e * delta - k_c * (delta + gap) + eta * rate;
    if (delta + gap > 0.0) return -k_c * (delta + gap);
    return 0.0;
  }
};

/// One stretch of motion inside one region.
struct Piece {
  double start;
  Region region;
  Mode mode;
  double shift;  ///< δ = y + shift
  double end = std::numeric_limits<double>::infinity();
};

Region region_of(const Pair& p, double delta, double rate) {
  if (delta > 0.0 || (delta == 0.0 && rate > 0.0)) return Region::contact;
  if (delta + p.gap > 0.0 || (delta + p.gap == 0.0 && rate > 0.0)) return Region::cohesive;
  return Region::apart;
}

Piece make_piece(const Pair& p, double t, Region region, double delta, double rate) {
  switch (region) {
    case Region::contact: {
      const double shift = p.equilibrium();
      return {t, region, Mode(p.mass, p.eta, p.k_e - p.k_c, delta - shift, rate), shift};
    }
    case Region::cohesive:
      return {t, region, Mode(p.mass, 0.0, -p.k_c, delta + p.gap, rate), -p.gap};
    case Region::apart: break;
  }
  return {t, region, Mode(p.mass, 0.0, 0.0, delta, rate), 0.0};
}

/// First τ in (0, horizon] at which y(τ) crosses `level` leaving the side it starts on (or, if
/// it starts on the level, the side `inside` says), by scanning and TOMS 748; empty if none.
std::optional<double> crossing(const Mode& mode, double level, double inside, double horizon) {
  const double h = std::min(horizon, 0.01 * mode.time_scale());
  const auto g = [&](double tau) { return inside * (mode.at(tau).first - level); };
  double lo = 0.0;
  for (double hi = h;; hi = std::min(hi + h, horizon)) {
    if (g(hi) <= 0.0) {
      if (g(lo) <= 0.0) return lo;  // only when it starts exactly on the level, outward
      std::uintmax_t iterations = 200;
      const auto b = boost::math::tools::toms748_solve(
          g, lo, hi, boost::math::tools::eps_tolerance<double>(std::numeric_limits<double>::digits - 2),
          iterations);
      return b.second;  // the side past the level, so the next region starts outside this one
    }
    if (hi >= horizon) return std::nullopt;
    lo = hi;
  }
}

/// τ > 0 where A cosh(ωτ) + B sinh(ωτ) = c (closed form), the smallest; `on_level` excludes the
/// root at τ = 0 when the motion starts on that level.
std::optional<double> cosh_crossing(double a, double b, double c, double omega, bool on_level) {
  std::vector<double> z;
  if (a + b == 0.0) {
    if (c != 0.0) z.push_back((a - b) / (2.0 * c));
  } else {
    const double disc = c * c - (a + b) * (a - b);
    if (disc >= 0.0) {
      z.push_back((c + std::sqrt(disc)) / (a + b));
      z.push_back((c - std::sqrt(disc)) / (a + b));
    }
    if (on_level) z = {(a - b) / (a + b)};  // the other root of the pair {1, (A−B)/(A+B)}
  }
  std::optional<double> best;
  for (const double v : z) {
    if (!(v > 1.0) || !std::isfinite(v)) continue;
    const double tau = std::log(v) / omega;
    if (!best || tau < *best) best = tau;
  }
  return best;
}

/// The exact motion of the pair from t = 0 to t_end, region by region.
class Motion {
 public:
  Motion(const Pair& p, double delta0, double rate0, double t_end) {
    double t = 0.0, delta = delta0, rate = rate0;
    bool on_boundary = false;
    while (pieces_.size() < kMaxPieces) {
      const Region region = region_of(p, delta, rate);
      Piece piece = make_piece(p, t, region, delta, rate);
      const double horizon = t_end - t;
      std::optional<double> tau;
      if (region == Region::contact) {
        tau = crossing(piece.mode, -piece.shift, 1.0, horizon);
      } else if (region == Region::cohesive) {
        const double omega = std::sqrt(p.k_c / p.mass);
        const double a = delta + p.gap, b = rate / omega;
        const bool at_contact = on_boundary && delta == 0.0;
        const bool at_edge = on_boundary && delta + p.gap == 0.0;
        const auto in = cosh_crossing(a, b, p.gap, omega, at_contact);
        const auto out = cosh_crossing(a, b, 0.0, omega, at_edge);
        tau = in && (!out || *in < *out) ? in : out;
        if (tau && *tau > horizon) tau.reset();
      } else if (rate > 0.0) {
        tau = (-p.gap - delta) / rate;
        if (*tau > horizon) tau.reset();
      }
      if (!tau) {
        pieces_.push_back(piece);
        return;
      }
      piece.end = t + *tau;
      pieces_.push_back(piece);
      // Continue exactly on the boundary that was crossed, moving into the next region.
      const auto [y, v] = piece.mode.at(*tau);
      t = piece.end;
      rate = v;
      const double reached = y + piece.shift;
      delta = std::abs(reached) <= std::abs(reached + p.gap) ? 0.0 : -p.gap;
      on_boundary = true;
    }
    throw std::runtime_error("the linear cohesion pair changes region too often to follow");
  }
  /// δ and δ' at time t.
  [[nodiscard]] std::pair<double, double> at(double t) const {
    const auto it = std::upper_bound(pieces_.begin(), pieces_.end(), t,
                                     [](double v, const Piece& p) { return v < p.start; });
    const Piece& piece = it == pieces_.begin() ? pieces_.front() : *(it - 1);
    const auto [y, v] = piece.mode.at(t - piece.start);
    return {y + piece.shift, v};
  }
  /// The regions in time order.
  [[nodiscard]] const std::vector<Piece>& pieces() const noexcept { return pieces_; }

 private:
  std::vector<Piece> pieces_;
};

Pair make_pair(const PreparedScene& prepared) {
  const cases::Scene& scene = prepared.scene();
  const std::size_t mobile = scene.particles[0].fixed ? 1 : 0;
  const std::size_t fixed = 1 - mobile;
  const auto& m = scene.particles[mobile];
  const auto& f = scene.particles[fixed];
  const dem::PairTable& table = prepared.pair_table();
  const dem::PairLaw& law = table.law(m.material, f.material);
  const double k_e = std::get<dem::LinearNormal>(law.normal).stiffness;
  const double k_c = std::get<dem::LinearCohesion>(law.cohesion).stiffness;
  const double mass = dem::sphere_mass(scene.materials.at(m.material).density, m.radius);
  const Vector3 x = minus(m.position, f.position);
  return Pair{mass, k_e, k_c, dem::damping_coefficient(law, mass, k_e),
              (m.effect_radius + f.effect_radius) - (m.radius + f.radius), m.radius + f.radius,
              f.position, scaled(x, 1.0 / norm(x)), mobile, fixed};
}

/// Overlap and its rate at t = 0.
std::pair<double, double> initial(const cases::Scene& scene, const Pair& p) {
  const auto& m = scene.particles[p.mobile];
  const double d = norm(minus(m.position, p.fixed_position));
  return {p.contact_distance - d, -dot(m.velocity, p.axis)};
}

void record(const cases::Scene& scene, const Pair& p, const Motion& motion, double t,
            cases::Trace& trace) {
  const auto [delta, rate] = motion.at(t);
  const double fn = p.force(delta, rate);
  const Vector3 x = minus(p.fixed_position, scaled(p.axis, delta - p.contact_distance));
  const Vector3 v = scaled(p.axis, -rate);
  std::vector<double> row;
  row.reserve(trace.columns().size());
  row.push_back(t);
  for (const std::size_t i : scene.output.trace_particles) {
    const bool is_mobile = i == p.mobile;
    const Vector3 pos = is_mobile ? x : p.fixed_position;
    const Vector3 vel = is_mobile ? v : Vector3{0.0, 0.0, 0.0};
    const Vector3 force = scaled(p.axis, is_mobile ? fn : -fn);
    row.insert(row.end(), pos.begin(), pos.end());
    row.insert(row.end(), vel.begin(), vel.end());
    const Vector3& w = scene.particles[i].angular_velocity;
    if (is_mobile) {
      row.insert(row.end(), w.begin(), w.end());
    } else {
      row.insert(row.end(), {0.0, 0.0, 0.0});
    }
    row.insert(row.end(), force.begin(), force.end());
  }
  for (std::size_t k = 0; k < scene.output.trace_pairs.size(); ++k) {
    row.push_back(delta);
    row.push_back(fn);
  }
  trace.append_row(row);
}

/// Exact figures of the first body contact and of the final rest state.
void add_exact_metrics(const Pair& p, const Motion& motion, double t_end,
                       cases::RunResult& result) {
  const double eq = p.equilibrium();
  result.exact_metrics["equilibrium_overlap"] = eq;
  const double final_delta = motion.at(t_end).first;
  if (std::abs(final_delta - eq) > 1e-9 * std::abs(eq)) {
    result.warnings.push_back(fmt::format(
        "the exact overlap at the end of the run, {:.9g} m, is not yet the equilibrium {:.9g} m: "
        "lengthen the run for equilibrium_overlap",
        final_delta, eq));
  }
  for (const Piece& piece : motion.pieces()) {
    if (piece.region != Region::contact) continue;
    if (std::isfinite(piece.end)) result.exact_metrics["contact_duration"] = piece.end - piece.start;
    // Deepest overlap: the first zero of δ' (scan + TOMS 748 on the velocity).
    const double span = std::min(piece.end, t_end) - piece.start;
    const double h = 0.01 * piece.mode.time_scale();
    const auto rate = [&](double tau) { return piece.mode.at(tau).second; };
    for (double lo = 0.0; lo < span; lo += h) {
      const double hi = std::min(lo + h, span);
      if (rate(lo) > 0.0 && rate(hi) <= 0.0) {
        std::uintmax_t iterations = 200;
        const auto b = boost::math::tools::toms748_solve(
            rate, lo, hi, boost::math::tools::eps_tolerance<double>(std::numeric_limits<double>::digits - 2),
            iterations);
        result.exact_metrics["max_overlap"] = piece.mode.at(0.5 * (b.first + b.second)).first + piece.shift;
        break;
      }
    }
    break;
  }
}

std::map<std::string, std::string> conventions(const Pair& p, double dt, std::uint64_t every) {
  std::map<std::string, std::string> c;
  c["solution"] =
      "exact piecewise closed form: cosh/sinh while only the effect spheres overlap, damped "
      "oscillator about δ_eq in contact; region changes by closed form or TOMS 748";
  c["sampling"] = fmt::format(
      "same time points as the in-house core: t_k = k·{}·Δt with Δt = {:.6g} s", every, dt);
  c["normal force"] = fmt::format(
      "k_e max(δ,0) − k_c max(δ̂,0) + η δ' in contact (eq 3.10, 3.33, E.5): k_e = {:.6g} N/m, "
      "k_c = {:.6g} N/m, η = {:.6g} kg/s, Δ = δ̂ − δ = {:.6g} m",
      p.k_e, p.k_c, p.eta, p.gap);
  c["equilibrium"] = fmt::format("δ_eq = k_c Δ/(k_e − k_c) = {:.9g} m", p.equilibrium());
  c["contact onset"] = "damping acts while δ > 0 (strictly); cohesion while δ̂ > 0";
  return c;
}


void check_linear_cohesion_layout(const cases::Scene& scene, std::vector<std::string>& reasons) {
  if (scene.particles.size() != 2 || scene.particles[0].fixed == scene.particles[1].fixed) {
    reasons.push_back("analytic (linear cohesion pair): needs exactly 2 particles, one fixed and one mobile");
    return;
  }
  const Vector3& g = scene.gravity;
  if (g[0] != 0.0 || g[1] != 0.0 || g[2] != 0.0) {
    reasons.push_back("analytic (linear cohesion pair): gravity must be zero");
  }
  if (!scene.walls.empty()) reasons.push_back("analytic (linear cohesion pair): no walls");
  if (scene.fluid) reasons.push_back("analytic (linear cohesion pair): no fluid");
  for (const auto& p : scene.particles) {
    if (p.material >= scene.materials.size()) {
      reasons.push_back("analytic (linear cohesion pair): a particle names no material");
      return;
    }
    if (!p.motion.empty()) reasons.push_back("analytic (linear cohesion pair): no prescribed motion");
  }
  const std::size_t mobile = scene.particles[0].fixed ? 1 : 0;
  const auto& m = scene.particles[mobile];
  const auto& f = scene.particles[1 - mobile];
  if (norm(f.velocity) != 0.0) reasons.push_back("analytic (linear cohesion pair): the fixed sphere must be at rest");
  const Vector3 x = minus(m.position, f.position);
  if (!(norm(x) > 0.0)) {
    reasons.push_back("analytic (linear cohesion pair): the centres coincide");
    return;
  }
  if (off_line(m.velocity, scaled(x, 1.0 / norm(x))) > kCollinearTolerance * norm(m.velocity)) {
    reasons.push_back(
        "analytic (linear cohesion pair): the mobile sphere must move along the line of centres");
  }
}

}  // namespace

std::vector<std::string> LinearCohesionSolver::unsupported_reasons(const PreparedScene& prepared) const {
  const cases::Scene& scene = prepared.scene();
  std::vector<std::string> reasons;
  for (std::string& r : model_reasons(scene.model, kLinearCohesionModel)) reasons.push_back(std::move(r));
  if (!reasons.empty()) return reasons;
  check_linear_cohesion_layout(scene, reasons);
  if (!reasons.empty()) return reasons;
  try {
    const Pair p = make_pair(prepared);
    if (!(p.k_e > p.k_c)) {
      reasons.push_back(fmt::format(
          "analytic (linear cohesion pair): needs k_e > k_c for an equilibrium, got k_e = {} N/m, "
          "k_c = {} N/m",
          p.k_e, p.k_c));
    }
    if (!(p.mass > 0.0)) reasons.push_back("analytic (linear cohesion pair): needs a positive mass");
    static_cast<void>(core_setup(prepared));
  } catch (const std::exception& e) {
    reasons.push_back(std::string("analytic (linear cohesion pair): ") + e.what());
  }
  return reasons;
}

cases::RunResult LinearCohesionSolver::run(const PreparedScene& prepared) const {
  const cases::Scene& scene = prepared.scene();
  const Pair p = make_pair(prepared);
  const auto [dt, steps, every, t_end] = sample_grid(prepared);
  const auto [delta0, rate0] = initial(scene, p);
  const Motion motion(p, delta0, rate0, t_end);

  cases::RunResult result;
  result.status = cases::RunStatus::ok;
  result.trace = cases::trace_layout(scene);
  for (std::uint64_t n = 0; n <= steps; n += every) {
    record(scene, p, motion, static_cast<double>(n) * dt, result.trace);
  }
  for (const std::uint64_t n : cases::snapshot_steps(scene.output.snapshot_times, dt, steps)) {
    const double t = static_cast<double>(n) * dt;
    const auto [delta, rate] = motion.at(t);
    cases::Snapshot snap;
    snap.time = t;
    snap.position.resize(2);
    snap.velocity.resize(2);
    snap.angular_velocity.resize(2);
    snap.position[p.mobile] = minus(p.fixed_position, scaled(p.axis, delta - p.contact_distance));
    snap.velocity[p.mobile] = scaled(p.axis, -rate);
    snap.angular_velocity[p.mobile] = scene.particles[p.mobile].angular_velocity;
    snap.position[p.fixed] = p.fixed_position;
    result.snapshots.push_back(std::move(snap));
  }
  result.conventions = conventions(p, dt, every);
  add_exact_metrics(p, motion, t_end, result);
  return result;
}

}  // namespace reference::analytic
