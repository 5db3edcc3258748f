// SPDX-License-Identifier: MIT
#pragma once
// Pictures of a packed bed for the report: snapshots seen along x (the view the ORF takes, thesis
// fig. 6.3), each sphere a disc coloured by its speed, nearer spheres drawn over farther ones.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cases/run_result.hpp"
#include "cases/scene.hpp"

namespace reports {

/// The window of a view along x: y and z ranges [m], and the speed that takes the colour
/// scale's top [m/s].
struct ProjectionWindow {
  double y_min = 0.0;
  double y_max = 0.0;
  double z_min = 0.0;
  double z_max = 0.0;
  double speed_max = 0.0;
};

/// The window around the compare.packing region of `scene`: the region widened by a tenth of its
/// extent along y on both sides and below, and by its height above (where fluidised spheres leave),
/// coloured up to the largest speed of the mobile spheres in `snapshots` (1 m/s when all rest).
ProjectionWindow packing_window(const cases::Scene& scene, const std::vector<cases::Snapshot>& snapshots);

/// The indices of at most `frames` snapshots of `count`, evenly spread, first and last included.
std::vector<std::size_t> frame_indices(std::size_t count, std::size_t frames);

/// The snapshots to show of a bed that empties, from its ORF at every snapshot: the first, then the
/// rest spread evenly from the last snapshot before the ORF has fallen by 2 % of its whole fall to
/// the first at which 98 % of it is done — the fluidisation itself, not the still bed before or the
/// empty reservoir after. A bed whose ORF falls by less than 0.05 gets frame_indices.
std::vector<std::size_t> fluidisation_frames(std::span<const double> orf, std::size_t frames);

/// Draws `snap` seen along x into `png` (data and script beside it): the mobile spheres as discs of
/// their radius in the y–z plane, farthest (largest x) first, coloured by speed; fixed spheres grey;
/// the packing region's outline. Returns empty on success, else why not.
std::optional<std::string> render_projection(const cases::Scene& scene, const cases::Snapshot& snap,
                                             const ProjectionWindow& window, const std::string& title,
                                             const std::filesystem::path& png);

}  // namespace reports
