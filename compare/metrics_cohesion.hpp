// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cases/scene.hpp"
#include "cases/trace.hpp"

// Metrics of cohesive contacts (pull-off, rupture, separation work, equilibrium), computed from
// the overlap and normal-force columns of the compared contact only, the same way for every
// engine. Conventions: overlap δ > 0 when the bodies interpenetrate, normal force repulsive
// positive, a sample with force exactly 0 is "not interacting".
namespace comparison {

/// Value of a cohesion metric, or why it cannot be computed.
struct CohesionMetric {
  std::optional<double> value;
  std::string problem;  ///< set when value is empty
};

/// The metric `name` of the scene's compared contact (compare.pair or compare.wall_contact)
/// from `trace`; empty when `name` is not a cohesion metric.
std::optional<CohesionMetric> cohesion_metric(const std::string& name, const cases::Scene& scene,
                                              const cases::Trace& trace);

/// Where a contact breaks in a sampled (overlap, force) series.
struct Rupture {
  std::size_t last_attached;  ///< last row with a nonzero, tensile force before the break
  double overlap;             ///< estimated overlap at rupture δ_r [m] (negative when apart)
  double force;               ///< estimated normal force just before rupture [N]
  bool fold_refined;          ///< true: located at the fold of the sampled curve
};

/// The last break of a tensile contact: the last row k with force < 0 followed by a row with
/// force 0. At a fold of the force–overlap curve (JKR displacement-controlled rupture, where
/// dF/dδ → ∞ and δ − δ_c ∝ (F − F_c)²) the break is located at the minimum of the cubic δ(F)
/// through rows k−3..k when that minimum lies ahead of row k and between rows k and k+1;
/// otherwise δ_r is the midpoint of δ_k and δ_{k+1} and the force is that of row k. Empty when
/// the series has no such break.
std::optional<Rupture> find_rupture(const std::vector<double>& overlap,
                                    const std::vector<double>& force);

/// Work done by the contact force while the pair separates from the deepest overlap of the
/// interacting stretch that ends at `r` to the rupture, W = ∫ F dℓ = −∫ F dδ [J] (trapezoids
/// on the samples, closed by the rupture estimate). Positive when repulsion dominates.
double separation_work(const std::vector<double>& overlap, const std::vector<double>& force,
                       const Rupture& r);

}  // namespace comparison
