// SPDX-License-Identifier: MIT
#pragma once
// The discharge metrics of a scene ([compare.discharge]) and what they need of it.

#include <algorithm>
#include <array>
#include <string_view>

namespace cases {

/// The metrics measured at compare.discharge's outlet plane (docs/metrics.md, "Discharge").
inline constexpr std::array<std::string_view, 2> kDischargeMetrics{"mass_flow_rate", "discharged_fraction"};

/// True when `metric` is one of kDischargeMetrics.
[[nodiscard]] inline bool is_discharge_metric(std::string_view metric) noexcept {
  return std::find(kDischargeMetrics.begin(), kDischargeMetrics.end(), metric) != kDischargeMetrics.end();
}

/// Fewest snapshots the mass flow rate is fitted over.
inline constexpr std::size_t kMinDischargeSnapshots = 3;

}  // namespace cases
