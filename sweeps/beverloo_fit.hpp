// SPDX-License-Identifier: MIT
#pragma once
// Beverloo's law for the discharge of a hopper through a round orifice (Beverloo, Leniger & van de
// Velde 1961): W = C ρ_b √g (D − k d)^{5/2}, fitted to flow rates measured at several orifice
// diameters (docs/hopper.md).

#include <optional>
#include <span>

namespace sweeps {

/// Beverloo's mass flow rate W [kg/s] through an orifice of diameter D [m] for grains of diameter
/// d [m] at bulk density ρ_b [kg/m³] under gravity g [m/s²]; 0 when D ≤ k d.
[[nodiscard]] double beverloo_rate(double c, double k, double bulk_density, double g, double orifice, double grain) noexcept;

/// C and k of Beverloo's law fitted to the points (D_i, W_i).
struct BeverlooFit {
  double c = 0.0;  ///< discharge coefficient C
  double k = 0.0;  ///< empty-annulus coefficient k (the orifice loses k d of its diameter)
  std::size_t points = 0;
  double largest_misfit = 0.0;  ///< max |W_fit/W − 1| over the points
};

/// The least-squares line through (D_i, W_i^{2/5}), which Beverloo's law makes straight:
/// W^{2/5} = a (D − k d) with a = (C ρ_b √g)^{2/5}, so C = a^{5/2} / (ρ_b √g) and k = −b / (a d)
/// for the line a D + b. Empty with fewer than two distinct diameters, a non-positive rate, or a
/// line that does not rise.
[[nodiscard]] std::optional<BeverlooFit> fit_beverloo(std::span<const double> orifice, std::span<const double> rate,
                                                      double bulk_density, double g, double grain);

}  // namespace sweeps
