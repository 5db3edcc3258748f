// SPDX-License-Identifier: MIT
// `demwb gate`: exit 0 only when every comparison is pass or n/a, and no in-house metric drifted
// from its committed baseline. A suite is run in-process (run_suite) and its typed results are
// judged; a directory's results.json is read into the same types (results::read_suite_results).
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/case_runner.hpp"
#include "app/cli.hpp"
#include "app/options.hpp"
#include "app/suite_runner.hpp"
#include "cases/case_library.hpp"
#include "results/gate.hpp"
#include "support/text_file.hpp"

namespace app {

int command_gate(const std::vector<std::string>& args, const Invocation& inv) {
  namespace po = boost::program_options;
  po::options_description opts("options");
  opts.add_options()("baseline", po::value<std::string>(),
                     "baseline file or directory for the drift check (default cases/baselines)")(
      "allow-missing", "let comparisons with an engine that is not installed pass")(
      "output,o", po::value<std::string>(), "where a suite run writes its report (default out/gate-<suite>)")(
      "jobs,j", po::value<unsigned>()->default_value(1), "cases run concurrently (suite runs)");
  add_run_options(opts);
  add_tier_option(opts);
  const auto vm = parse_command(args, "usage: demwb gate DIR|SUITE [--baseline FILE] [--allow-missing] [--tier fast|full]", opts,
                                {"target"});
  if (!vm) return kExitOk;
  const std::string target = (*vm)["target"].as<std::string>();
  results::SuiteResults found;
  if (const std::filesystem::path dir = target; std::filesystem::exists(dir / "results.json")) {
    const std::filesystem::path file = dir / "results.json";
    refuse_matches(*vm, "gate DIR");  // results already written: nothing runs here
    found = results::read_suite_results(nlohmann::ordered_json::parse(support::read_file(file)), file.string());
  } else {
    // A suite: run it here, then gate what it returned.
    const std::filesystem::path out =
        vm->count("output") != 0 ? std::filesystem::path((*vm)["output"].as<std::string>())
                                 : std::filesystem::path("out") / ("gate-" + cases::resolve_suite(target).filename().string());
    const SuiteRun run = run_suite(target, out, *vm, inv);
    std::cout << suite_summary(run) << "\nwrote " << (out / "report.md").string() << "\n";
    if (vm->count("no-match") != 0) std::cout << kNoMatchNote;
    found = suite_results(run);
  }
  results::GateOptions options;
  options.allow_missing = vm->count("allow-missing") != 0;
  options.baselines = vm->count("baseline") != 0
                          ? std::optional<std::filesystem::path>((*vm)["baseline"].as<std::string>())
                          : default_baselines();
  const results::GateFindings g = results::gate(found, options);
  for (const auto& n : g.notes) std::cout << "note: " << n << "\n";
  for (const auto& f : g.failures) std::cout << "FAIL " << f << "\n";
  std::cout << results::gate_summary(g, options) << "\n";
  return g.passed() ? kExitOk : kExitFailed;
}

}  // namespace app
