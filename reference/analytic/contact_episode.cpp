// SPDX-License-Identifier: MIT
#include "reference/analytic/contact_episode.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <boost/math/tools/minima.hpp>

#include "dem/contact/laws/linear_dashpot.hpp"

namespace reference::analytic {
namespace {

/// Bits of precision asked of Brent's method (half the mantissa: its best).
constexpr int kBrentBits = std::numeric_limits<double>::digits / 2;

/// Largest value of f on [lo, hi]: Brent's method plus both ends (the peak may be an end).
/// Brent works on u ∈ [0, 1], t = lo + u (hi − lo): Boost's stopping rule has an absolute
/// part that would be coarse on a time scale of microseconds.
template <class F>
double maximum_on(const F& f, double lo, double hi) {
  double best = std::max(f(lo), f(hi));
  if (hi > lo) {
    const double width = hi - lo;
    std::uintmax_t iterations = 200;
    const auto [u, minus_f] = boost::math::tools::brent_find_minima(
        [&](double v) { return -f(lo + v * width); }, 0.0, 1.0, kBrentBits, iterations);
    static_cast<void>(u);
    best = std::max(best, -minus_f);
  }
  return best;
}

/// Figures of a contact during which only its own spring acts: the closed form of
/// m δ'' + η δ' + k δ = 0 with δ(0) = 0, δ'(0) = v_in.
ContactFigures single_spring_figures(const AxisProblem& problem, const AxisPartner& p,
                                     double approach_speed) {
  ContactFigures f;
  f.closed_form = true;
  const LinearOscillator overlap(problem.mass, p.damping, p.stiffness, 0.0, approach_speed);
  f.duration = dem::laws::linear_contact_duration(p.stiffness, problem.mass, p.damping);
  f.restitution = -overlap.at(f.duration).velocity / approach_speed;
  const double decay = p.damping / (2.0 * problem.mass);
  const double damped_frequency = std::sqrt(p.stiffness / problem.mass - decay * decay);
  const double peak_time = std::atan2(damped_frequency, decay) / damped_frequency;  // dδ/dt = 0
  f.max_overlap = overlap.at(peak_time).position;
  f.max_force = maximum_on(
      [&](double tau) {
        const AxisKinematics k = overlap.at(tau);
        return p.stiffness * k.position + p.damping * k.velocity;
      },
      0.0, f.duration);
  return f;
}

/// Figures of a contact measured on the exact piecewise solution.
ContactFigures piecewise_figures(const AxisProblem& problem, const ContactEpisode& e) {
  const AxisPartner& p = problem.partners[e.partner];
  ContactFigures f;
  f.duration = e.end - e.start;
  const double approach = e.segments.front().overlap_rate(e.partner, e.start);
  const double rebound = -e.segments.back().overlap_rate(e.partner, e.end);
  if (approach > 0.0) f.restitution = rebound / approach;
  f.max_overlap = -std::numeric_limits<double>::infinity();
  f.max_force = -std::numeric_limits<double>::infinity();
  for (const Segment& s : e.segments) {
    const double lo = std::max(s.begin, e.start);
    const double hi = std::min(s.end, e.end);
    if (lo > hi) continue;
    f.max_overlap = std::max(
        f.max_overlap, maximum_on([&](double t) { return s.overlap(e.partner, t); }, lo, hi));
    f.max_force = std::max(f.max_force, maximum_on(
                                            [&](double t) {
                                              return p.stiffness * s.overlap(e.partner, t) +
                                                     p.damping * s.overlap_rate(e.partner, t);
                                            },
                                            lo, hi));
  }
  return f;
}

/// True when partner i is the only active one and pushes from side `side`.
bool alone(const Regime& r, std::size_t i, int side) {
  for (std::size_t j = 0; j < r.active.size(); ++j) {
    if (r.active[j] != (j == i)) return false;
  }
  return r.side[i] == side;
}

}  // namespace

std::optional<ContactEpisode> first_contact(const AxisProblem& problem, std::size_t partner,
                                            double latest_start, double horizon) {
  ContactEpisode e;
  e.partner = partner;
  SegmentWalker forward(problem, 1);
  Segment current = forward.next(std::max(latest_start, 0.0));
  if (current.regime.active[partner]) {
    // In contact just after t = 0: the contact may have begun earlier.
    SegmentWalker backward(problem, -1);
    std::vector<Segment> before;
    for (;;) {
      if (backward.time() <= -horizon) return std::nullopt;
      Segment s = backward.next(-horizon);
      if (!s.regime.active[partner]) break;
      before.push_back(std::move(s));
    }
    e.start = before.empty() ? 0.0 : before.back().begin;
    e.segments.assign(before.rbegin(), before.rend());
  } else {
    while (!current.regime.active[partner]) {
      if (forward.time() >= latest_start) return std::nullopt;
      current = forward.next(latest_start);
    }
    e.start = current.begin;
  }
  e.segments.push_back(std::move(current));
  const double give_up = e.start + horizon;
  for (;;) {
    if (forward.time() >= give_up) return std::nullopt;
    Segment s = forward.next(give_up);
    if (!s.regime.active[partner]) {
      e.end = s.begin;
      break;
    }
    e.segments.push_back(std::move(s));
  }
  const int side = e.segments.front().regime.side[partner];
  e.single_spring = std::all_of(e.segments.begin(), e.segments.end(), [&](const Segment& s) {
    return alone(s.regime, partner, side);
  });
  return e;
}

ContactFigures contact_figures(const AxisProblem& problem, const ContactEpisode& episode) {
  const double approach = episode.segments.front().overlap_rate(episode.partner, episode.start);
  if (episode.single_spring && approach > 0.0) {
    return single_spring_figures(problem, problem.partners[episode.partner], approach);
  }
  return piecewise_figures(problem, episode);
}

}  // namespace reference::analytic
