// SPDX-License-Identifier: MIT
#pragma once
// The packing metrics' region of a scene ([compare.packing]) and what they need of it.

#include <array>
#include <cstddef>
#include <string_view>

#include "cases/scene.hpp"

namespace cases {

/// The metrics measured in compare.packing's region (docs/metrics.md, "Packing").
inline constexpr std::array<std::string_view, 8> kPackingMetrics{
    "packing_fraction", "packing_fraction_interior", "orf", "dose_remaining", "coordination_number",
    "fluidisation_time", "orf_largest_drop", "largest_departed_fragment"};

/// The packing metrics read from the whole ORF curve over the snapshots rather than from one
/// snapshot (docs/metrics.md, "Fluidisation").
inline constexpr std::array<std::string_view, 3> kFluidisationMetrics{"fluidisation_time", "orf_largest_drop",
                                                                      "largest_departed_fragment"};

/// The fewest snapshots a fluidisation metric reads (a curve needs two points).
inline constexpr std::size_t kMinFluidisationSnapshots = 2;

/// True when `metric` is one of kPackingMetrics.
[[nodiscard]] bool is_packing_metric(std::string_view metric) noexcept;

/// True when `metric` is one of kFluidisationMetrics.
[[nodiscard]] bool is_fluidisation_metric(std::string_view metric) noexcept;

/// The interior margin of the packing region `packing` of `scene`: its interior_margin, else two
/// mean diameters of the scene's mobile spheres (of all spheres when none is mobile).
[[nodiscard]] double interior_margin(const Scene& scene, const PackingSpec& packing) noexcept;

}  // namespace cases
