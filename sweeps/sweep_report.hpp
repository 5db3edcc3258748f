// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "sweeps/beverloo_fit.hpp"
#include "sweeps/sweep_rows.hpp"
#include "sweeps/sweep_spec.hpp"

namespace sweeps {

/// Everything a sweep's report shows.
struct SweepResults {
  const SweepSpec& spec;
  const std::vector<SweepPoint>& points;
  const std::vector<std::string>& engines;
  const std::vector<std::string>& metrics;
  const std::vector<SweepRow>& rows;  ///< every point × seed × engine, in sweep.csv order
  std::string command;                ///< reproduces the sweep
  double seconds = 0.0;               ///< wall time of the whole sweep
  int ranks = 1;                      ///< MPI ranks the runs were shared between
};

/// One plot of a metric against one axis: a curve per value of `family` (when the matrix has a
/// second axis with several values) and per engine, every other axis held at its middle value
/// (thesis figs 5.6–5.9 hold the remaining parameters at the benchmark, the middle of a matrix).
struct CurveFamily {
  std::size_t x_axis = 0;
  std::optional<std::size_t> family;  ///< the axis whose values label the curves
  std::vector<std::size_t> held;      ///< per axis: the value index held (ignored for x and family)
};

/// The curve families of a sweep: one per axis with at least two values.
std::vector<CurveFamily> curve_families(const SweepSpec& spec);

/// The point holding these value indices (one per axis; the first axis varies slowest).
std::size_t point_at(const SweepSpec& spec, const std::vector<std::size_t>& value_indices);

/// Beverloo's law fitted to one engine's flow rates (SweepSpec::beverloo).
struct EngineBeverloo {
  std::string engine;
  std::vector<double> orifice;     ///< D [m] of each orifice with a flow rate
  std::vector<double> rate;        ///< mean W over the seeds [kg/s]
  std::vector<double> rate_error;  ///< its standard error (0 with one seed)
  double bulk_density = 0.0;       ///< ρ_b [kg/m³]: the mean packing fraction × the grain density
  std::optional<BeverlooFit> fit;  ///< empty with `problem` set when it cannot be fitted
  std::string problem;
};

/// Beverloo fits per engine of a sweep with a [beverloo] table (empty without one), over the
/// orifice axis with every other axis held at its middle value.
std::vector<EngineBeverloo> beverloo_fits(const SweepResults& results);

/// Writes `dir`/report.md (means ± standard errors per point and engine; engines compared by the
/// difference of their means over the combined standard error) and its figures under
/// `dir`/plots: each metric against each axis, and κDAMAGE against the cohesive work
/// (thesis figs 5.14, 5.16). A figure that cannot be drawn is named in the report with the reason.
void write_sweep_report(const SweepResults& results, const std::filesystem::path& dir);

}  // namespace sweeps
