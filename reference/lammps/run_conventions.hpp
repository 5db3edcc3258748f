// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include "cases/scene.hpp"
#include "reference/common/prepared_scene.hpp"

namespace reference::lammps {

/// The conventions and workarounds of a LAMMPS run of the prepared scene, for reports (RunResult::
/// conventions): integrator, time step, rotation, contact onset, fix freeze and m_eff, explicit
/// pair coefficients, η per type pair, the registry's mapping text of each chosen sub-model, box,
/// gravity, where each trace column comes from, output precision and version (the run directory is RunResult::scratch_dir).
std::map<std::string, std::string> run_conventions(const PreparedScene& prepared, double dt,
                                                   std::uint64_t steps,
                                                   const std::string& version);

/// Metrics of `scene` that LAMMPS cannot produce as the case defines them, with the reason:
/// with JKR cohesion and jkr_rupture = "displacement", LAMMPS 2021 breaks the neck at the
/// load-controlled pull-off overlap δ_f (pair_granular's pulloff_distance), not at δ_c, so the
/// rupture separation, the force at rupture and the separation work are LAMMPS' own rule's;
/// with walls, friction, rotation and wall_lever_arm = "contact_point", the spin after impact
/// and the tangential restitution (fix wall/gran's lever arm is r).
std::map<std::string, std::string> inexpressible_metrics(const cases::Scene& scene);

}  // namespace reference::lammps
