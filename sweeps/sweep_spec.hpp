// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sweeps/case_override.hpp"

namespace sweeps {

/// A case-file key that moves with an axis: it takes its own value at each of the axis' values
/// (e.g. the run's duration with an orifice's size).
struct LinkedKey {
  std::string key;
  std::vector<double> values;  ///< one per value of the axis
};

/// One swept parameter: a dotted key of the case file and the values it takes.
struct SweepAxis {
  std::string key;             ///< e.g. "materials.linear_benchmark.cohesive_stiffness", "stages[0].pull"
  std::string label;           ///< short name in tables and plots (default: the key's last part)
  std::vector<double> values;  ///< at least one, in the order given
  bool log_scale = false;      ///< plot this axis on a logarithmic scale
  std::vector<LinkedKey> linked{};  ///< keys set together with this one (parameters[i].with)
};

/// The Beverloo fit of a hopper sweep ([beverloo], docs/hopper.md): which axis holds the orifice
/// and what the law needs besides the measured flow rates.
struct BeverlooSpec {
  std::size_t axis = 0;            ///< the axis holding the orifice (`orifice`, one of the axes' keys)
  double orifice_scale = 1.0;      ///< D = this × the axis value (2 when the axis holds a radius)
  double grain_diameter = 0.0;     ///< d [m]
  double grain_density = 0.0;      ///< ρ_p [kg/m³]; ρ_b = φ ρ_p
  std::string flow_rate = "mass_flow_rate";         ///< metric holding W
  std::string packing_fraction = "packing_fraction";  ///< metric holding the bed's φ
  double gravity = 9.81;           ///< g [m/s²]
};

/// A sweep file (docs/sweeps.md): a case, the parameters varied over it, the seeds of each point.
struct SweepSpec {
  std::string name;
  std::string description;
  std::filesystem::path source_path;  ///< the sweep file
  std::string source_text;            ///< its exact bytes
  std::filesystem::path case_file;    ///< the base case, resolved against the sweep file's folder
  std::vector<std::uint64_t> seeds;   ///< population seeds run at every point
  std::vector<std::string> engines;   ///< empty: the case's compare.engines
  std::vector<std::string> metrics;   ///< empty: the case's compare.metrics
  /// Seconds before a reference code's run is killed ([sweep] timeout); none: the command's
  /// --timeout. An explicit --timeout wins over it.
  std::optional<double> timeout_s;
  std::vector<FixedSetting> fixed;    ///< [sweep] set: case keys held at one value in every run
  std::vector<SweepAxis> axes;        ///< the matrix is their Cartesian product
  std::optional<BeverlooSpec> beverloo;  ///< fit Beverloo's law to the flow rates ([beverloo])
};

/// One point of the matrix: its index and one value per axis.
struct SweepPoint {
  std::size_t index = 0;
  std::vector<double> values;
  std::vector<std::size_t> positions;  ///< the index of each value in its axis
};

/// Every (key, value) the point sets in the case: each axis' key and its linked keys.
[[nodiscard]] std::vector<std::pair<std::string, double>> point_overrides(const SweepSpec& spec,
                                                                         const SweepPoint& point);

/// Reads a sweep file. Throws cases::CaseError naming the file and key on any problem (unknown
/// key, empty axis, repeated seed, missing case file).
SweepSpec load_sweep(const std::filesystem::path& file);
/// Reads sweep text named `path` in messages (the case file resolves against its folder).
SweepSpec load_sweep_text(const std::string& text, const std::filesystem::path& path);

/// The points of the matrix: the Cartesian product of the axes, the first axis varying slowest.
std::vector<SweepPoint> expand(const SweepSpec& spec);

}  // namespace sweeps
