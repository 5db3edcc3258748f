// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/code_run.hpp"
#include "bench/core_run.hpp"

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

/// Every run of one reference code in a bench, and the one the result reports.
struct CodeBench {
  BenchCode code;
  std::vector<CodeRun> runs;     ///< every repetition, in order (alternating with the core's)
  std::optional<CodeRun> median; ///< the median run by particle-steps/s, or the first failed one
};

/// Everything `demwb bench` measured on one scene.
struct BenchResult {
  std::string scene;
  std::string description;
  std::size_t particles = 0;
  std::uint64_t steps = 0;
  std::optional<CoreRun> core;       ///< the core's median run (by particle-steps/s)
  std::vector<CoreRun> core_runs;    ///< every repetition, in order (core and the codes alternate)
  std::vector<CodeBench> codes;      ///< the reference codes asked for, in the order asked
  std::vector<EnergyCheck> checks;
  /// Translational kinetic energy at the last step by engine [J] (a box or case file): the
  /// codes ran the same physics when these agree to the chaos of the contacts.
  std::map<std::string, double> kinetic_energy_at_end;
  std::vector<std::string> notes;

  /// The code with this engine name, or null.
  [[nodiscard]] const CodeBench* code(std::string_view engine) const;
  /// Core particle-steps/s over the code's, when both ran: the median of the ratios of the runs
  /// made one after the other (repetition k of the core over repetition k of the code).
  [[nodiscard]] std::optional<double> ratio(std::string_view engine) const;
  /// Every pairwise ratio against the code.
  [[nodiscard]] std::vector<double> ratios(std::string_view engine) const;
  /// True when every check matched and every code asked for ran (or cannot express the scene).
  [[nodiscard]] bool ok() const;
};

/// Sets `core` and every code's `median` from their runs.
void choose_medians(BenchResult& r);

/// bench.json: {"scene", "n_particles", "steps", "engines": {"inhouse": {...}, "lammps": {...},
/// "liggghts": {...}}, "ratio_inhouse_to_lammps", "ratio_inhouse_to_liggghts", "repetitions",
/// "checks", "notes"}.
nlohmann::json bench_json(const BenchResult& r);
/// report.md: the scene, a table per engine, the ratios, the checks and how to reproduce.
std::string bench_markdown(const BenchResult& r, const std::string& command);
/// A short table for the terminal.
std::string bench_table(const BenchResult& r);

}  // namespace bench
