// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "bench/lammps_log.hpp"

namespace bench {

/// What timing LAMMPS on one deck measured.
struct LammpsRun {
  std::string status = "missing";    ///< "ok", "missing" (no lmp / mpirun), "error" or "n/a"
  std::string reason;                ///< why not ok
  std::string version;               ///< banner version
  int ranks = 1;
  LammpsLog log;                     ///< loop time, steps, memory, thermo
  double particle_steps_per_s = 0.0;
  double bytes_per_particle = 0.0;   ///< "Per MPI rank memory allocation" × ranks / atoms
  std::filesystem::path dir;         ///< run directory (deck, log)
  std::string log_tail;              ///< end of the log when not ok
};

/// A file written beside the deck.
struct DeckFile {
  std::string name;
  std::string content;
};

/// Runs `deck` (written to dir/deck.in, with `files` beside it and each of `links` symlinked into
/// dir by its file name) with `program`, under `mpirun -np ranks` when ranks > 1, killed after
/// `timeout_s`.
LammpsRun run_lammps_bench(const std::string& program, const std::string& deck,
                           const std::filesystem::path& dir, int ranks, double timeout_s,
                           const std::vector<std::filesystem::path>& links,
                           const std::vector<DeckFile>& files = {});

}  // namespace bench
