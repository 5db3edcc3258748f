// SPDX-License-Identifier: MIT
// `mpirun -np 2 demwb sweep`: the ranks share the runs, rank 0 writes the same sweep.csv a single
// process writes, and runs that fail on a rank are error rows, never dropped ones.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "../small_agglomerate.hpp"
#include "demwb_process.hpp"
#include "support/process.hpp"
#include "support/text_file.hpp"

namespace sweep_mpi_test {

using demwb_e2e::demwb;
using demwb_e2e::scratch;
namespace fs = std::filesystem;

/// Runs `mpirun -np 2 demwb ARGS` (as root too: the CI runs as root); exit code and streams.
demwb_e2e::Outcome mpirun_demwb(const std::vector<std::string>& args, const fs::path& logs) {
  support::ProcessSpec spec;
  spec.argv = {"mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2", DEMWB_BINARY};
  spec.argv.insert(spec.argv.end(), args.begin(), args.end());
  // Containers often forbid the cross-memory attach OpenMPI's shared-memory transport tries first.
  spec.environment = {{"OMPI_MCA_btl_vader_single_copy_mechanism", "none"}};
  fs::create_directories(logs);
  spec.stdout_file = logs / "mpirun.out";
  spec.stderr_file = logs / "mpirun.err";
  spec.timeout_s = 300;
  const auto r = support::run_process(spec);
  EXPECT_TRUE(r.started) << r.error << " (install openmpi-bin: scripts/setup.sh)";
  EXPECT_FALSE(r.timed_out);
  return {r.exit_code, support::read_file(spec.stdout_file), support::read_file(spec.stderr_file)};
}

TEST(DemwbSweepMpi, TwoRanksWriteTheSweepCsvOneProcessWrites) {
  ASSERT_TRUE(support::find_program("mpirun").has_value()) << "mpirun is missing: install openmpi-bin";
  const fs::path dir = scratch("mpi_sweep_files");
  support::write_file(dir / "small.toml", test_support::small_agglomerate(8, 1));
  // Three points (one cannot be built: a negative cohesion stiffness) × 2 seeds: 6 runs, so each
  // rank runs three, the failing point's runs among them.
  support::write_file(dir / "mpi.toml", R"(
[sweep]
name = "mpi"
case = "small.toml"
seeds = [3, 4]
metrics = ["kappa_vol", "kappa_damage", "fragments", "cohesive_work"]
[[parameters]]
key = "materials.m.cohesive_stiffness"
values = [30.0, -5.0, 300.0]
)");
  const fs::path cache = scratch("mpi_sweep_cache");
  const fs::path ranks = scratch("mpi_sweep_ranks");
  const fs::path single = scratch("mpi_sweep_single");
  const auto m = mpirun_demwb({"sweep", (dir / "mpi.toml").string(), "-o", ranks.string(), "--cache", cache.string()},
                              scratch("mpi_sweep_logs"));
  EXPECT_EQ(m.exit_code, 1) << m.out << m.err;  // the negative stiffness rows are errors
  EXPECT_NE(m.err.find("rank 0: [3/3]"), std::string::npos) << m.err;
  EXPECT_NE(m.err.find("rank 1: [3/3]"), std::string::npos) << m.err;
  const auto s = demwb({"sweep", (dir / "mpi.toml").string(), "-j", "2", "-o", single.string(), "--no-cache"});
  EXPECT_EQ(s.exit_code, 1) << s.out << s.err;
  const std::string csv = support::read_file(ranks / "sweep.csv");
  EXPECT_EQ(csv, support::read_file(single / "sweep.csv"));
  std::size_t lines = 0;
  std::size_t errors = 0;
  std::size_t oks = 0;
  for (std::size_t at = csv.find('\n'); at != std::string::npos; at = csv.find('\n', at + 1)) {
    ++lines;
    const std::size_t next = csv.find('\n', at + 1);
    const std::string line = csv.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1);
    errors += line.find(",inhouse,error,") != std::string::npos ? 1 : 0;
    oks += line.find(",inhouse,ok,") != std::string::npos ? 1 : 0;
  }
  EXPECT_EQ(lines, 7U) << csv;  // header + 6 rows
  EXPECT_EQ(errors, 2U) << csv;
  EXPECT_EQ(oks, 4U) << csv;
  EXPECT_NE(csv.find("cohesive_stiffness"), std::string::npos);
  const std::string report = support::read_file(ranks / "report.md");
  EXPECT_NE(report.find("on 2 MPI ranks"), std::string::npos) << report;
  // Only rank 0 writes; nothing else lands in the output directory's top level.
  EXPECT_TRUE(fs::exists(ranks / "command.txt"));
}

}  // namespace
