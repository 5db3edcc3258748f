// SPDX-License-Identifier: MIT
// `demwb sweep`: a parameter matrix over a case, several seeds per point, every engine; one CSV
// row per point × seed × engine and a report of means ± standard errors (docs/sweeps.md).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <future>
#include <map>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/case_runner.hpp"
#include "app/cli.hpp"
#include "app/driver_revisions.hpp"
#include "app/options.hpp"
#include "cases/case_loader.hpp"
#include "cases/catalogue.hpp"
#include "ranks/ranks.hpp"
#include "reference/common/engine.hpp"
#include "reference/registry.hpp"
#include "reports/case_outputs.hpp"
#include "support/sha256.hpp"
#include "support/text_file.hpp"
#include "sweeps/case_override.hpp"
#include "sweeps/stored_ensembles.hpp"
#include "sweeps/sweep_report.hpp"
#include "sweeps/sweep_rows.hpp"
#include "sweeps/sweep_spec.hpp"
#include "cases/case_file.hpp"
#include "support/interrupts.hpp"

namespace app {
namespace {

namespace po = boost::program_options;

/// Runs one point × seed on every engine; a case that cannot be built makes every engine's row
/// an error with the reason (never a dropped row).
sweeps::SweepRun run_job(const sweeps::SweepSpec& spec, const sweeps::SweepPoint& point, std::size_t job,
                         std::uint64_t seed, const std::string& case_text, const std::vector<std::string>& metrics,
                         const std::vector<std::string>& engines, RunContext ctx, const std::filesystem::path& out) {
  sweeps::SweepRun run{job, {}, 0.0};
  const auto start = std::chrono::steady_clock::now();
  try {
    const std::vector<std::pair<std::string, double>> values = sweeps::point_overrides(spec, point);
    const std::string text = sweeps::override_case(case_text, spec.case_file.string(), values, seed, spec.fixed);
    cases::Scene scene = cases::load_case_text(text, spec.case_file.string(), ctx.load);
    scene.compare.metrics = metrics;
    ctx.options.work_dir = out / "work" / fmt::format("p{:04d}_s{}", point.index, seed);
    ctx.refine_time_step = false;  // an ensemble's spread, not one run's Δt, is what its rows judge
    const comparison::CaseOutcome o = run_case(scene, engines, ctx);
    for (const auto& r : o.runs) {
      sweeps::SweepRow row{point.index, seed, r.engine, std::string(cases::to_string(r.status)), {}, r.reason, {}};
      if (r.status == cases::RunStatus::ok && o.scene.compare.packing) {
        auto bed = comparison::packing_series(o.scene, r);
        if (auto* samples = std::get_if<std::vector<comparison::PackingSample>>(&bed)) row.bed = std::move(*samples);
      }
      const auto set = o.metrics.find(r.engine);
      for (const auto& m : metrics) {
        std::optional<double> v;
        if (set != o.metrics.end()) {
          if (const auto it = set->second.find(m); it != set->second.end()) {
            v = it->second.value;
            if (!v && row.reason.empty()) row.reason = m + ": " + it->second.problem;
          }
        }
        row.values.push_back(v);
      }
      run.rows.push_back(row);
    }
  } catch (const std::exception& e) {
    run.rows = sweeps::error_rows(point.index, seed, engines, metrics.size(), e.what());
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

/// The sweep as one rank sees it: what to run and where to write.
struct SweepPlan {
  sweeps::SweepSpec spec;
  std::string case_text;
  std::map<std::string, std::string> mesh_sha256;  ///< the STL files the base case reads (sweeps::mesh_sha256)
  std::vector<std::string> engines;
  std::vector<std::string> metrics;
  std::vector<sweeps::SweepPoint> points;
  std::filesystem::path out;
  unsigned jobs = 1;
};

/// Runs this rank's share of the runs — every run whose number is the rank modulo the ranks —
/// `plan.jobs` at a time, printing a progress line per finished run. A failure outside the runs
/// themselves makes the runs not yet finished error rows naming the rank; none is dropped.
std::vector<sweeps::SweepRun> run_share(const SweepPlan& plan, const RunContext& context, const ranks::Ranks& ranks) {
  const std::size_t seeds = plan.spec.seeds.size();
  const std::size_t total = plan.points.size() * seeds;
  std::vector<std::size_t> mine;
  for (std::size_t j = static_cast<std::size_t>(ranks.rank()); j < total; j += static_cast<std::size_t>(ranks.size())) {
    mine.push_back(j);
  }
  const bool terminal = ::isatty(STDERR_FILENO) != 0 && !ranks.distributed();
  const std::string who = ranks.distributed() ? fmt::format("rank {}: ", ranks.rank()) : std::string();
  std::vector<std::optional<sweeps::SweepRun>> results(mine.size());
  std::size_t done = 0;
  const auto start = std::chrono::steady_clock::now();
  try {
    std::vector<std::pair<std::size_t, std::future<sweeps::SweepRun>>> running;
    std::size_t next = 0;
    while (done < mine.size()) {
      while (running.size() < plan.jobs && next < mine.size()) {
        const std::size_t job = mine[next];
        running.emplace_back(next, std::async(std::launch::async, run_job, std::cref(plan.spec),
                                              std::cref(plan.points[job / seeds]), job, plan.spec.seeds[job % seeds],
                                              std::cref(plan.case_text), std::cref(plan.metrics),
                                              std::cref(plan.engines), context, plan.out));
        ++next;
      }
      for (auto it = running.begin(); it != running.end();) {
        if (it->second.wait_for(std::chrono::milliseconds(20)) != std::future_status::ready) {
          ++it;
          continue;
        }
        const sweeps::SweepRun& run = results[it->first].emplace(it->second.get());
        ++done;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double eta = elapsed / static_cast<double>(done) * static_cast<double>(mine.size() - done);
        std::size_t ok = 0;
        for (const auto& r : run.rows) ok += r.status == "ok" ? 1 : 0;
        std::fprintf(stderr, "%s%s[%zu/%zu] point %zu seed %llu: %zu/%zu engine(s) ok (%.2f s), elapsed %.1f s, ETA %.1f s%s",
                     terminal ? "\r\033[K" : "", who.c_str(), done, mine.size(), run.job / seeds,
                     static_cast<unsigned long long>(plan.spec.seeds[run.job % seeds]), ok, run.rows.size(), run.seconds,
                     elapsed, eta, terminal ? "" : "\n");
        it = running.erase(it);
      }
    }
  } catch (const std::exception& e) {
    for (std::size_t k = 0; k < mine.size(); ++k) {
      if (results[k]) continue;
      const std::size_t job = mine[k];
      results[k] = sweeps::SweepRun{job,
                                    sweeps::error_rows(job / seeds, plan.spec.seeds[job % seeds], plan.engines,
                                                       plan.metrics.size(), who + e.what()),
                                    0.0};
    }
  }
  if (terminal && !mine.empty()) std::fprintf(stderr, "\n");
  std::vector<sweeps::SweepRun> out;
  for (auto& r : results) out.push_back(std::move(*r));
  return out;
}

/// Every run's rows in sweep.csv order, from the runs every rank sent; a run no rank sent is an
/// error row for each engine.
std::vector<sweeps::SweepRow> collect_rows(const SweepPlan& plan, const std::vector<std::string>& payloads) {
  const std::size_t seeds = plan.spec.seeds.size();
  std::vector<std::optional<sweeps::SweepRun>> runs(plan.points.size() * seeds);
  for (const auto& payload : payloads) {
    for (auto& run : sweeps::decode_runs(payload)) {
      if (run.job < runs.size()) runs[run.job] = std::move(run);
    }
  }
  std::vector<sweeps::SweepRow> rows;
  for (std::size_t j = 0; j < runs.size(); ++j) {
    if (!runs[j]) {
      const auto lost = sweeps::error_rows(j / seeds, plan.spec.seeds[j % seeds], plan.engines, plan.metrics.size(),
                                           "no rank returned this run");
      rows.insert(rows.end(), lost.begin(), lost.end());
      continue;
    }
    rows.insert(rows.end(), runs[j]->rows.begin(), runs[j]->rows.end());
  }
  return rows;
}

/// sweep.json: what produced sweep.csv — the sweep and case (their SHA-256), the core's source
/// revision, every engine's version — and the SHA-256 of sweep.csv itself, so a committed sweep
/// can be checked against the files it came from.
std::string sweep_fingerprint(const SweepPlan& plan, const std::vector<sweeps::SweepRow>& rows,
                              const std::string& command, double seconds, int ranks,
                              const reference::ExternalPrograms& programs) {
  nlohmann::json versions = nlohmann::json::object();
  for (const auto& name : plan.engines) {
    const auto engine = reference::make_engine(name, programs);
    const auto version = engine ? engine->version() : std::nullopt;
    versions[name] = version ? nlohmann::json(*version) : nlohmann::json("missing");
  }
  std::size_t failed = 0;
  for (const auto& r : rows) failed += r.status == "ok" ? 0 : 1;
  nlohmann::json j{
      {"sweep", plan.spec.name},
      {"sweep_file", plan.spec.source_path.string()},
      {"sweep_sha256", support::sha256_hex(plan.spec.source_text)},
      {"case_file", plan.spec.case_file.string()},
      {"case_sha256", support::sha256_hex(plan.case_text)},
      {"mesh_sha256", plan.mesh_sha256},
      {"core_revision", kCoreRevision},
      {"engines", versions},
      {"points", plan.points.size()},
      {"seeds", plan.spec.seeds},
      {"rows", rows.size()},
      {"rows_not_ok", failed},
      {"sweep_csv_sha256", support::sha256_hex(sweeps::sweep_csv(plan.spec, plan.points, plan.metrics, rows))},
      {"ranks", ranks},
      {"jobs", plan.jobs},
      {"wall_time_s", seconds},
      {"command", command}};
  if (const std::string bed = sweeps::bed_csv(plan.spec, plan.points, rows); !bed.empty()) {
    j["bed_csv_sha256"] = support::sha256_hex(bed);
  }
  return j.dump(2) + "\n";
}

/// The sweep command on one rank: parse, run this rank's share, gather at rank 0, which writes.
int sweep(const std::vector<std::string>& args, const Invocation& inv, const ranks::Ranks& ranks) {
  po::options_description opts("options");
  opts.add_options()("output,o", po::value<std::string>(), "output directory (default out/sweep-<name>)")(
      "jobs,j", po::value<unsigned>()->default_value(1), "runs (point × seed) at once, per MPI rank")(
      "engines", po::value<std::string>(), "engines, comma-separated (default: the sweep's, else the case's)");
  add_run_options(opts);
  const auto vm = parse_command(args, "usage: demwb sweep SWEEP.toml [-j N] [-o DIR] [--engines E,F]  (or under mpirun -np N)",
                                opts, {"sweep"});
  if (!vm) return kExitOk;
  refuse_matches(*vm, "sweep");
  const std::string command = reports::reproduce_command(inv.argc, inv.argv);
  SweepPlan plan;
  plan.spec = sweeps::load_sweep((*vm)["sweep"].as<std::string>());
  plan.case_text = cases::read_case_file(plan.spec.case_file);
  // The base case must load as it is and with the sweep's fixed settings: their errors are the
  // user's to fix before any run. The runs' engines and metrics are those of the latter.
  cases::Scene base = cases::load_case_text(plan.case_text, plan.spec.case_file.string(), load_options(*vm));
  if (!plan.spec.fixed.empty()) {
    base = cases::load_case_text(
        sweeps::override_case(plan.case_text, plan.spec.case_file.string(), {}, std::nullopt, plan.spec.fixed),
        plan.spec.case_file.string(), load_options(*vm));
  }
  plan.mesh_sha256 = sweeps::mesh_sha256(base);
  plan.engines = plan.spec.engines.empty() ? base.compare.engines : plan.spec.engines;
  if (vm->count("engines") != 0) plan.engines = split_names({(*vm)["engines"].as<std::string>()});
  for (const auto& e : plan.engines) {
    if (!cases::is_known_engine(e)) throw std::invalid_argument("unknown engine '" + e + "'");
  }
  plan.metrics = plan.spec.metrics.empty() ? base.compare.metrics : plan.spec.metrics;
  if (plan.metrics.empty()) {
    throw std::invalid_argument(plan.spec.source_path.string() + ": the sweep and its case list no metrics");
  }
  plan.out = vm->count("output") != 0 ? std::filesystem::path((*vm)["output"].as<std::string>())
                                      : std::filesystem::path("out") / ("sweep-" + plan.spec.name);
  plan.jobs = std::max(1U, (*vm)["jobs"].as<unsigned>());
  plan.points = sweeps::expand(plan.spec);
  const support::OwnedPathGuard partial = support::OwnedPathGuard::if_new(plan.out);  // removed if interrupted
  RunContext context = run_context(*vm, plan.out / "work");
  if (plan.spec.timeout_s && (*vm)["timeout"].defaulted()) context.options.timeout_s = *plan.spec.timeout_s;
  const auto start = std::chrono::steady_clock::now();

  const std::vector<std::string> payloads = ranks.gather(sweeps::encode_runs(run_share(plan, context, ranks)));
  long long failed = 0;
  if (ranks.rank() == 0) {
    const std::vector<sweeps::SweepRow> rows = collect_rows(plan, payloads);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::filesystem::create_directories(plan.out);
    support::write_file(plan.out / "sweep.csv", sweeps::sweep_csv(plan.spec, plan.points, plan.metrics, rows));
    if (const std::string bed = sweeps::bed_csv(plan.spec, plan.points, rows); !bed.empty()) {
      support::write_file(plan.out / "bed.csv", bed);
    }
    support::write_file(plan.out / "sweep.toml", plan.spec.source_text);
    support::write_file(plan.out / "case.toml", plan.case_text);
    support::write_file(plan.out / "command.txt", command + "\n");
    support::write_file(plan.out / "sweep.json", sweep_fingerprint(plan, rows, command, seconds, ranks.size(), context.programs));
    sweeps::write_sweep_report({plan.spec, plan.points, plan.engines, plan.metrics, rows, command, seconds, ranks.size()},
                               plan.out);
    for (const auto& r : rows) failed += r.status == "ok" ? 0 : 1;
    std::printf("wrote %s and %s: %zu rows, %lld not ok\n", (plan.out / "sweep.csv").c_str(),
                (plan.out / "report.md").c_str(), rows.size(), failed);
  }
  failed = ranks.broadcast(failed);
  return failed == 0 ? kExitOk : kExitFailed;
}

}  // namespace

int command_sweep(const std::vector<std::string>& args, const Invocation& inv) {
  const ranks::Ranks ranks;
  try {
    return sweep(args, inv, ranks);
  } catch (const std::exception& e) {
    // Under MPI the job ends when this exception leaves `ranks`; say why first.
    if (ranks.size() > 1) std::fprintf(stderr, "demwb sweep: rank %d: %s\n", ranks.rank(), e.what());
    throw;
  }
}

}  // namespace app
