// SPDX-License-Identifier: MIT
#pragma once
// A packed bed followed over a run's snapshots: the obscured reservoir fraction and the dose left
// in the compare.packing region at every snapshot, and the fluidisation metrics read from that
// curve (docs/metrics.md, "Fluidisation"; thesis §6.4).

#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "cases/run_result.hpp"
#include "cases/scene.hpp"

namespace comparison {

/// The bed in the packing region at one snapshot.
struct PackingSample {
  double time = 0.0;            ///< [s]
  double orf = 0.0;             ///< obscured reservoir fraction (thesis appendix G)
  double dose_remaining = 0.0;  ///< share of the mobile spheres whose centres lie in the region
  /// The largest fragment of the mobile spheres whose centres lie outside the region, as a share
  /// of the whole dose's volume: a plug pushed out whole makes it large, a stream of single
  /// spheres small (see kFragmentGap).
  double largest_departed_fragment = 0.0;
};

/// Two departed spheres belong to one fragment while their centres are closer than this factor
/// times the sum of their radii: in contact, or within a twentieth of their radii of it — a plug
/// carried by the air is not always pressed together, a stream's spheres are farther apart.
inline constexpr double kFragmentGap = 1.05;

/// The packing region's ORF and dose at every snapshot of `run`, or why there is none (no
/// compare.packing region, a snapshot that does not hold every sphere).
[[nodiscard]] std::variant<std::vector<PackingSample>, std::string> packing_series(const cases::Scene& scene,
                                                                                 const cases::RunResult& run);

/// The first time at which the sampled curve (times, values) falls to `level` or below, linearly
/// interpolated between the last sample above it and the first at or below it; the first time
/// itself when the curve starts there; empty when it never does. Sizes must agree.
[[nodiscard]] std::optional<double> first_time_at_or_below(std::span<const double> times,
                                                           std::span<const double> values, double level);

/// The largest fall of a sampled curve between consecutive samples, max(v[k] − v[k+1], 0); 0 for
/// fewer than two samples. Of the ORF, the biggest share of the reservoir cleared between two
/// snapshots: a bed leaving as a few large fragments makes it large, a stream small.
[[nodiscard]] double largest_drop(std::span<const double> values) noexcept;

}  // namespace comparison
