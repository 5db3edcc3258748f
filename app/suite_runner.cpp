// SPDX-License-Identifier: MIT
#include "app/suite_runner.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <future>
#include <map>
#include <mutex>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/case_runner.hpp"
#include "app/options.hpp"
#include "cases/case_library.hpp"
#include "cases/case_loader.hpp"
#include "reports/case_outputs.hpp"
#include "reports/case_report.hpp"
#include "reports/junit.hpp"
#include "reports/markdown.hpp"
#include "reports/results_json.hpp"
#include "support/interrupts.hpp"
#include "support/text_file.hpp"

namespace app {
namespace {

namespace po = boost::program_options;

SuiteEntry run_entry(const std::filesystem::path& file, const std::filesystem::path& out,
                     RunContext ctx, const po::variables_map& vm) {
  SuiteEntry e{file, std::nullopt, "", 0.0};
  const auto start = std::chrono::steady_clock::now();
  try {
    const cases::Scene scene = with_matches(cases::load_case(file, ctx.load), vm);
    ctx.options.work_dir = out / scene.name / "work";
    e.outcome = run_case(scene, engines_to_run(scene, {}), ctx);
  } catch (const std::exception& ex) {
    e.load_error = ex.what();
  }
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return e;
}

comparison::Status entry_status(const SuiteEntry& e) {
  return e.outcome ? comparison::worst_status(*e.outcome) : comparison::Status::error;
}

std::string summary_table(const std::vector<SuiteEntry>& entries) {
  reports::MarkdownTable t({"case", "engines", "status", "worst rel. diff", "comparisons", "time (s)"});
  for (const auto& e : entries) {
    if (!e.outcome) {
      t.add_row({e.file.filename().string(), "—", reports::status_cell(comparison::Status::error), "—",
                 e.load_error, fmt::format("{:.2f}", e.seconds)});
      continue;
    }
    std::string engines;
    for (const auto& r : e.outcome->runs) {
      engines += (engines.empty() ? "" : ", ") + r.engine + " (" + std::string(cases::to_string(r.status)) + ")";
    }
    for (const auto& u : e.outcome->unlisted) {  // not listed by the case: the driver's verdict
      engines += fmt::format("{}{} (not listed: {})", engines.empty() ? "" : ", ", u.engine, reports::unlisted_verdict(u));
    }
    std::optional<double> worst;
    std::size_t green = 0;
    for (const auto& c : e.outcome->comparisons) {
      if (c.rel_diff && (!worst || *c.rel_diff > *worst)) worst = c.rel_diff;
      if (comparison::is_green(c.status)) ++green;
    }
    t.add_row({"[`" + e.outcome->scene.name + "`](#" + e.outcome->scene.name + ")", engines,
               reports::status_cell(entry_status(e)), reports::format_ratio(worst),
               fmt::format("{}/{} green", green, e.outcome->comparisons.size()),
               fmt::format("{:.2f}", e.seconds)});
  }
  return t.render();
}

/// Full tier: runs every cross-code sweep of `sweeps_dir` afresh (demwb sweep) into
/// `root`/<name>/ and reads the results back as ensembles; a sweep that fails is an ensemble
/// with its problem, which fails the gate.
std::vector<sweeps::StoredEnsemble> run_ensembles(const std::filesystem::path& sweeps_dir,
                                                  const std::filesystem::path& root, const po::variables_map& vm,
                                                  const Invocation& inv) {
  // The committed store tells which sweeps compare engines (and any that do not load).
  const auto listed = sweeps::stored_ensembles(sweeps_dir, root);
  std::map<std::string, std::string> failed;
  for (const auto& e : listed) {
    if (e.engines.empty()) continue;  // did not load: stored_ensembles says why
    const auto args = sweep_arguments(e.sweep_file, root / e.name, vm["jobs"].as<unsigned>(), vm);
    std::fprintf(stderr, "full tier: running the sweep %s\n", e.sweep_file.c_str());
    try {
      if (command_sweep(args, inv) != kExitOk) failed[e.name] = "some of its runs failed (see its report)";
    } catch (const std::exception& ex) {
      failed[e.name] = std::string("the sweep could not run: ") + ex.what();
    }
  }
  auto ran = sweeps::stored_ensembles(sweeps_dir, root);
  for (auto& e : ran) {
    if (const auto it = failed.find(e.name); it != failed.end()) {
      e.problem = it->second;
      e.current = false;
    }
  }
  return ran;
}

}  // namespace

SuiteRun run_suite(const std::string& suite_name, const std::filesystem::path& out, const po::variables_map& vm,
                   const Invocation& inv) {
  const std::filesystem::path dir = cases::resolve_suite(suite_name);
  const unsigned jobs = std::max(1U, vm["jobs"].as<unsigned>());
  const support::OwnedPathGuard partial = support::OwnedPathGuard::if_new(out);  // removed if interrupted
  RunContext context = run_context(vm, out);
  context.tier = tier_option(vm);
  context.survey_unlisted = true;
  const auto files = cases::case_files(dir);
  if (files.empty()) throw std::runtime_error("suite " + dir.string() + " holds no *.toml case");
  const bool terminal = ::isatty(STDERR_FILENO) != 0;

  std::mutex print_mutex;
  std::size_t cases_done = 0;
  const auto suite_clock = std::chrono::steady_clock::now();
  // One line per engine run: overwritten in place on a terminal, plain lines in CI logs.
  context.on_engine_done = [&](const cases::Scene& scene, const cases::RunResult& run) {
    const std::lock_guard lock(print_mutex);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - suite_clock).count();
    const std::string what = fmt::format("{} / {}: {} in {:.2f} s ({})", scene.name, run.engine,
                                         cases::to_string(run.status), run.wall_time_s,
                                         run.source == "run" ? "ran" : run.source);
    if (terminal) {
      const std::string eta = cases_done == 0 ? "—" : fmt::format("{:.0f} s", elapsed / static_cast<double>(cases_done) *
                                                                        static_cast<double>(files.size() - cases_done));
      std::fprintf(stderr, "\r\033[K[%zu/%zu cases] %s, elapsed %.1f s, ETA %s", cases_done, files.size(),
                   what.c_str(), elapsed, eta.c_str());
    } else {
      std::fprintf(stderr, "  %s\n", what.c_str());
    }
  };
  std::vector<SuiteEntry> entries(files.size());
  std::vector<std::future<SuiteEntry>> running;
  std::size_t next = 0;
  std::size_t done = 0;
  const auto suite_start = std::chrono::steady_clock::now();
  const auto report = [&](const SuiteEntry& e) {
    const std::lock_guard lock(print_mutex);
    cases_done = ++done;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - suite_start).count();
    const double eta = elapsed / static_cast<double>(done) * static_cast<double>(files.size() - done);
    std::fprintf(stderr, "%s[%zu/%zu] %s: %s (%.2f s)%s", terminal ? "\r\033[K" : "", done, files.size(),
                 e.file.stem().c_str(), std::string(comparison::to_string(entry_status(e))).c_str(), e.seconds,
                 terminal ? fmt::format(", elapsed {:.1f} s, ETA {:.1f} s", elapsed, eta).c_str() : "\n");
  };
  std::vector<std::size_t> slot_of;
  while (done < files.size()) {
    while (running.size() < jobs && next < files.size()) {
      running.push_back(std::async(std::launch::async, run_entry, files[next], out, context, std::cref(vm)));
      slot_of.push_back(next++);
    }
    for (std::size_t k = 0; k < running.size(); ++k) {
      if (running[k].wait_for(std::chrono::milliseconds(20)) != std::future_status::ready) continue;
      entries[slot_of[k]] = running[k].get();
      report(entries[slot_of[k]]);
      running.erase(running.begin() + static_cast<std::ptrdiff_t>(k));
      slot_of.erase(slot_of.begin() + static_cast<std::ptrdiff_t>(k));
      break;
    }
  }
  if (terminal) std::fputs("\n", stderr);

  const std::string command = reports::reproduce_command(inv.argc, inv.argv);
  std::string md = fmt::format("# dem-workbench suite `{}`\n\nCases from `{}`, {} tier{}.\n\nReproduce with:\n\n```sh\n{}\n```\n\n",
                               suite_name, dir.string(), cases::to_string(context.tier),
                               context.tier == cases::Tier::fast
                                   ? " (reference results of full-tier cases come from their committed baselines)"
                                   : " (every engine of every case ran)",
                               command);
  md += "## Summary\n\n" + summary_table(entries) + "\n";
  nlohmann::ordered_json all;
  all["suite"] = suite_name;
  all["tier"] = std::string(cases::to_string(context.tier));
  all["cases"] = nlohmann::ordered_json::array();
  comparison::Status worst = comparison::Status::not_applicable;
  for (const auto& e : entries) {
    worst = comparison::worse(worst, entry_status(e));
    if (!e.outcome) {
      all["cases"].push_back({{"case_file", e.file.string()}, {"status", "error"}, {"reason", e.load_error}});
      continue;
    }
    const std::filesystem::path case_dir = out / e.outcome->scene.name;
    reports::write_case_outputs(*e.outcome, case_dir, command, context.wall_times);
    md += "<a id=\"" + e.outcome->scene.name + "\"></a>\n\n";
    md += reports::case_section(*e.outcome, case_dir / "plots", out, 2);
    all["cases"].push_back(reports::results_json(*e.outcome, context.wall_times));
  }
  // The cross-code ensembles beside the suite (cases/sweeps): their committed results
  // (cases/baselines/sweeps) in the fast tier, run afresh in the full tier.
  const bool full = context.tier == cases::Tier::full;
  auto ensembles = full ? run_ensembles(dir.parent_path() / "sweeps", out / "ensembles", vm, inv)
                        : sweeps::stored_ensembles(dir.parent_path() / "sweeps", dir.parent_path() / "baselines" / "sweeps");
  md += sweeps::stored_ensembles_section(ensembles, out, full);
  all["ensembles"] = nlohmann::ordered_json::array();
  for (const auto& e : ensembles) {
    all["ensembles"].push_back({{"sweep", e.name},
                                {"current", e.current},
                                {"problem", e.problem},
                                {"cells_beyond_two_standard_errors", e.beyond_two}});
  }
  all["status"] = std::string(comparison::to_string(worst));
  support::write_file(out / "report.md", md);
  std::vector<const comparison::CaseOutcome*> outcomes;
  std::vector<std::pair<std::string, std::string>> broken;
  for (const auto& e : entries) {
    if (e.outcome) {
      outcomes.push_back(&*e.outcome);
    } else {
      broken.emplace_back(e.file.filename().string(), e.load_error);
    }
  }
  support::write_file(out / "junit.xml", reports::junit_xml(outcomes, suite_name, broken));
  support::write_file(out / "results.json", all.dump(2) + "\n");
  SuiteRun run;
  run.suite = suite_name;
  run.out = out;
  run.tier = context.tier;
  run.entries = std::move(entries);
  run.ensembles = std::move(ensembles);
  run.worst = worst;
  return run;
}

std::string suite_summary(const SuiteRun& run) { return summary_table(run.entries); }

results::SuiteResults suite_results(const SuiteRun& run) {
  results::SuiteResults r;
  r.suite = run.suite;
  r.tier = run.tier;
  for (const auto& e : run.entries) {
    r.cases.push_back(e.outcome ? results::case_results(*e.outcome) : results::failed_case(e.file.string(), e.load_error));
  }
  for (const auto& e : run.ensembles) r.ensembles.push_back({e.name, e.current, e.problem});
  return r;
}

}  // namespace app
