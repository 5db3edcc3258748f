// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "cases/run_result.hpp"

namespace reports {

/// One snapshot as a legacy-VTK polydata file for ParaView: particle centres as points, with
/// point data radius, effect_radius, fixed, material (index into the case's materials), contacts,
/// velocity and angular_velocity (SI units; render with a sphere glyph scaled by `radius`).
std::string snapshot_vtk(const cases::Scene& scene, const cases::Snapshot& snapshot,
                         const std::string& engine);

/// Body contacts of each sphere in a snapshot: the other spheres it overlaps (δ > 0) plus the
/// walls it overlaps (centre closer to the plane than its radius, the wall at the snapshot's time).
std::vector<int> snapshot_contacts(const cases::Scene& scene, const cases::Snapshot& snapshot);

/// The ParaView time series of one engine's snapshots (`<engine>.vtk.series`, JSON): each file
/// name with its time, so ParaView opens the legacy-VTK files as one animation.
std::string vtk_series(const std::vector<std::pair<std::string, double>>& files);

}  // namespace reports
