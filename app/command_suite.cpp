// SPDX-License-Identifier: MIT
// `demwb suite`: every case of a suite on the engines each names, one report.
#include <iostream>

#include "app/cli.hpp"
#include "app/options.hpp"
#include "app/suite_runner.hpp"
#include "cases/case_library.hpp"

namespace app {

int command_suite(const std::vector<std::string>& args, const Invocation& inv) {
  namespace po = boost::program_options;
  po::options_description opts("options");
  opts.add_options()("output,o", po::value<std::string>(), "output directory (default out/<suite>)")(
      "jobs,j", po::value<unsigned>()->default_value(1), "cases run concurrently");
  add_run_options(opts);
  add_tier_option(opts);
  const auto vm = parse_command(args, "usage: demwb suite canonical|DIR [-j N] [-o DIR] [--tier fast|full]", opts,
                                {"suite"});
  if (!vm) return kExitOk;
  const std::string suite_name = (*vm)["suite"].as<std::string>();
  const std::filesystem::path out = vm->count("output") != 0
                                        ? std::filesystem::path((*vm)["output"].as<std::string>())
                                        : std::filesystem::path("out") / cases::resolve_suite(suite_name).filename();
  const SuiteRun run = run_suite(suite_name, out, *vm, inv);
  std::cout << suite_summary(run) << "\nwrote " << (out / "report.md").string() << "\n";
  if (vm->count("no-match") != 0) std::cout << kNoMatchNote;
  return comparison::is_green(run.worst) ? kExitOk : kExitFailed;
}

}  // namespace app
