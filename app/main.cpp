// SPDX-License-Identifier: MIT
// demwb: the dem-workbench command line. Thin: each command lives in its own file.
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "app/cli.hpp"
#include "support/build_info.hpp"
#include "support/interrupts.hpp"

namespace {

constexpr std::string_view kUsage = R"(usage: demwb <command> [options]

commands:
  run CASE.toml [--engine E ...] [-o DIR]     run a case on engines, write results
  compare CASE.toml [--engines E,F] [-o DIR]  run and print the discrepancy table
  suite canonical|DIR [-j N] [-o DIR] [--tier fast|full]  every case of a suite, one report
  sweep SWEEP.toml [-j N] [-o DIR]            a parameter matrix over a case, several seeds per point
  study integrators [-o DIR]                  the integrator-accuracy study (thesis ch. 4)
  gate DIR|SUITE [--tier fast|full] [--baseline F] [--allow-missing]  exit 0 only when every comparison is green
  refresh [SUITE|CASE] [--write-baselines]    re-run reference codes into the cache/baselines
  refresh --sweep SWEEP.toml [-j N]           re-run a committed sweep and store its results
  bench chute|box [--threads N] [--ranks N]    the core against LAMMPS: particle-steps/s, memory
  engines [--lammps PATH] [--yade PATH] [--liggghts PATH]  installed engines, their versions and where they are
  fuzz-matched --code lammps|yade|liggghts [--count N] [--seed S]  random scenes: the code against its matched core
  convert linear-to-jkr|jkr-to-linear ...     appendix E: linear cohesion <-> JKR

options:
  -h, --help      help (also after a command: demwb run --help)
  --version       print the version

reference binaries: --lammps PATH / --yade PATH / --liggghts PATH, else $DEMWB_LAMMPS / $DEMWB_YADE /
$DEMWB_LIGGGHTS, else lmp / yade / liggghts in PATH

exit codes: 0 all green, 1 a comparison failed or an engine errored or is missing, 2 bad usage or
case file, 130 / 143 interrupted by SIGINT / SIGTERM (reference runs stopped, partial outputs removed)
)";

}  // namespace

int main(int argc, char** argv) {
  // SIGINT/SIGTERM stop the reference runs and remove partial outputs (support/interrupts.hpp).
  support::install_interrupt_handling();
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "-h" || args[0] == "--help" || args[0] == "help") {
    std::fputs(kUsage.data(), args.empty() ? stderr : stdout);
    return args.empty() ? app::kExitUsage : app::kExitOk;
  }
  if (args[0] == "--version") {
    std::printf("demwb %s (%s)\n", support::kVersion, support::kGitCommit);
    return app::kExitOk;
  }
  const app::Invocation inv{argc, argv};
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  try {
    if (args[0] == "run") return app::command_run(rest, inv);
    if (args[0] == "fuzz-matched") return app::command_fuzz_matched(rest, inv);
    if (args[0] == "compare") return app::command_compare(rest, inv);
    if (args[0] == "suite") return app::command_suite(rest, inv);
    if (args[0] == "sweep") return app::command_sweep(rest, inv);
    if (args[0] == "study") return app::command_study(rest, inv);
    if (args[0] == "engines") return app::command_engines(rest, inv);
    if (args[0] == "gate") return app::command_gate(rest, inv);
    if (args[0] == "refresh") return app::command_refresh(rest, inv);
    if (args[0] == "convert") return app::command_convert(rest, inv);
    if (args[0] == "bench") return app::command_bench(rest, inv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "demwb %s: error: %s\n", args[0].c_str(), e.what());
    return app::kExitUsage;
  }
  std::fprintf(stderr, "demwb: unknown command '%s'\n\n%s", args[0].c_str(), kUsage.data());
  return app::kExitUsage;
}
