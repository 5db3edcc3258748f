// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>

// Load-time bounds on what a case file may ask for (docs/case-format.md, "Limits"). A case file
// is untrusted input: each bound keeps a number from overflowing, a loop from running for ever or
// memory from running out. Physical bounds are set only where no DEM study could want to pass
// them; the rest are numerical.
namespace cases {

/// Speed of light in vacuum [m/s]: no sphere, wall, prescribed motion, fluid or launch may move
/// this fast (a velocity of 1e300 m/s would overflow every kinetic energy).
inline constexpr double kSpeedOfLight = 299'792'458.0;

/// Largest material density [kg/m³]: above the density of an atomic nucleus (2.3e17 kg/m³), and
/// still room for density scaling by 10¹² of the densest solid (osmium, 2.3e4 kg/m³), as
/// quasi-static DEM studies do.
inline constexpr double kMaxDensity = 1.0e18;

/// Largest overlap a sphere may have with another body (a sphere or a wall) where a run or a
/// stage starts, as a share of the smaller radius: more is an error in the case, not a contact.
inline constexpr double kMaxInitialOverlap = 0.01;

/// Window in which every derived quantity (sphere mass and moment of inertia, collision stiffness,
/// contact time, time step) must lie, in SI units. No physical sphere, spring or collision lies
/// outside it (an electron weighs 9e-31 kg, the observable universe 1e53 kg; the Planck time is
/// 5e-44 s, the age of the universe 4e17 s), and the product or quotient of two numbers in it is
/// a normal double, so the core's formulas (m v², k δ², m*²/(R* E*²), √(m/k)) neither overflow
/// nor underflow to zero.
inline constexpr double kMinDerived = 1.0e-100;
/// Upper end of the window of derived quantities (see kMinDerived).
inline constexpr double kMaxDerived = 1.0e100;

/// Most spheres a scene may hold, listed and generated together: ten million. The explicit
/// scene costs about 150 bytes a sphere before any engine holds its own copy; the workbench
/// benchmarks run 10⁵.
inline constexpr std::size_t kMaxParticles = 10'000'000;

/// Most materials a case may define: the contact model holds a law for every pair (n²).
inline constexpr std::size_t kMaxMaterials = 256;

/// Most walls a scene may hold, boxes counted as their faces: the core checks every wall against
/// every sphere at each neighbour-list build.
inline constexpr std::size_t kMaxWalls = 256;

/// Most mesh facets a scene may hold, all meshes together: each is a wall of its own, found for a
/// sphere by a bounding-sphere test at every list build (docs/walls.md, "Meshes").
inline constexpr std::size_t kMaxMeshFacets = 50000;

/// Farthest a sphere may start from a periodic box, in box lengths along a periodic axis: the
/// core counts periodic images in an int, and a sphere a million box lengths away has already
/// lost six digits of its position.
inline constexpr double kMaxPeriodicImages = 1.0e6;

/// Most time steps a run or a formation stage may take.
inline constexpr double kMaxSteps = 1.0e9;

}  // namespace cases
