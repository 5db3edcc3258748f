// SPDX-License-Identifier: MIT
// `demwb run` and `demwb compare`: one case on several engines.
#include <cstdio>
#include <iostream>

#include <fmt/format.h>

#include "app/case_runner.hpp"
#include "app/cli.hpp"
#include "app/options.hpp"
#include "cases/case_loader.hpp"
#include "cases/catalogue.hpp"
#include "reports/case_outputs.hpp"
#include "reports/case_report.hpp"
#include "reports/markdown.hpp"
#include "support/interrupts.hpp"
#include "reference/registry.hpp"

namespace app {
namespace {

namespace po = boost::program_options;

/// Loads a case, printing its warnings; CaseError propagates to main as a usage error.
cases::Scene load(const std::string& path, const cases::LoadOptions& options) {
  cases::Scene scene = cases::load_case(path, options);
  for (const auto& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  return scene;
}

/// Rejects engine names the workbench does not know or cannot build.
void check_engines(const std::vector<std::string>& names) {
  for (const auto& n : names) {
    if (!cases::is_known_engine(n)) {
      throw std::invalid_argument(fmt::format("unknown engine '{}' (known: inhouse, analytic, lammps, yade)", n));
    }
    if (!reference::make_engine(n)) {
      throw std::invalid_argument(fmt::format("engine '{}' has no driver in this build yet", n));
    }
  }
}

/// Per-engine status and metric values, as a markdown table for the terminal.
std::string engine_summary(const comparison::CaseOutcome& o) {
  std::vector<std::string> header{"engine", "status", "wall time (s)"};
  for (const auto& m : o.scene.compare.metrics) header.push_back(m);
  reports::MarkdownTable t(header);
  for (const auto& r : o.runs) {
    std::vector<std::string> row{r.engine, std::string(cases::to_string(r.status)),
                                 fmt::format("{:.3f}", r.wall_time_s)};
    for (const auto& m : o.scene.compare.metrics) {
      const auto& set = o.metrics.at(r.engine);
      const auto it = set.find(m);
      row.push_back(it == set.end() ? "—" : reports::format_number(it->second.value));
    }
    t.add_row(row);
  }
  return t.render();
}

/// Notes of engines that did not run (missing, n/a, error), one line each.
void print_engine_notes(const comparison::CaseOutcome& o) {
  for (const auto& r : o.runs) {
    if (r.status == cases::RunStatus::ok) continue;
    std::cout << fmt::format("{}: {} — {}\n", r.engine, cases::to_string(r.status), r.reason);
    if (!r.log_tail.empty()) std::cout << r.log_tail;
  }
  for (const auto& u : o.unlisted) {
    std::cout << fmt::format("{} (not among the engines): {}{}\n", u.engine, reports::unlisted_verdict(u),
                             u.reason.empty() ? " (add it with --engines)" : " — " + u.reason);
  }
  for (const auto& r : o.runs) {
    for (const auto& w : r.warnings) std::fprintf(stderr, "warning: %s: %s\n", r.engine.c_str(), w.c_str());
  }
}

/// True when an engine errored or is missing: either fails a run.
bool any_engine_error(const comparison::CaseOutcome& o) {
  for (const auto& r : o.runs) {
    if (r.status == cases::RunStatus::error || r.status == cases::RunStatus::missing) return true;
  }
  return false;
}

}  // namespace

int command_run(const std::vector<std::string>& args, const Invocation& inv) {
  po::options_description opts("options");
  opts.add_options()("engine,e", po::value<std::vector<std::string>>()->composing(),
                     "engine to run (repeatable or comma-separated; default inhouse)")(
      "output,o", po::value<std::string>(), "output directory (default out/run/<case>)");
  add_run_options(opts);
  const auto vm = parse_command(args, "usage: demwb run CASE.toml [--engine E ...] [-o DIR]", opts, {"case"});
  if (!vm) return kExitOk;
  const cases::Scene scene = with_matches(load((*vm)["case"].as<std::string>(), load_options(*vm)), *vm);
  std::vector<std::string> engines{"inhouse"};
  if (vm->count("engine") != 0) engines = split_names((*vm)["engine"].as<std::vector<std::string>>());
  engines = engines_to_run(scene, engines);
  check_engines(engines);
  const std::filesystem::path out = vm->count("output") != 0
                                        ? std::filesystem::path((*vm)["output"].as<std::string>())
                                        : std::filesystem::path("out/run") / scene.name;
  const support::OwnedPathGuard partial = support::OwnedPathGuard::if_new(out);  // removed if interrupted
  const RunContext context = run_context(*vm, out / "work");
  comparison::CaseOutcome outcome = run_case(scene, engines, context);
  if (std::find(engines.begin(), engines.end(), scene.compare.reference) == engines.end()) {
    // The case's reference did not run: keep only rows whose own reference did (matched rows).
    std::erase_if(outcome.comparisons, [&](const comparison::Comparison& c) {
      return std::find(engines.begin(), engines.end(), c.reference) == engines.end();
    });
  }
  reports::write_case_outputs(outcome, out, reports::reproduce_command(inv.argc, inv.argv), context.wall_times);
  std::cout << engine_summary(outcome);
  if (!outcome.comparisons.empty()) std::cout << "\n" << reports::discrepancy_table(outcome);
  print_engine_notes(outcome);
  std::cout << "\nwrote " << (out / "results.json").string() << " and " << (out / "report.md").string() << "\n";
  return any_engine_error(outcome) ? kExitFailed : kExitOk;
}

int command_compare(const std::vector<std::string>& args, const Invocation& inv) {
  po::options_description opts("options");
  opts.add_options()("engines,e", po::value<std::vector<std::string>>()->composing(),
                     "engines to run (comma-separated or repeated; default: the case's compare.engines)")(
      "output,o", po::value<std::string>(), "also write results, traces and report.md here");
  add_run_options(opts);
  const auto vm = parse_command(args, "usage: demwb compare CASE.toml [--engines E,F] [-o DIR]", opts, {"case"});
  if (!vm) return kExitOk;
  const cases::Scene scene = with_matches(load((*vm)["case"].as<std::string>(), load_options(*vm)), *vm);
  std::vector<std::string> engines;
  if (vm->count("engines") != 0) engines = split_names((*vm)["engines"].as<std::vector<std::string>>());
  engines = engines_to_run(scene, engines);
  if (std::find(engines.begin(), engines.end(), scene.compare.reference) == engines.end()) {
    engines.insert(engines.begin(), scene.compare.reference);  // a comparison needs its reference
  }
  check_engines(engines);
  const std::filesystem::path out = vm->count("output") != 0
                                        ? std::filesystem::path((*vm)["output"].as<std::string>())
                                        : std::filesystem::temp_directory_path() / "demwb-compare";
  const support::OwnedPathGuard partial = support::OwnedPathGuard::if_new(out);  // removed if interrupted
  RunContext context = run_context(*vm, out / "work");
  context.survey_unlisted = true;
  const comparison::CaseOutcome outcome = run_case(scene, engines, context);
  if (vm->count("output") != 0) {
    reports::write_case_outputs(outcome, out, reports::reproduce_command(inv.argc, inv.argv), context.wall_times);
  }
  std::cout << fmt::format("case {} — reference {}\n\n", scene.name, scene.compare.reference);
  std::cout << engine_summary(outcome) << "\n" << reports::discrepancy_table(outcome);
  print_engine_notes(outcome);
  const comparison::Status worst = comparison::worst_status(outcome);
  std::cout << fmt::format("\nresult: {}\n", reports::status_cell(worst));
  return comparison::is_green(worst) ? kExitOk : kExitFailed;
}

std::vector<std::string> split_names(const std::vector<std::string>& values) {
  std::vector<std::string> out;
  for (const auto& v : values) {
    std::size_t start = 0;
    while (start <= v.size()) {
      const std::size_t comma = v.find(',', start);
      const std::string item = v.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      if (!item.empty()) out.push_back(item);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return out;
}

}  // namespace app
