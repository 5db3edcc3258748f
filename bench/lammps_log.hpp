// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace bench {

/// One thermo row: the step and every column by its header name.
struct ThermoRow {
  std::uint64_t step = 0;
  std::map<std::string, double> values;
};

/// What a LAMMPS or LIGGGHTS log says about a run's cost and state.
struct LammpsLog {
  double loop_s = 0.0;                  ///< sum of "Loop time of …" over every run command
  std::uint64_t steps = 0;              ///< sum of their steps
  std::uint64_t atoms = 0;              ///< atoms of the last run
  int procs = 0;                        ///< MPI ranks of the last run
  double memory_mb_per_rank = 0.0;      ///< largest "Per MPI rank memory allocation" average
  std::map<std::string, double> breakdown_s;  ///< "MPI task timing breakdown" averages, summed
  std::vector<ThermoRow> thermo;        ///< every thermo row, in order
};

/// Reads a log.lammps text (LAMMPS 2016–2022 formats) or a log of LIGGGHTS 3.8 (LAMMPS 2013's
/// memory line and timing breakdown).
LammpsLog parse_lammps_log(std::string_view text);

}  // namespace bench
