// SPDX-License-Identifier: MIT
#pragma once

#include "cases/scene.hpp"

namespace reference::lammps {

/// An axis-aligned LAMMPS simulation box [m] (`boundary f f f`).
struct Box {
  cases::Vector3 low{};
  cases::Vector3 high{};
};

/// A box that comfortably contains every particle's whole trajectory over `duration` [s]:
/// the bounding box of all bodies (centre ± r) widened along each axis k on both sides by
/// 2 v_max T + |g_k| T² + 2 r_max, where v_max is the largest initial speed of a mobile sphere,
/// except on a side an axis-aligned plane wall bounds: the box ends 2 r_max beyond that plane (the
/// spheres stay on its inner side, whatever speed they gain). A free sphere travels at most v T + ½|g_k|T² along k; the factor 2 leaves
/// room for speed gained in collisions (an elastic hit by a heavier sphere at most doubles its
/// speed) and 2 r_max keeps every body clear of the faces. A sphere that still leaves it makes
/// LAMMPS stop with "Lost atoms", which the driver reports as an error: never a silent result.
Box simulation_box(const cases::Scene& scene, double duration);

/// Neighbour-list skin [m]: 0.2 × the smallest radius (LAMMPS' SI default of 1 mm is wrong for
/// both sub-mm grains and metre-sized bodies). With `neigh_modify every 1 check yes` any positive
/// skin is exact; the size only trades list builds against list length.
double neighbour_skin(const cases::Scene& scene);

}  // namespace reference::lammps
