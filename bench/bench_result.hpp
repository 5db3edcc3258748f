// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/core_run.hpp"
#include "bench/lammps_run.hpp"

namespace bench {

/// One energy the core must reproduce (the chute's step-100 thermo), as printed digits.
struct EnergyCheck {
  std::string quantity;   ///< e.g. "KinEng at step 100"
  std::string core;       ///< the core's value to the printed digits
  std::string core_exact; ///< the core's value to 17 significant digits (round-off tracking)
  std::string reference;  ///< LAMMPS's reference log
  std::string lammps;     ///< this machine's LAMMPS run, when it ran
  bool match = false;     ///< core == reference (and == lammps when it ran)
};

/// Everything `demwb bench` measured on one scene.
struct BenchResult {
  std::string scene;
  std::string description;
  std::size_t particles = 0;
  std::uint64_t steps = 0;
  std::optional<CoreRun> core;       ///< the core's median run (by particle-steps/s)
  std::optional<LammpsRun> lammps;   ///< LAMMPS's median run
  std::vector<CoreRun> core_runs;    ///< every repetition, in order (core and LAMMPS alternate)
  std::vector<LammpsRun> lammps_runs;
  std::vector<EnergyCheck> checks;
  std::vector<std::string> notes;

  /// Core particle-steps/s over LAMMPS's, when both ran: the median of the ratios of the runs
  /// made one after the other (repetition k of the core over repetition k of LAMMPS).
  [[nodiscard]] std::optional<double> ratio() const;
  /// Every pairwise ratio.
  [[nodiscard]] std::vector<double> ratios() const;
  /// True when every check matched and every engine asked for ran (or cannot express the scene).
  [[nodiscard]] bool ok() const;
};

/// Sets `core` and `lammps` to the median runs of `core_runs` and `lammps_runs`.
void choose_medians(BenchResult& r);

/// bench.json: {"scene", "n_particles", "steps", "engines": {"inhouse": {...}, "lammps": {...}},
/// "ratio_inhouse_to_lammps", "repetitions", "checks", "notes"}.
nlohmann::json bench_json(const BenchResult& r);
/// report.md: the scene, a table per engine, the ratio, the checks and how to reproduce.
std::string bench_markdown(const BenchResult& r, const std::string& command);
/// A short table for the terminal.
std::string bench_table(const BenchResult& r);

}  // namespace bench
