// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include "cases/scene.hpp"

namespace reference::lammps {

/// The conventions and workarounds of a LAMMPS run of `scene`, for reports (RunResult::
/// conventions): integrator, time step, rotation, contact onset, fix freeze and m_eff, explicit
/// pair coefficients, η per type pair, the registry's mapping text of each chosen sub-model, box,
/// gravity, where each trace column comes from, output precision, version and run directory.
std::map<std::string, std::string> run_conventions(const cases::Scene& scene, double dt,
                                                   std::uint64_t steps,
                                                   const std::string& version,
                                                   const std::filesystem::path& dir);

}  // namespace reference::lammps
