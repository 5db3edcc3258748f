// SPDX-License-Identifier: MIT
#include "bench/lammps_run.hpp"

#include <unistd.h>

#include <fmt/format.h>

#include "reference/lammps/lammps_runner.hpp"
#include "support/process.hpp"
#include "support/text_file.hpp"

namespace bench {

LammpsRun run_lammps_bench(const std::string& program, const std::string& deck,
                           const std::filesystem::path& dir, int ranks, double timeout_s,
                           const std::vector<std::filesystem::path>& links,
                           const std::vector<DeckFile>& files) {
  LammpsRun run;
  run.ranks = ranks;
  run.dir = dir;
  const auto lmp = support::find_program(program);
  if (!lmp) {
    run.reason = fmt::format("'{}' is not installed (Debian package lammps)", program);
    return run;
  }
  if (const auto v = reference::lammps::lammps_version(program)) run.version = *v;
  std::optional<std::filesystem::path> mpirun;
  if (ranks > 1) {
    mpirun = support::find_program("mpirun");
    if (!mpirun) {
      run.reason = "--ranks needs mpirun (Debian package openmpi-bin)";
      return run;
    }
  }
  std::filesystem::create_directories(dir);
  support::write_file(dir / "deck.in", deck);
  for (const DeckFile& f : files) support::write_file(dir / f.name, f.content);
  for (const auto& file : links) {
    std::error_code ec;
    std::filesystem::remove(dir / file.filename(), ec);
    std::filesystem::create_symlink(std::filesystem::absolute(file), dir / file.filename());
  }
  support::ProcessSpec spec;
  if (mpirun) spec.argv = {mpirun->string(), "-np", std::to_string(ranks)};
  for (const std::string& a : {lmp->string(), std::string("-in"), std::string("deck.in"), std::string("-log"),
                               std::string("log.lammps"), std::string("-screen"), std::string("none")}) {
    spec.argv.push_back(a);
  }
  spec.working_directory = dir;
  spec.stdout_file = dir / "stdout.txt";
  spec.stderr_file = dir / "stderr.txt";
  spec.environment["OMP_NUM_THREADS"] = "1";
  if (mpirun && geteuid() == 0) {
    spec.environment["OMPI_ALLOW_RUN_AS_ROOT"] = "1";
    spec.environment["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1";
  }
  spec.timeout_s = timeout_s;
  const support::ProcessResult result = support::run_process(spec);
  std::string log_text;
  try {
    log_text = support::read_file(dir / "log.lammps");
  } catch (const std::exception&) {
    // no log: reported below as an error with the stderr tail
  }
  run.log = parse_lammps_log(log_text);
  if (!result.started) {
    run.status = "error";
    run.reason = "could not start: " + result.error;
  } else if (result.timed_out) {
    run.status = "error";
    run.reason = fmt::format("timed out after {} s", timeout_s);
  } else if (result.exit_code != 0 || run.log.steps == 0) {
    run.status = "error";
    run.reason = result.signal ? fmt::format("killed by signal {}", *result.signal)
                               : fmt::format("exit code {}", result.exit_code);
  } else {
    run.status = "ok";
    run.particle_steps_per_s =
        static_cast<double>(run.log.atoms) * static_cast<double>(run.log.steps) / run.log.loop_s;
    run.bytes_per_particle = run.log.memory_mb_per_rank * 1024.0 * 1024.0 * run.log.procs /
                             static_cast<double>(run.log.atoms);
  }
  if (run.status != "ok") {
    run.log_tail = support::file_tail(dir / "log.lammps", 20) + support::file_tail(dir / "stderr.txt", 10);
  }
  return run;
}

}  // namespace bench
