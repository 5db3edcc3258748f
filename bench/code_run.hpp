// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "bench/lammps_log.hpp"

namespace bench {

/// A reference code `demwb bench` times: LAMMPS or its granular fork LIGGGHTS, whose logs share
/// one format ("Loop time of …", the memory line, the timing breakdown).
struct BenchCode {
  std::string engine;    ///< "lammps" or "liggghts": the key in bench.json
  std::string title;     ///< "LAMMPS" or "LIGGGHTS", for tables
  std::string program;   ///< the binary timed
  std::string package;   ///< the Debian package that installs it
  std::string log_file;  ///< the log the run writes
  double probe_timeout_s = 10.0;  ///< limit of the version probe (and never beyond the run's timeout)
};

/// LAMMPS run as `program` (log.lammps).
BenchCode lammps_code(const std::string& program, double probe_timeout_s);
/// LIGGGHTS run as `program` (log.liggghts; its screen unbuffered, where some errors go alone).
BenchCode liggghts_code(const std::string& program, double probe_timeout_s);

/// What timing a reference code on one deck measured.
struct CodeRun {
  std::string engine;                ///< BenchCode::engine
  std::string status = "missing";    ///< "ok", "missing" (no binary / mpirun), "error" or "n/a"
  std::string reason;                ///< why not ok
  std::string version;               ///< banner version
  int ranks = 1;
  LammpsLog log;                     ///< loop time, steps, memory, thermo
  double particle_steps_per_s = 0.0;
  double bytes_per_particle = 0.0;   ///< the log's memory per rank × ranks / atoms
  std::filesystem::path dir;         ///< run directory (deck, log)
  std::string log_tail;              ///< end of the log when not ok
};

/// A file written beside the deck.
struct DeckFile {
  std::string name;
  std::string content;
};

/// Runs `deck` (written to dir/deck.in, with `files` beside it and each of `links` symlinked into
/// dir by its file name) with `code`, under `mpirun -np ranks` when ranks > 1, killed after
/// `timeout_s`.
CodeRun run_code_bench(const BenchCode& code, const std::string& deck, const std::filesystem::path& dir, int ranks,
                       double timeout_s, const std::vector<std::filesystem::path>& links,
                       const std::vector<DeckFile>& files = {});

}  // namespace bench
