// SPDX-License-Identifier: MIT
#pragma once

#include <functional>
#include <vector>

namespace reference::analytic {

/// Total normal force F(δ, δ') [N] of a contact, repulsive positive, for an overlap δ ≥ 0 [m]
/// and overlap rate δ' = −u_c·n [m/s] (positive while the bodies approach).
using NormalForceLaw = std::function<double(double overlap, double overlap_rate)>;

/// One head-on normal contact, m* δ'' = −F(δ, δ'), from first touch δ(0) = 0, δ'(0) = v > 0.
struct NormalContactProblem {
  double reduced_mass = 0.0;    ///< m* [kg]
  double approach_speed = 0.0;  ///< v = δ'(0) > 0 [m/s]
  double length_scale = 0.0;    ///< typical overlap [m] (the elastic δ_max): unit of the tolerances
  NormalForceLaw force;         ///< evaluated only at δ ≥ 0
};

/// State of the contact at one instant.
struct NormalContactState {
  double time = 0.0;          ///< since first touch [s]
  double overlap = 0.0;       ///< δ [m]
  double overlap_rate = 0.0;  ///< δ' [m/s]
  double force = 0.0;         ///< F(δ, δ') [N]
};

/// The contact, from first touch to the first return of δ to 0.
struct NormalContactSolution {
  double duration = 0.0;             ///< t_c [s]
  double exit_rate = 0.0;            ///< δ'(t_c) [m/s] (negative: separating)
  NormalContactState deepest;        ///< at the largest overlap (δ' = 0)
  NormalContactState strongest;      ///< at the largest force
  std::vector<NormalContactState> samples;  ///< at the requested times that lie in [0, t_c]
};

/// Solves the contact with Boost.Odeint's Dormand–Prince 5(4) with dense output, relative and
/// absolute tolerance `tolerance` on δ/L and δ'/v (L = length_scale, time unit L/v). The end
/// of contact (δ = 0) and the deepest point (δ' = 0) are located by TOMS 748 on the dense output
/// of the step that contains them; the force peak by Brent's method on states re-integrated from
/// the stored step ends; samples come from the dense output. Beyond δ = 0 the right-hand side
/// uses F(0, δ') (the force law's limit δ → 0⁺), so the step that straddles the end stays
/// smooth enough to interpolate. `sample_times` [s since first touch] need not be sorted;
/// samples come back in time order. Throws std::runtime_error when the contact does not end
/// within 10³ time units (e.g. an overdamped unclipped dashpot that creeps back towards δ = 0
/// without reaching it).
NormalContactSolution solve_normal_contact(const NormalContactProblem& problem,
                                           const std::vector<double>& sample_times,
                                           double tolerance = 1e-12);

}  // namespace reference::analytic
