// SPDX-License-Identifier: MIT
#pragma once

#include "cases/scene.hpp"
#include "reference/common/code_conventions.hpp"

namespace reference::liggghts {

/// The scene the in-house core runs to reproduce LIGGGHTS-PUBLIC 3.8.0's numerics: velocity
/// Verlet as `fix nve/sphere` with the pinned Δt; the Coulomb basis |F_el + F_d|
/// (FrictionLimit::elastic_damping); the slip increment added, then projected without rescaling
/// (TangentialHistory::increment_project); the Coulomb limit tested on the spring alone, the dashpot
/// dropped while sliding (CoulombTest::spring); lever arm and contact-point velocity r − δ/2 for
/// pairs and walls (contact_point). The dashpots need no change: the driver feeds LIGGGHTS the
/// core's own (a restitution coefficient whose Hertz dashpot is the core's 'tsuji', or η in kg/s).
cases::Scene matched_scene(const PreparedScene& prepared);

/// LIGGGHTS's numerics as the matched engine "inhouse@liggghts" adopts them.
[[nodiscard]] const CodeConventions& conventions() noexcept;

}  // namespace reference::liggghts
