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
#include "bench/cpu_ceiling.hpp"
#include "bench/machine_probe.hpp"

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

/// The core on one thread pinned to one CPU (`--per-cpu`).
struct PinnedRun {
  int cpu = 0;
  int ran_on = -1;   ///< the CPU the thread was on when the run ended (sched_getcpu): `cpu` when the pin held
  int order = 0;     ///< its place among the repetition's pinned runs (0 first)
  CoreRun run;
};

/// The medians over the repetitions of what the pinned one-thread runs say (`--per-cpu`).
struct PerCpuSummary {
  std::size_t repetitions = 0;                 ///< the repetitions timed well enough to count
  std::vector<std::pair<int, double>> loop_s;  ///< each CPU with its median loop time [s] over those
  // Each a median taken on its own, so efficiency need not equal speedup / ceiling.
  double ceiling = 0.0;     ///< median CpuCeiling::ceiling
  double speedup = 0.0;     ///< median CpuCeiling::speedup (over the fastest CPU's one thread)
  double efficiency = 0.0;  ///< median CpuCeiling::efficiency
};

/// Everything `demwb bench` measured on one scene.
struct BenchResult {
  std::string scene;
  std::string description;
  std::size_t particles = 0;
  std::uint64_t steps = 0;
  std::optional<CoreRun> core;       ///< the core's median run (by particle-steps/s)
  std::vector<CoreRun> core_runs;    ///< every repetition, in order (core and the codes alternate)
  /// With `--speedup`: the core on one thread, run in every repetition right after its run on
  /// `threads` threads, and the median of those runs.
  std::vector<CoreRun> one_thread_runs;
  std::optional<CoreRun> one_thread;
  /// With `--speedup`: what the machine gave the same threads against one, probed right after
  /// each pair of core runs (kernels independent of the core).
  std::vector<MachineProbe> machine_probes;
  /// With `--per-cpu`: in every repetition, right after the run on `threads` threads, the core
  /// on one thread pinned to each CPU in turn.
  std::vector<std::vector<PinnedRun>> pinned_runs;
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
  /// The core's speed-up on its threads over one thread, one value per repetition (the two runs
  /// made one after the other); empty without one-thread runs.
  [[nodiscard]] std::vector<double> speedups() const;
  /// The median of speedups(), when there are one-thread runs.
  [[nodiscard]] std::optional<double> speedup() const;
  /// The medians of the machine probes' ratios, when there are probes.
  [[nodiscard]] std::optional<MachineProbe> machine() const;
  /// CpuCeiling of repetition k's run on `threads` threads from its pinned runs; none without
  /// them, or when a run there was too short to time (a speed that is not positive and finite).
  [[nodiscard]] std::optional<CpuCeiling> ceiling_at(std::size_t k) const;
  /// ceiling_at() of every repetition that has one, in order.
  [[nodiscard]] std::vector<CpuCeiling> ceilings() const;
  /// The medians of the pinned runs and of ceilings(), when there are pinned runs.
  [[nodiscard]] std::optional<PerCpuSummary> per_cpu() const;
  /// True when every run of the core, on one thread (pinned or not) and on several, ended in the
  /// same state to the last bit (the deterministic mode); nullopt without one-thread runs.
  [[nodiscard]] std::optional<bool> identical_across_threads() const;
  /// True when every check matched (the energies, and identical states across thread counts) and every code asked for ran (or cannot express the scene).
  [[nodiscard]] bool ok() const;
};

/// Sets `core`, `one_thread` and every code's `median` from their runs.
void choose_medians(BenchResult& r);

/// bench.json: {"scene", "n_particles", "steps", "engines": {"inhouse": {...}, "lammps": {...},
/// "liggghts": {...}}, "ratio_inhouse_to_lammps", "ratio_inhouse_to_liggghts", "thread_speedup"
/// (null without `--speedup`), "per_cpu" (null without `--per-cpu`), "repetitions", "checks", "notes"}.
nlohmann::json bench_json(const BenchResult& r);
/// report.md: the scene, a table per engine, the ratios, the checks and how to reproduce.
std::string bench_markdown(const BenchResult& r, const std::string& command);
/// A short table for the terminal.
std::string bench_table(const BenchResult& r);

}  // namespace bench
