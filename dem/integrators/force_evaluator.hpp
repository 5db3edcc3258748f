// SPDX-License-Identifier: MIT
#pragma once

#include "dem/particles/particles.hpp"

namespace dem {

/// What an integrator asks of the force model. Contact history advances only on `commit`;
/// `trial` evaluations (Runge–Kutta stages, predictor and implicit iterates) see a history
/// advanced by `elapsed` from the last commit and leave nothing behind.
class ForceEvaluator {
 public:
  virtual ~ForceEvaluator() = default;
  /// Accelerations at `state`, `elapsed` seconds after the last commit; keeps nothing.
  virtual void trial(const KinematicState& state, double elapsed, Accelerations& out) = 0;
  /// Accelerations at `state`; the contact history advanced by `elapsed` becomes the committed one.
  virtual void commit(const KinematicState& state, double elapsed, Accelerations& out) = 0;
};

}  // namespace dem
