// SPDX-License-Identifier: MIT
#include "reference/analytic/collinear_motion.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include <boost/math/tools/toms748_solve.hpp>

namespace reference::analytic {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
/// Scan steps per natural period when bracketing regime changes.
constexpr double kScanStepsPerPeriod = 64.0;
/// Regime changes in a row that may leave the time unchanged before the walker gives up.
constexpr int kMaxStalledSegments = 1000;
/// Segments one AxisSolution may hold.
constexpr std::size_t kMaxSegments = 10'000'000;

/// δ_i = −n_i (offset_i + y).
double overlap_of(int side, double offset, double y) noexcept {
  return -static_cast<double>(side) * (offset + y);
}

/// |δ_i| below which partner i counts as just touching: 1e-15 R_i plus the rounding of
/// offset_i + y.
double touch_tolerance(const AxisPartner& p, double offset, double y) noexcept {
  return 1e-15 * p.reach + 4.0 * kEpsilon * (std::abs(offset) + std::abs(y));
}

/// The regime that holds just after (direction +1) or just before (−1) an instant with
/// s = base + y, s' = rate. Partners whose overlap is within rounding of zero are active when
/// the overlap grows in the walking direction; a sphere at a partner's centre goes on to the
/// side it moves to. The base is moved to the active springs' equilibrium.
Regime start_regime(const AxisProblem& problem, int direction, double base, std::vector<int> side,
                    std::vector<double> offset, double y, double rate) {
  const std::size_t n = problem.partners.size();
  const double d = static_cast<double>(direction);
  for (std::size_t i = 0; i < n; ++i) {
    const AxisPartner& p = problem.partners[i];
    const double centre_distance = p.reach - overlap_of(side[i], offset[i], y);  // n_i (s − s_i)
    const double tolerance =
        1e-15 * p.reach + 4.0 * kEpsilon * (p.reach + std::abs(offset[i]) + std::abs(y));
    int new_side = side[i];
    if (centre_distance < -tolerance) {
      new_side = -side[i];
    } else if (centre_distance <= tolerance && d * rate != 0.0) {
      new_side = d * rate > 0.0 ? 1 : -1;
    }
    if (new_side != side[i]) {
      offset[i] += static_cast<double>(side[i] - new_side) * p.reach;
      side[i] = new_side;
    }
  }

  // Acceleration from the contacts that certainly act, to settle touching ones at rest.
  double certain_force = 0.0;
  std::vector<double> overlap(n);
  for (std::size_t i = 0; i < n; ++i) {
    const AxisPartner& p = problem.partners[i];
    overlap[i] = overlap_of(side[i], offset[i], y);
    if (overlap[i] > touch_tolerance(p, offset[i], y)) {
      certain_force += static_cast<double>(side[i]) * p.stiffness * overlap[i] - p.damping * rate;
    }
  }
  const double acceleration = certain_force / problem.mass;

  Regime r;
  r.active.assign(n, false);
  double stiffness = 0.0;
  double damping = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const AxisPartner& p = problem.partners[i];
    const double tolerance = touch_tolerance(p, offset[i], y);
    const double growth = -static_cast<double>(side[i]) * rate;  // dδ_i/dt
    bool active = false;
    if (overlap[i] > tolerance) {
      active = true;
    } else if (overlap[i] >= -tolerance) {
      active = d * growth > 0.0 ||
               (growth == 0.0 && -static_cast<double>(side[i]) * acceleration > 0.0);
    }
    r.active[i] = active;
    if (active) {
      stiffness += p.stiffness;
      damping += p.damping;
    }
  }
  if (stiffness > 0.0) {
    double shift = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (r.active[i]) shift -= problem.partners[i].stiffness / stiffness * offset[i];
    }
    base += shift;
    for (double& o : offset) o += shift;
    y -= shift;
  }
  r.side = std::move(side);
  r.base = base;
  r.offset = std::move(offset);
  r.motion = LinearOscillator(problem.mass, damping, stiffness, y, rate);
  return r;
}

/// A function of τ whose sign change from negative to non-negative is a regime change:
/// F = sign·δ_i + shift (contact begins: δ_i; contact ends: −δ_i; centre crossed: δ_i − R_i).
struct Watch {
  std::size_t partner;
  double sign;
  double shift;
};

/// F and dF/dτ of a watch for the motion state k.
std::pair<double, double> watch_value(const Regime& r, const Watch& w, const AxisKinematics& k) {
  const double n = static_cast<double>(r.side[w.partner]);
  return {w.sign * (-n * (r.offset[w.partner] + k.position)) + w.shift, w.sign * (-n * k.velocity)};
}

/// Regime changes to watch: every inactive partner's contact start; every active partner's
/// contact end and centre crossing.
std::vector<Watch> watches_of(const AxisProblem& problem, const Regime& r) {
  std::vector<Watch> out;
  for (std::size_t i = 0; i < problem.partners.size(); ++i) {
    if (r.active[i]) {
      out.push_back({i, -1.0, 0.0});
      out.push_back({i, 1.0, -problem.partners[i].reach});
    } else {
      out.push_back({i, 1.0, 0.0});
    }
  }
  return out;
}

/// Root of f between a and b (any order) where f(a) < 0 ≤ f(b), located by TOMS 748 to double
/// precision; returns the end of the final bracket on the non-negative side, so the change has
/// certainly happened at the returned time.
template <class F>
double locate_change(const F& f, double a, double fa, double b, double fb) {
  if (fb == 0.0) return b;
  const bool increasing = a < b;
  const double lo = increasing ? a : b;
  const double hi = increasing ? b : a;
  std::uintmax_t iterations = 200;
  const auto [x1, x2] = boost::math::tools::toms748_solve(
      f, lo, hi, increasing ? fa : fb, increasing ? fb : fa,
      boost::math::tools::eps_tolerance<double>(), iterations);
  const double f1 = f(x1);
  const double f2 = f(x2);
  const double near = increasing ? x1 : x2;  // the bracket end nearer to a
  const double far = increasing ? x2 : x1;
  const double f_near = increasing ? f1 : f2;
  return f_near >= 0.0 ? near : far;
}

/// First time in the walking direction between a and b (|a| < |b|) at which the watch
/// changes sign from negative to non-negative, or empty. The interval is short enough to hold
/// at most one extremum of F, which is located first so that grazing changes are not missed.
std::optional<double> change_in(const Regime& r, const Watch& w, double a, double b,
                                const std::pair<double, double>& at_a,
                                const std::pair<double, double>& at_b) {
  const auto value = [&](double tau) { return watch_value(r, w, r.motion.at(tau)).first; };
  const auto crossing = [&](double lo, double f_lo, double hi,
                            double f_hi) -> std::optional<double> {
    if (f_lo < 0.0 && f_hi >= 0.0) return locate_change(value, lo, f_lo, hi, f_hi);
    return std::nullopt;
  };
  if (at_a.second * at_b.second < 0.0) {
    const auto slope = [&](double tau) { return watch_value(r, w, r.motion.at(tau)).second; };
    const double lo = std::min(a, b);
    const double hi = std::max(a, b);
    std::uintmax_t iterations = 200;
    const auto [x1, x2] = boost::math::tools::toms748_solve(
        slope, lo, hi, a < b ? at_a.second : at_b.second, a < b ? at_b.second : at_a.second,
        boost::math::tools::eps_tolerance<double>(), iterations);
    const double extremum = 0.5 * (x1 + x2);
    const double f_extremum = value(extremum);
    if (auto c = crossing(a, at_a.first, extremum, f_extremum)) return c;
    return crossing(extremum, f_extremum, b, at_b.first);
  }
  return crossing(a, at_a.first, b, at_b.first);
}

/// Time τ (signed in the walking direction) of the first regime change within |τ| ≤ span of a
/// regime with springs, or empty.
std::optional<double> next_change_with_springs(const AxisProblem& problem, const Regime& r,
                                               int direction, double span) {
  const std::vector<Watch> watches = watches_of(problem, r);
  const double d = static_cast<double>(direction);
  const double step = std::min(r.motion.natural_period() / kScanStepsPerPeriod, span);
  if (!(step > 0.0)) return std::nullopt;
  std::vector<std::pair<double, double>> previous(watches.size());
  const AxisKinematics start = r.motion.at(0.0);
  for (std::size_t w = 0; w < watches.size(); ++w) previous[w] = watch_value(r, watches[w], start);
  double tau_previous = 0.0;
  for (std::uint64_t j = 1;; ++j) {
    const double reach = std::min(static_cast<double>(j) * step, span);
    const double tau = d * reach;
    const AxisKinematics k = r.motion.at(tau);
    std::optional<double> first;
    for (std::size_t w = 0; w < watches.size(); ++w) {
      const auto current = watch_value(r, watches[w], k);
      if (const auto c = change_in(r, watches[w], tau_previous, tau, previous[w], current)) {
        if (!first || d * *c < d * *first) first = c;
      }
      previous[w] = current;
    }
    if (first) return first;
    if (reach >= span) return std::nullopt;
    tau_previous = tau;
  }
}

/// Time τ of the first contact in free flight within |τ| ≤ span, solved directly, or empty.
std::optional<double> next_change_in_flight(const AxisProblem& problem, const Regime& r,
                                            int direction, double span) {
  const double d = static_cast<double>(direction);
  const AxisKinematics k = r.motion.at(0.0);
  std::optional<double> first;
  for (std::size_t i = 0; i < problem.partners.size(); ++i) {
    const double growth = -static_cast<double>(r.side[i]) * k.velocity;  // dδ_i/dt
    if (!(d * growth > 0.0)) continue;
    const double tau = -(r.offset[i] + k.position) / k.velocity;  // δ_i(τ) = 0
    if (!(d * tau > 0.0) || std::abs(tau) > span) continue;
    if (!first || d * tau < d * *first) first = tau;
  }
  return first;
}

}  // namespace

AxisSample Segment::sample(const AxisProblem& problem, double t) const {
  const AxisKinematics k = regime.motion.at(t - origin);
  AxisSample out;
  out.coordinate = {regime.base + k.position, k.velocity, k.acceleration};
  const std::size_t n = problem.partners.size();
  out.side = regime.side;
  out.overlap.resize(n);
  out.overlap_rate.resize(n);
  out.normal_force.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const AxisPartner& p = problem.partners[i];
    const double side = static_cast<double>(regime.side[i]);
    out.overlap[i] = overlap_of(regime.side[i], regime.offset[i], k.position);
    out.overlap_rate[i] = -side * k.velocity;
    out.normal_force[i] = out.overlap[i] > 0.0
                              ? p.stiffness * out.overlap[i] + p.damping * out.overlap_rate[i]
                              : 0.0;
  }
  return out;
}

double Segment::overlap(std::size_t partner, double t) const noexcept {
  return overlap_of(regime.side[partner], regime.offset[partner],
                    regime.motion.at(t - origin).position);
}

double Segment::overlap_rate(std::size_t partner, double t) const noexcept {
  return -static_cast<double>(regime.side[partner]) * regime.motion.at(t - origin).velocity;
}

SegmentWalker::SegmentWalker(AxisProblem problem, int direction)
    : problem_(std::move(problem)),
      direction_(direction >= 0 ? 1 : -1),
      base_(problem_.position),
      rate_(problem_.velocity) {
  for (const AxisPartner& p : problem_.partners) {
    const int side = problem_.position >= p.position ? 1 : -1;
    side_.push_back(side);
    offset_.push_back(problem_.position - (p.position + static_cast<double>(side) * p.reach));
  }
}

Segment SegmentWalker::next(double limit) {
  const double d = static_cast<double>(direction_);
  const double span = std::max(0.0, d * (limit - time_));
  for (int stalled = 0; stalled < kMaxStalledSegments; ++stalled) {
    Segment seg;
    seg.origin = time_;
    seg.regime = start_regime(problem_, direction_, base_, side_, offset_, y_, rate_);
    const std::optional<double> change =
        seg.regime.motion.free() ? next_change_in_flight(problem_, seg.regime, direction_, span)
                                 : next_change_with_springs(problem_, seg.regime, direction_, span);
    const double tau = change ? *change : d * span;
    const double finish = change ? time_ + tau : limit;
    const AxisKinematics k = seg.regime.motion.at(tau);
    base_ = seg.regime.base;
    side_ = seg.regime.side;
    offset_ = seg.regime.offset;
    y_ = k.position;
    rate_ = k.velocity;
    seg.begin = std::min(time_, finish);
    seg.end = std::max(time_, finish);
    const bool progressed = finish != time_ || span == 0.0;
    time_ = finish;
    if (progressed) return seg;
  }
  throw std::runtime_error(
      "analytic: the collinear solution makes no progress in time (regime changes pile up at "
      "t = " + std::to_string(time_) + " s)");
}

AxisSolution::AxisSolution(const AxisProblem& problem, double t_min, double t_max)
    : problem_(problem) {
  if (!(t_min <= 0.0 && t_max >= 0.0)) {
    throw std::invalid_argument("analytic: the solved interval must contain t = 0");
  }
  const auto guard = [&] {
    if (segments_.size() > kMaxSegments) {
      throw std::runtime_error("analytic: more than 10^7 regime changes in the solved interval");
    }
  };
  if (t_min < 0.0) {
    SegmentWalker back(problem_, -1);
    while (back.time() > t_min) {
      segments_.push_back(back.next(t_min));
      guard();
    }
    std::reverse(segments_.begin(), segments_.end());
  }
  SegmentWalker forward(problem_, 1);
  do {
    segments_.push_back(forward.next(t_max));
    guard();
  } while (forward.time() < t_max);
}

AxisSample AxisSolution::at(double t) const {
  if (!(t >= segments_.front().begin && t <= segments_.back().end)) {
    throw std::out_of_range("analytic: time " + std::to_string(t) +
                            " s lies outside the solved interval");
  }
  const auto after = std::upper_bound(segments_.begin(), segments_.end(), t,
                                      [](double time, const Segment& s) { return time < s.begin; });
  return std::prev(after)->sample(problem_, t);
}

}  // namespace reference::analytic
