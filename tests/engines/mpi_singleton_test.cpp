// SPDX-License-Identifier: MIT
// LAMMPS and LIGGGHTS run as Open MPI singletons (no mpirun). In the drivers' environment
// (reference::mpi_singleton_environment) such a run starts no `orted` support daemon; without the
// setting the same run does, so the check below can see one.
#include <chrono>
#include <filesystem>
#include <future>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "reference/common/run_directory.hpp"
#include "support/process.hpp"
#include "support/text_file.hpp"
#include "test_scratch.hpp"

namespace mpi_singleton_test {

namespace fs = std::filesystem;

/// True when a process named `orted` runs with its working directory `dir` (a singleton's daemon
/// starts where its parent runs).
bool orted_runs_in(const fs::path& dir) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator("/proc", ec)) {
    const std::string pid = entry.path().filename().string();
    if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
    if (support::read_file_or_empty(entry.path() / "comm") != "orted\n") continue;
    std::error_code link;
    if (fs::read_symlink(entry.path() / "cwd", link) == dir) return true;
  }
  return false;
}

/// Whether an `orted` ran while `lmp` worked through a deck that waits two seconds in `dir` with
/// `environment`; the run itself must succeed.
bool saw_orted(const fs::path& dir, const std::map<std::string, std::string>& environment) {
  support::write_file(dir / "deck.in", "shell sleep 2\n");
  support::ProcessSpec spec;
  spec.argv = {"lmp", "-in", "deck.in", "-log", "none", "-screen", "none"};
  spec.working_directory = dir;
  spec.environment = environment;
  spec.timeout_s = 60.0;
  auto run = std::async(std::launch::async, [&] { return support::run_process(spec); });
  bool seen = false;
  while (run.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
    seen = seen || orted_runs_in(dir);
  }
  const support::ProcessResult result = run.get();
  EXPECT_TRUE(result.started) << result.error;
  EXPECT_EQ(result.exit_code, 0);
  return seen;
}

TEST(MpiSingleton, TheDriversEnvironmentStartsNoOrtedDaemon) {
  if (!support::find_program("lmp")) GTEST_SKIP() << "lmp is not installed (scripts/setup.sh installs it)";
  const fs::path base = fs::temp_directory_path() / "demwb-engine-tests" / demwb_engine_test::current_test_folder();
  fs::remove_all(base);
  fs::create_directories(base / "plain");
  fs::create_directories(base / "driver");
  const fs::path plain_dir = fs::canonical(base / "plain");
  const fs::path driver_dir = fs::canonical(base / "driver");
  // A singleton left to its defaults forks the daemon in MPI_Init: the check sees it.
  auto plain = reference::mpi_singleton_environment(plain_dir);
  ASSERT_EQ(plain.erase("OMPI_MCA_ess_singleton_isolated"), 1U);
  EXPECT_TRUE(saw_orted(plain_dir, plain));
  // The drivers' environment starts none.
  EXPECT_FALSE(saw_orted(driver_dir, reference::mpi_singleton_environment(driver_dir)));
}

}  // namespace mpi_singleton_test
