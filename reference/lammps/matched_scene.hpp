// SPDX-License-Identifier: MIT
#pragma once

#include "cases/scene.hpp"

namespace reference::lammps {

/// The scene the in-house core runs to reproduce LAMMPS 29 Sep 2021's numerics (velocity Verlet
/// as `fix nve/sphere`, pinned Δt, and every sub-model replaced by the variant LAMMPS computes).
cases::Scene matched_scene(const cases::Scene& scene);

}  // namespace reference::lammps
