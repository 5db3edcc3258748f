// SPDX-License-Identifier: MIT
#include "reference/analytic/two_body_ode.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <boost/numeric/odeint.hpp>

namespace reference::analytic {
namespace {

namespace odeint = boost::numeric::odeint;

using State = std::array<double, 2>;  // x = δ/L, x' = dx/dτ = δ'/v

/// Time units (of L/v) a contact may last before it is abandoned (elastic Hertz: 3.2).
constexpr double kHorizon = 1e3;

/// The contact in units of L (overlap), v (rate) and L/v (time).
class ScaledContact {
 public:
  explicit ScaledContact(const NormalContactProblem& p)
      : problem_(p),
        length_(p.length_scale),
        speed_(p.approach_speed),
        force_unit_(p.reduced_mass * p.approach_speed * p.approach_speed / p.length_scale) {}

  /// x'' = −F(L max(x, 0), v x') / (m* v²/L).
  void operator()(const State& s, State& ds, double /*tau*/) const {
    ds[0] = s[1];
    ds[1] = -force(s) / force_unit_;
  }
  /// F [N] at the scaled state (δ taken as 0 beyond the end of contact).
  [[nodiscard]] double force(const State& s) const {
    return problem_.force(length_ * std::max(s[0], 0.0), speed_ * s[1]);
  }
  /// The physical state at scaled time τ.
  [[nodiscard]] NormalContactState physical(double tau, const State& s) const {
    return {tau * length_ / speed_, length_ * s[0], speed_ * s[1], force(s)};
  }
  [[nodiscard]] double time_unit() const noexcept { return length_ / speed_; }

 private:
  const NormalContactProblem& problem_;
  double length_;
  double speed_;
  double force_unit_;
};

/// Root of f on [a, b] with f(a) f(b) ≤ 0, to double precision.
template <class F>
double root(F f, double a, double b) {
  const double fa = f(a);
  const double fb = f(b);
  if (fb == 0.0) return b;
  if (fa == 0.0) return a;
  std::uintmax_t iterations = 200;
  const auto [lo, hi] = boost::math::tools::toms748_solve(
      f, a, b, fa, fb, boost::math::tools::eps_tolerance<double>(52), iterations);
  return 0.5 * (lo + hi);
}

}  // namespace

NormalContactSolution solve_normal_contact(const NormalContactProblem& problem,
                                           const std::vector<double>& sample_times,
                                           double tolerance) {
  if (!(problem.approach_speed > 0.0) || !(problem.reduced_mass > 0.0) ||
      !(problem.length_scale > 0.0) || !problem.force) {
    throw std::invalid_argument("normal contact: need m* > 0, v > 0, a length scale and a force law");
  }
  const ScaledContact sys(problem);
  const double unit = sys.time_unit();

  std::vector<double> taus;
  taus.reserve(sample_times.size());
  for (const double t : sample_times) taus.push_back(t / unit);
  std::sort(taus.begin(), taus.end());
  auto next_sample = std::lower_bound(taus.begin(), taus.end(), 0.0);

  NormalContactSolution out;
  std::vector<std::pair<double, State>> checkpoints{{0.0, State{0.0, 1.0}}};
  std::vector<double> forces{sys.force(checkpoints.front().second)};

  auto dense = odeint::make_dense_output(tolerance, tolerance, odeint::runge_kutta_dopri5<State>());
  dense.initialize(State{0.0, 1.0}, 0.0, 1e-4);
  bool deepest_found = false;
  double tau_end = -1.0;
  State end_state{};
  while (dense.current_time() < kHorizon) {
    const auto [t0, t1] = dense.do_step(sys);
    const State before = checkpoints.back().second;
    const State after = dense.current_state();
    const auto at = [&](double tau) {
      State s{};
      dense.calc_state(tau, s);
      return s;
    };
    if (!deepest_found && before[1] > 0.0 && after[1] <= 0.0) {
      const double tau = root([&](double t) { return at(t)[1]; }, t0, t1);
      out.deepest = sys.physical(tau, at(tau));
      out.deepest.overlap_rate = 0.0;
      deepest_found = true;
    }
    const bool ended = after[0] <= 0.0;
    if (ended) {
      tau_end = root([&](double t) { return at(t)[0]; }, t0, t1);
      end_state = at(tau_end);
      end_state[0] = 0.0;
    }
    const double last = ended ? tau_end : t1;
    for (; next_sample != taus.end() && *next_sample <= last; ++next_sample) {
      out.samples.push_back(sys.physical(*next_sample, at(*next_sample)));
    }
    if (ended) {
      checkpoints.emplace_back(tau_end, end_state);
      forces.push_back(sys.force(end_state));
      break;
    }
    checkpoints.emplace_back(t1, after);
    forces.push_back(sys.force(after));
  }
  if (tau_end < 0.0) {
    throw std::runtime_error("normal contact: the overlap does not return to zero within 1e3 "
                             "time units (overdamped contact)");
  }
  out.duration = tau_end * unit;
  out.exit_rate = problem.approach_speed * end_state[1];

  // Force peak: Brent's method between the neighbours of the largest step-end force, on states
  // re-integrated from the nearest stored step end (to the same tolerance).
  const auto state_at = [&](double tau) {
    auto it = std::upper_bound(checkpoints.begin(), checkpoints.end(), tau,
                               [](double t, const auto& c) { return t < c.first; });
    const auto& [t_from, s_from] = *std::prev(it);
    State s = s_from;
    if (tau > t_from) {
      odeint::integrate_adaptive(
          odeint::make_controlled(tolerance, tolerance, odeint::runge_kutta_dopri5<State>()),
          sys, s, t_from, tau, tau - t_from);
    }
    return s;
  };
  const auto best = static_cast<std::size_t>(
      std::distance(forces.begin(), std::max_element(forces.begin(), forces.end())));
  const double lo = checkpoints[best == 0 ? 0 : best - 1].first;
  const double hi = checkpoints[std::min(best + 1, checkpoints.size() - 1)].first;
  std::uintmax_t iterations = 200;
  const auto [tau_peak, minus_peak] = boost::math::tools::brent_find_minima(
      [&](double tau) { return -sys.force(state_at(tau)); }, lo, hi, 40, iterations);
  out.strongest = sys.physical(checkpoints[best].first, checkpoints[best].second);
  if (-minus_peak > out.strongest.force) out.strongest = sys.physical(tau_peak, state_at(tau_peak));
  if (!deepest_found) out.deepest = out.strongest;  // cannot happen for a repulsive contact
  return out;
}

}  // namespace reference::analytic
