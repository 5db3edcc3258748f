// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sweeps {

/// One swept parameter: a dotted key of the case file and the values it takes.
struct SweepAxis {
  std::string key;             ///< e.g. "materials.linear_benchmark.cohesive_stiffness", "stages[0].pull"
  std::string label;           ///< short name in tables and plots (default: the key's last part)
  std::vector<double> values;  ///< at least one, in the order given
  bool log_scale = false;      ///< plot this axis on a logarithmic scale
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
  std::vector<SweepAxis> axes;        ///< the matrix is their Cartesian product
};

/// One point of the matrix: its index and one value per axis.
struct SweepPoint {
  std::size_t index = 0;
  std::vector<double> values;
};

/// Reads a sweep file. Throws cases::CaseError naming the file and key on any problem (unknown
/// key, empty axis, repeated seed, missing case file).
SweepSpec load_sweep(const std::filesystem::path& file);
/// Reads sweep text named `path` in messages (the case file resolves against its folder).
SweepSpec load_sweep_text(const std::string& text, const std::filesystem::path& path);

/// The points of the matrix: the Cartesian product of the axes, the first axis varying slowest.
std::vector<SweepPoint> expand(const SweepSpec& spec);

}  // namespace sweeps
