// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "reference/analytic/collinear_motion.hpp"

namespace reference::analytic {

/// One contact of a partner, from the instant δ_i rises above 0 to the instant it returns to 0.
struct ContactEpisode {
  std::size_t partner = 0;
  double start = 0.0;             ///< [s]
  double end = 0.0;               ///< [s]
  std::vector<Segment> segments;  ///< exact motion covering [start, end], in time order
  /// No other partner acts at any time during the contact and the sphere stays on one side of
  /// the partner's centre, so δ obeys m δ'' + η δ' + k δ = 0 from δ = 0 and the closed forms of
  /// eq 3.11 / 3.40 hold.
  bool single_spring = false;
};

/// The first contact of `partner`: the one going on at t = 0 (its start found by solving
/// backwards) or else the first to start in (0, latest_start]. Empty when there is none, or
/// when it does not end within `horizon` [s] of its start.
std::optional<ContactEpisode> first_contact(const AxisProblem& problem, std::size_t partner,
                                            double latest_start, double horizon);

/// Exact figures of one contact of the linear spring–dashpot.
struct ContactFigures {
  double duration = 0.0;                 ///< t_c [s] (eq 3.40, corrected)
  std::optional<double> restitution;     ///< rebound / approach normal speed (eq 3.11)
  double max_overlap = 0.0;              ///< continuous maximum of δ [m]
  double max_force = 0.0;                ///< continuous maximum of k δ + η dδ/dt [N]
  bool closed_form = false;              ///< true: single-spring closed forms; false: piecewise
};

/// Duration, restitution, maximum overlap and maximum normal force of `episode`. A
/// single-spring contact uses the closed forms δ(τ) of m δ'' + η δ' + k δ = 0 from δ(0) = 0
/// (duration from laws::linear_contact_duration, the overlap peak where dδ/dt = 0, the force
/// peak by Brent's method); any other contact is measured on the exact piecewise solution.
ContactFigures contact_figures(const AxisProblem& problem, const ContactEpisode& episode);

}  // namespace reference::analytic
