// SPDX-License-Identifier: MIT
#pragma once

#include "cases/scene.hpp"
#include "reference/common/code_conventions.hpp"

namespace reference::lammps {

/// The scene the in-house core runs to reproduce LAMMPS 29 Sep 2021's numerics: velocity
/// Verlet as `fix nve/sphere` with the pinned Δt; the Coulomb-limit basis of pair granular
/// (FrictionLimit::elastic_damping, jkr_shifted for jkr/dmt, which leaves the dashpot out as
/// LAMMPS does); fix wall/gran's lever arm r (WallLeverArm::radius); pair granular's contact
/// velocity with full radii and torque with r − δ/2 (PairLeverArm::radius_velocity); pair
/// granular's JKR rupture at δ_f (JkrRupture::load). Damping needs no change: the driver feeds
/// LAMMPS the core's own dashpot (η, or the Tsuji e_in whose factor is the core's). Not
/// reproduced (documented in docs/engines.md (section LAMMPS)): the 1e-10 threshold of the
/// history projection and the wall's δ = 0 contact onset.
cases::Scene matched_scene(const PreparedScene& prepared);

/// LAMMPS's numerics as the matched engine "inhouse@lammps" adopts them (matched_scene above).
[[nodiscard]] const CodeConventions& conventions() noexcept;

}  // namespace reference::lammps
