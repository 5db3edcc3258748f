// SPDX-License-Identifier: MIT
// `demwb refresh`: re-run the reference codes of a suite or case, store them in the cache, and
// optionally write the committed baselines.
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

namespace app {

int command_refresh(const std::vector<std::string>& args, const Invocation&) {
  namespace po = boost::program_options;
  po::options_description opts("options");
  opts.add_options()("write-baselines", "also write <baselines>/<case>.json (reference results and in-house metrics)")(
      "output,o", po::value<std::string>()->default_value("out/refresh"), "scratch directory for the runs");
  add_run_options(opts);
  const auto vm = parse_command(args, "usage: demwb refresh [canonical|DIR|CASE.toml] [--write-baselines]", opts,
                                {"target?"});
  if (!vm) return kExitOk;
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
    ctx.options.work_dir = std::filesystem::path((*vm)["output"].as<std::string>()) / scene.name;
    RunContext fresh = ctx;
    fresh.refresh = true;           // re-run the reference codes, then store their results
    fresh.baselines = std::nullopt;  // never answer a refresh from the baselines
    const comparison::CaseOutcome o = run_case(scene, engines, fresh);
    store::Baseline baseline{scene.name, store::scene_fingerprint(o.scene), {}, {}};
    for (const auto& r : o.runs) {
      const bool ok = r.status == cases::RunStatus::ok;
      if (r.engine == "inhouse") {
        for (const auto& [metric, v] : o.metrics.at("inhouse")) {
          if (v.value) baseline.inhouse_metrics[metric] = *v.value;
        }
        continue;
      }
      if (ok) baseline.references[r.engine] = r;
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
