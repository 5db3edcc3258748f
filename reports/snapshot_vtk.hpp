// SPDX-License-Identifier: MIT
#pragma once

#include <string>

#include "cases/run_result.hpp"

namespace reports {

/// One snapshot as a legacy-VTK polydata file for ParaView: particle centres as points, with
/// point data radius, effect_radius, fixed, velocity and angular_velocity (SI units; render
/// with a sphere glyph scaled by `radius`).
std::string snapshot_vtk(const cases::Scene& scene, const cases::Snapshot& snapshot,
                         const std::string& engine);

}  // namespace reports
