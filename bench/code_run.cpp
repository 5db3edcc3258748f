// SPDX-License-Identifier: MIT
#include "bench/code_run.hpp"

#include <unistd.h>

#include <algorithm>

#include <fmt/format.h>

#include "reference/common/log_lines.hpp"
#include "reference/common/run_directory.hpp"
#include "reference/lammps/lammps_runner.hpp"
#include "reference/liggghts/liggghts_runner.hpp"
#include "support/process.hpp"
#include "support/text_file.hpp"

namespace bench {

BenchCode lammps_code(const std::string& program, double probe_timeout_s) {
  return {"lammps", "LAMMPS", program, "lammps", reference::lammps::kLogFile, probe_timeout_s};
}

BenchCode liggghts_code(const std::string& program, double probe_timeout_s) {
  return {"liggghts", "LIGGGHTS", program, "liggghts", reference::liggghts::kLogFile, probe_timeout_s};
}

CodeRun run_code_bench(const BenchCode& code, const std::string& deck, const std::filesystem::path& dir, int ranks,
                       double timeout_s, const std::vector<std::filesystem::path>& links,
                       const std::vector<DeckFile>& files) {
  CodeRun run;
  run.engine = code.engine;
  run.ranks = ranks;
  run.dir = dir;
  const auto lmp = support::find_program(code.program);
  if (!lmp) {
    run.reason = fmt::format("'{}' is not installed (Debian package {})", code.program, code.package);
    return run;
  }
  const bool liggghts = code.engine == "liggghts";
  const double probe_s = std::min(timeout_s, code.probe_timeout_s);
  const auto version = liggghts ? reference::liggghts::probe_liggghts(code.program, probe_s).version
                                : reference::lammps::lammps_version(code.program, probe_s);
  if (version) run.version = *version;
  std::optional<std::filesystem::path> mpirun;
  if (ranks > 1) {
    mpirun = support::find_program("mpirun");
    if (!mpirun) {
      run.reason = "--ranks needs mpirun (Debian package openmpi-bin)";
      return run;
    }
  }
  std::filesystem::create_directories(dir);
  // Nothing of an earlier run may pass for this one's.
  for (const std::string& stale : {code.log_file, std::string("stdout.txt"), std::string("stderr.txt")}) {
    std::error_code ec;
    std::filesystem::remove(dir / stale, ec);
  }
  support::write_file(dir / "deck.in", deck);
  for (const DeckFile& f : files) support::write_file(dir / f.name, f.content);
  for (const auto& file : links) {
    std::error_code ec;
    std::filesystem::remove(dir / file.filename(), ec);
    std::filesystem::create_symlink(std::filesystem::absolute(file), dir / file.filename());
  }
  support::ProcessSpec spec;
  if (mpirun) spec.argv = {mpirun->string(), "-np", std::to_string(ranks)};
  // LIGGGHTS writes some errors to the screen alone and aborts unflushed: its screen goes
  // unbuffered to stdout.txt. LAMMPS's screen is off (the log has everything).
  const auto stdbuf = liggghts ? support::find_program("stdbuf") : std::nullopt;
  if (stdbuf) {
    for (const std::string& a : {stdbuf->string(), std::string("-o0"), std::string("-e0")}) spec.argv.push_back(a);
  }
  for (const std::string& a : {lmp->string(), std::string("-in"), std::string("deck.in"), std::string("-log"), code.log_file}) {
    spec.argv.push_back(a);
  }
  if (!liggghts) {
    spec.argv.emplace_back("-screen");
    spec.argv.emplace_back("none");
  }
  spec.working_directory = dir;
  spec.stdout_file = dir / "stdout.txt";
  spec.stderr_file = dir / "stderr.txt";
  // As the reference runs: a code run alone is an Open MPI singleton, its session files kept
  // inside the run directory (two singletons starting at once race on a shared one).
  if (!mpirun) spec.environment = reference::mpi_singleton_environment(dir);
  spec.environment["OMP_NUM_THREADS"] = "1";
  if (mpirun && geteuid() == 0) {
    spec.environment["OMPI_ALLOW_RUN_AS_ROOT"] = "1";
    spec.environment["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1";
  }
  spec.timeout_s = timeout_s;
  const support::ProcessResult result = support::run_process(spec);
  const std::string log_text = support::read_file_or_empty(dir / code.log_file);  // none: an error below
  run.log = parse_lammps_log(log_text);
  if (!result.started) {
    run.status = "error";
    run.reason = "could not start: " + result.error;
  } else if (result.timed_out) {
    run.status = "error";
    run.reason = fmt::format("timed out after {} s", timeout_s);
  } else if (std::string error = reference::first_error(log_text + "\n" + support::read_file_or_empty(dir / "stdout.txt"));
             !error.empty()) {
    run.status = "error";
    run.reason = error;
  } else if (result.exit_code != 0 || run.log.steps == 0 || !(run.log.loop_s > 0.0) || run.log.atoms == 0) {
    run.status = "error";
    run.reason = result.signal      ? fmt::format("killed by signal {}", *result.signal)
                 : result.exit_code ? fmt::format("exit code {}", result.exit_code)
                                    : std::string("the log has no loop time (no \"Loop time of\" line with steps, atoms)");
  } else {
    run.status = "ok";
    run.particle_steps_per_s =
        static_cast<double>(run.log.atoms) * static_cast<double>(run.log.steps) / run.log.loop_s;
    run.bytes_per_particle = run.log.memory_mb_per_rank * 1024.0 * 1024.0 * run.log.procs /
                             static_cast<double>(run.log.atoms);
  }
  if (run.status != "ok") {
    run.log_tail = support::file_tail(dir / code.log_file, 20) + support::file_tail(dir / "stdout.txt", 10) +
                   support::file_tail(dir / "stderr.txt", 10);
  }
  return run;
}

}  // namespace bench
