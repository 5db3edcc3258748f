// SPDX-License-Identifier: MIT
#pragma once

#include "reference/analytic/solver.hpp"

namespace reference::analytic {

/// A sphere sliding on a plane wall under gravity normal to the wall, resting at its static
/// overlap δ_s = m g / k_e so that the normal force is m g from t = 0: Coulomb sliding with
/// deceleration μ g against the slip direction while the spin grows at μ m g ℓ / I, until the
/// contact point comes to rest (v = v0 / (1 + I/(m ℓ²)) ≈ 5/7 v0 without initial spin), then
/// rolling at constant velocity (thesis eq 3.23, 3.32; ℓ the lever arm).
class SlidingSolver final : public Solver {
 public:
  using Solver::run;
  using Solver::unsupported_reasons;
  [[nodiscard]] std::string_view name() const noexcept override {
    return "sphere sliding then rolling on a plane";
  }
  [[nodiscard]] std::vector<std::string> unsupported_reasons(const PreparedScene& prepared) const override;
  [[nodiscard]] cases::RunResult run(const PreparedScene& prepared) const override;
};

}  // namespace reference::analytic
