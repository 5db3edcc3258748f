// SPDX-License-Identifier: MIT
// `demwb refresh`: re-run the reference codes of a suite or case, store them in the cache, and
// optionally write the committed baselines.
#include <algorithm>
#include <iostream>

#include <fmt/format.h>

#include "app/case_runner.hpp"
#include "app/cli.hpp"
#include "app/options.hpp"
#include "cases/case_library.hpp"
#include "cases/case_loader.hpp"
#include "cases/catalogue.hpp"
#include "reports/markdown.hpp"
#include "store/scene_json.hpp"
#include "support/interrupts.hpp"
#include "sweeps/sweep_spec.hpp"
#include "reference/registry.hpp"

namespace app {

namespace {

namespace fs = std::filesystem;
namespace po = boost::program_options;

/// `demwb refresh --sweep SWEEP.toml`: runs a committed sweep afresh (demwb sweep) and stores what
/// it wrote — sweep.csv, bed.csv (when it has one), sweep.json (its fingerprint), report.md and
/// plots/ — in
/// <baselines>/sweeps/<name>/, replacing what was there. The suite reports that store and the
/// gate fails while it no longer fits the sweep and case files.
int refresh_sweep(const po::variables_map& vm, const Invocation& inv) {
  const fs::path file = vm["sweep"].as<std::string>();
  const sweeps::SweepSpec spec = sweeps::load_sweep(file);
  const fs::path out = fs::path(vm["output"].as<std::string>()) / spec.name;
  const fs::path root = vm.count("baselines") != 0 ? fs::path(vm["baselines"].as<std::string>())
                                                   : file.parent_path().parent_path() / "baselines";
  const fs::path dest = root / "sweeps" / spec.name;
  const auto sweep_args = sweep_arguments(file, out, vm["jobs"].as<unsigned>(), vm);
  fs::remove_all(out);
  const int status = command_sweep(sweep_args, inv);
  if (status != kExitOk) {
    throw std::runtime_error(fmt::format("some runs of the sweep {} failed (see {}); nothing was stored", file.string(),
                                         (out / "report.md").string()));
  }
  for (const char* needed : {"sweep.csv", "sweep.json", "report.md"}) {
    if (!fs::exists(out / needed)) {
      throw std::runtime_error(fmt::format("the sweep {} wrote no {} in {}; nothing was stored", file.string(), needed,
                                           out.string()));
    }
  }
  fs::remove_all(dest);
  fs::create_directories(dest);
  for (const char* kept : {"sweep.csv", "sweep.json", "report.md"}) fs::copy_file(out / kept, dest / kept);
  if (fs::exists(out / "bed.csv")) fs::copy_file(out / "bed.csv", dest / "bed.csv");
  if (fs::is_directory(out / "plots")) fs::copy(out / "plots", dest / "plots", fs::copy_options::recursive);
  std::cout << "stored " << dest.string() << "\n";
  return kExitOk;
}

}  // namespace

int command_refresh(const std::vector<std::string>& args, const Invocation& inv) {
  po::options_description opts("options");
  opts.add_options()("write-baselines", "also write <baselines>/<case>.json (reference results and in-house metrics)")(
      "sweep", po::value<std::string>(),
      "instead: run this committed sweep file and store its results in <baselines>/sweeps/<name>/")(
      "jobs,j", po::value<unsigned>()->default_value(2), "runs at once (--sweep)")(
      "output,o", po::value<std::string>()->default_value("out/refresh"), "scratch directory for the runs");
  add_run_options(opts);
  const auto vm = parse_command(
      args, "usage: demwb refresh [canonical|DIR|CASE.toml] [--write-baselines]  |  demwb refresh --sweep SWEEP.toml [-j N]",
      opts, {"target?"});
  if (!vm) return kExitOk;
  refuse_matches(*vm, "refresh");
  if (vm->count("sweep") != 0) {
    if (vm->count("target") != 0) throw std::invalid_argument("demwb refresh: give either --sweep FILE or a case target, not both");
    return refresh_sweep(*vm, inv);
  }
  const std::string target = vm->count("target") != 0 ? (*vm)["target"].as<std::string>() : "canonical";
  std::vector<std::filesystem::path> files;
  if (target.ends_with(".toml")) {
    files.push_back(target);
  } else {
    files = cases::case_files(cases::resolve_suite(target));
  }
  const support::OwnedPathGuard partial =
      support::OwnedPathGuard::if_new((*vm)["output"].as<std::string>());  // removed if interrupted
  RunContext ctx = run_context(*vm, (*vm)["output"].as<std::string>());
  ctx.refresh = true;
  const bool write = vm->count("write-baselines") != 0;
  if (write && !ctx.baselines) ctx.baselines = cases::resolve_suite(target.ends_with(".toml") ? "canonical" : target).parent_path() / "baselines";
  reports::MarkdownTable table({"case", "engine", "status", "version", "wall time (s)", "stored"});
  bool all_ok = true;
  for (const auto& file : files) {
    const cases::Scene scene = cases::load_case(file, ctx.load);
    std::vector<std::string> engines;
    for (const auto& e : scene.compare.engines) {
      if (cases::is_reference_code(e)) engines.push_back(e);
    }
    if (write) engines.push_back("inhouse");
    if (engines.empty()) continue;
    // The analytic solution, when the case has one, serves the time-step check of the codes'
    // amplitude_error (measured against it); it is not stored.
    const auto& listed = scene.compare.engines;
    if (std::find(listed.begin(), listed.end(), "analytic") != listed.end()) engines.push_back("analytic");
    ctx.options.work_dir = std::filesystem::path((*vm)["output"].as<std::string>()) / scene.name;
    RunContext fresh = ctx;
    fresh.refresh = true;           // re-run the reference codes, then store their results
    fresh.baselines = std::nullopt;  // never answer a refresh from the baselines
    const comparison::CaseOutcome o = run_case(scene, engines, fresh);
    store::Baseline baseline{scene.name, store::scene_fingerprint(o.scene), {}, {}, {}};
    for (const auto& r : o.runs) {
      const bool ok = r.status == cases::RunStatus::ok;
      if (r.engine == "analytic") continue;
      if (r.engine == "inhouse") {
        for (const auto& [metric, v] : o.metrics.at("inhouse")) {
          if (v.value) baseline.inhouse_metrics[metric] = *v.value;
        }
        continue;
      }
      if (ok) {
        baseline.references[r.engine] = r;
        // What the driver fed the code: the fast tier trusts this result only while it would
        // feed the same again.
        baseline.inputs[r.engine] = reference::make_engine(r.engine, ctx.programs)->input_fingerprint(o.scene);
      }
      // n/a is an answer (the code cannot express the case, with the reason); error and missing
      // are failures.
      all_ok = all_ok && (ok || r.status == cases::RunStatus::not_applicable);
      table.add_row({scene.name, r.engine, std::string(cases::to_string(r.status)), r.version,
                     fmt::format("{:.2f}", r.wall_time_s), ok && ctx.cache ? "cache" : "—"});
    }
    if (write) {
      const auto path = *ctx.baselines / (scene.name + ".json");
      store::write_baseline(path, baseline);
      std::cout << "wrote " << path.string() << "\n";
    }
  }
  std::cout << table.render();
  return all_ok ? kExitOk : kExitFailed;
}

}  // namespace app
