// SPDX-License-Identifier: MIT
#pragma once
// Geometry of packed beds: how much of each sphere lies inside a box, packing fractions, and the
// obscured reservoir fraction of thesis appendix G (docs/metrics.md, "Packing").

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>
#include <stdexcept>

#include "cases/scene.hpp"

namespace comparison {

/// An axis-aligned box [lo, hi] (a reservoir, a packing region).
struct Box {
  cases::Vector3 lo{};
  cases::Vector3 hi{};
  /// Volume; 0 when any side is empty.
  [[nodiscard]] double volume() const noexcept;
  /// True when `p` lies inside or on the boundary.
  [[nodiscard]] bool contains(const cases::Vector3& p) const noexcept;
};

/// Area of the disk of radius `rho` centred at the origin that lies in the rectangle
/// [x0, x1] × [y0, y1] (exact: inclusion–exclusion over quadrant areas, each a sum of circular
/// segment integrals ½(x√(ρ² − x²) + ρ² asin(x/ρ))).
[[nodiscard]] double disk_rectangle_area(double rho, double x0, double x1, double y0, double y1) noexcept;

/// Volume of the sphere (centre `c`, radius `r`) inside `box`: the disk–rectangle area of each
/// slice integrated over the sphere's height with the substitution z = c_z + r sin θ, split where
/// a slice's radius reaches a side line or a corner of the box's x–y rectangle, each piece
/// mapped by a smoothstep (θ = θ₀ + w(3s² − 2s³), which makes the 3/2-power onsets at its ends
/// analytic) and integrated by 30-point Gauss–Legendre (about 1e-14 of the sphere's volume).
[[nodiscard]] double sphere_box_volume(const cases::Vector3& c, double r, const Box& box) noexcept;

/// Packing fraction of the spheres in `box`: the sum of their volumes inside it (clipped at its
/// faces) over its volume. Throws std::invalid_argument when the box is empty or the sizes of
/// `centres` and `radii` differ.
[[nodiscard]] double packing_fraction(std::span<const cases::Vector3> centres, std::span<const double> radii,
                                      const Box& box);

/// `box` shrunk by `margin` on every side (the interior of a packing, away from wall ordering).
/// Throws std::invalid_argument when nothing is left.
[[nodiscard]] Box interior(const Box& box, double margin);

/// Obscured reservoir fraction (thesis appendix G): the box's y–z face is sampled by an
/// `ny` × `nz` grid of points at cell centres; a point is obscured when some sphere whose centre
/// lies in the box covers it seen along x, r > √((y_p − y_q)² + (z_p − z_q)²) (eq G.1). Returns
/// the obscured share of the points. Throws std::invalid_argument on an empty grid or box.
[[nodiscard]] double obscured_fraction(std::span<const cases::Vector3> centres, std::span<const double> radii,
                                       const Box& box, std::size_t ny, std::size_t nz);

/// Body contacts (overlap > 0) of each of the given spheres with the others, found by the
/// breakup metrics' cell search. Throws std::invalid_argument when the sizes differ.
[[nodiscard]] std::vector<std::uint32_t> contact_counts(std::span<const cases::Vector3> centres,
                                                        std::span<const double> radii);

/// Mean number of body contacts (overlap > 0) with any of the given spheres, over the spheres
/// whose centres lie in `box` (contact_counts). Throws std::invalid_argument when no centre lies
/// in the box or the sizes differ.
[[nodiscard]] double coordination_number(std::span<const cases::Vector3> centres, std::span<const double> radii,
                                         const Box& box);

/// Share of the spheres whose centres lie in `box` (the dose remaining in a reservoir), by count.
[[nodiscard]] double share_inside(std::span<const cases::Vector3> centres, const Box& box) noexcept;

}  // namespace comparison
