// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "compare/packing_series.hpp"
#include "sweeps/seed_statistics.hpp"
#include "sweeps/sweep_spec.hpp"

namespace sweeps {

/// One engine's result of one run (a point × a seed): a row of sweep.csv.
struct SweepRow {
  std::size_t point = 0;
  std::uint64_t seed = 0;
  std::string engine;
  std::string status;                         ///< ok, error, missing, n/a
  std::vector<std::optional<double>> values;  ///< one per metric; empty when the run gave none
  std::string reason;                         ///< why a value or the run is missing
  /// The compare.packing region's ORF and dose at every snapshot (empty without a region): the
  /// fluidisation curve of this run (docs/sweeps.md, "Outputs").
  std::vector<comparison::PackingSample> bed{};
};

/// The rows of one run (every engine of one point × seed) and how long the run took.
struct SweepRun {
  std::size_t job = 0;  ///< point × seeds + seed index: the run's place in sweep.csv
  std::vector<SweepRow> rows;
  double seconds = 0.0;
};

/// Rows for every engine of a run that could not happen at all, each an error with `reason`.
std::vector<SweepRow> error_rows(std::size_t point, std::uint64_t seed, const std::vector<std::string>& engines,
                                 std::size_t metrics, const std::string& reason);

/// sweep.csv (docs/sweeps.md): a header, then the rows as given; numbers with 17 significant digits.
std::string sweep_csv(const SweepSpec& spec, const std::vector<SweepPoint>& points,
                      const std::vector<std::string>& metrics, const std::vector<SweepRow>& rows);

/// bed.csv (docs/sweeps.md): one line per snapshot of every row that has a bed curve — point, each
/// parameter's value, seed, engine, time, orf, dose_remaining; empty when no row has one.
std::string bed_csv(const SweepSpec& spec, const std::vector<SweepPoint>& points, const std::vector<SweepRow>& rows);

/// The mean over the seeds of the bed curves of one point and engine, snapshot by snapshot: the
/// mean time, and the statistics of the ORF (`dose` false) or of the dose remaining (true). A
/// snapshot counts the runs that reached it.
struct MeanCurve {
  std::vector<double> time;
  std::vector<SeedStatistics> value;
};
MeanCurve mean_bed_curve(const std::vector<SweepRow>& rows, std::size_t point, const std::string& engine, bool dose);

/// Runs as JSON text, for sending between MPI ranks; doubles survive the trip exactly.
std::string encode_runs(const std::vector<SweepRun>& runs);
/// The runs of encode_runs' text. Throws std::runtime_error on text it did not write.
std::vector<SweepRun> decode_runs(const std::string& text);

/// Statistics over the seeds of one metric (index `metric`) at one point for one engine.
SeedStatistics point_statistics(const std::vector<SweepRow>& rows, std::size_t point, const std::string& engine,
                                std::size_t metric);

}  // namespace sweeps
