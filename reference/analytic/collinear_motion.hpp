// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <vector>

#include "reference/analytic/linear_oscillator.hpp"

namespace reference::analytic {

/// A fixed partner on the collision axis, acting through a linear spring–dashpot (eq 3.10).
struct AxisPartner {
  double position = 0.0;   ///< s_i, coordinate of the partner's centre on the axis [m]
  double reach = 0.0;      ///< R_i = r_p + r_i: body overlap δ_i = R_i − |s − s_i| [m]
  double stiffness = 0.0;  ///< k_i [N/m], > 0
  double damping = 0.0;    ///< η_i [kg/s] (eq 3.11), ≥ 0
};

/// One coordinate s moving along a line among fixed partners: the mobile sphere's position
/// along its velocity (one mobile sphere), or the centre separation (two mobile spheres,
/// mass m*). Each partner with δ_i > 0 pushes with n_i (k_i δ_i − η_i n_i ds/dt), n_i =
/// sign(s − s_i) (thesis eq 3.10), so m s'' is piecewise linear in (s, s').
struct AxisProblem {
  double mass = 0.0;      ///< m, or m* = m_a m_b / (m_a + m_b) [kg]
  double position = 0.0;  ///< s(0) [m]
  double velocity = 0.0;  ///< s'(0) [m/s]
  std::vector<AxisPartner> partners;
};

/// A fixed set of active contacts and the closed-form motion while it lasts. The coordinate is
/// s = base + y(τ); each partner's overlap is δ_i = −n_i (offset_i + y) with offset_i =
/// base − (s_i + n_i R_i), written so that δ keeps full relative precision near contact.
struct Regime {
  std::vector<int> side;        ///< n_i = ±1: the side of partner i's centre s lies on
  std::vector<bool> active;     ///< partner i pushes (δ_i > 0) throughout the regime
  double base = 0.0;            ///< b [m]: equilibrium of the active springs, or a reference
  std::vector<double> offset;   ///< b − (s_i + n_i R_i) [m]
  LinearOscillator motion{1.0, 0.0, 0.0, 0.0, 0.0};  ///< y(τ): m y'' + C y' + K y = 0
};

/// State on the axis at one instant, with every partner's overlap and normal force.
struct AxisSample {
  AxisKinematics coordinate;          ///< s, s', s''
  std::vector<int> side;              ///< n_i
  std::vector<double> overlap;        ///< δ_i [m], negative when apart
  std::vector<double> overlap_rate;   ///< dδ_i/dt = −n_i s' [m/s]
  std::vector<double> normal_force;   ///< k_i δ_i + η_i dδ_i/dt while δ_i > 0, else 0 [N]
};

/// The motion between two consecutive regime changes (or the ends of the solved interval).
struct Segment {
  double begin = 0.0;   ///< earlier end [s]
  double end = 0.0;     ///< later end [s]
  double origin = 0.0;  ///< time at which the regime's τ = 0: begin forwards, end backwards [s]
  Regime regime;

  /// Exact state at time t (meaningful for begin ≤ t ≤ end).
  [[nodiscard]] AxisSample sample(const AxisProblem& problem, double t) const;
  /// δ_i(t) [m] of partner i.
  [[nodiscard]] double overlap(std::size_t partner, double t) const noexcept;
  /// dδ_i/dt [m/s] of partner i.
  [[nodiscard]] double overlap_rate(std::size_t partner, double t) const noexcept;
};

/// Builds the exact piecewise solution one regime at a time, forwards (direction +1) or
/// backwards (−1) in time from t = 0. Regime changes (a δ_i crossing 0, or s crossing a
/// partner's centre) are found by scanning the closed form with steps of at most 1/64 of the
/// regime's natural period and refined with TOMS 748 to double precision; in free flight they
/// are solved directly.
class SegmentWalker {
 public:
  /// Walker starting at t = 0 from the problem's initial state.
  SegmentWalker(AxisProblem problem, int direction);
  /// The next segment: from the current time to the next regime change, or to `limit` [s]
  /// (≥ the current time forwards, ≤ backwards) if none comes first. Throws
  /// std::runtime_error when the solution makes no progress.
  [[nodiscard]] Segment next(double limit);
  /// Time reached so far [s].
  [[nodiscard]] double time() const noexcept { return time_; }
  /// The problem being solved.
  [[nodiscard]] const AxisProblem& problem() const noexcept { return problem_; }

 private:
  AxisProblem problem_;
  int direction_;
  double time_ = 0.0;
  double base_;                 // carried across regime changes: s = base_ + y_
  std::vector<int> side_;
  std::vector<double> offset_;
  double y_ = 0.0;
  double rate_;
};

/// The exact piecewise solution over [t_min, t_max] (t_min ≤ 0 ≤ t_max).
class AxisSolution {
 public:
  /// Solves `problem` backwards to t_min and forwards to t_max.
  AxisSolution(const AxisProblem& problem, double t_min, double t_max);
  /// Exact state at t ∈ [t_min, t_max].
  [[nodiscard]] AxisSample at(double t) const;
  /// Segments in increasing time; consecutive ones share their boundary.
  [[nodiscard]] const std::vector<Segment>& segments() const noexcept { return segments_; }
  /// The problem solved.
  [[nodiscard]] const AxisProblem& problem() const noexcept { return problem_; }

 private:
  AxisProblem problem_;
  std::vector<Segment> segments_;
};

}  // namespace reference::analytic
