// SPDX-License-Identifier: MIT
// `demwb fuzz-matched`: random small scenes run on a reference code and on the core with that
// code's numerics (studies/matched_fuzz.hpp). Every scene either agrees within the matched
// tolerance or is n/a by the code's mapping, with the reason; the rest are listed and their case
// files kept under DIR/failing/ so that each can be replayed with `demwb compare`.
#include <algorithm>
#include <atomic>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/case_runner.hpp"
#include "app/cli.hpp"
#include "app/options.hpp"
#include "cases/catalogue.hpp"
#include "cases/case_loader.hpp"
#include "compare/metrics.hpp"
#include "reference/common/engine.hpp"
#include "reference/registry.hpp"
#include "studies/matched_fuzz.hpp"
#include "support/text_file.hpp"

namespace app {
namespace {

/// What became of one scene.
struct FuzzResult {
  studies::FuzzScene scene;
  std::uint64_t seed = 0;
  std::string status;  ///< agree, disagree, n/a, error, invalid (the generator wrote a case the loader refused)
  std::optional<double> deviation;
  std::string reason;
  bool roundoff_horizon = false;  ///< compared only up to its round-off horizon (docs/metrics.md)
};

/// Writes a generated scene's case file and the files it names into `dir`; returns the case's path.
std::filesystem::path write_scene(const std::filesystem::path& dir, const studies::FuzzScene& generated) {
  for (const auto& [name, text] : generated.files) support::write_file(dir / name, text);
  const std::filesystem::path file = dir / (generated.name + ".toml");
  support::write_file(file, generated.toml);
  return file;
}

/// Runs one generated scene and reads its matched row.
FuzzResult run_scene(const studies::FuzzScene& generated, std::uint64_t seed, const std::string& code,
                     const std::filesystem::path& out, const RunContext& context, const cases::LoadOptions& load) {
  FuzzResult r{generated, seed, "error", std::nullopt, ""};
  const std::filesystem::path file = write_scene(out / "cases", generated);
  cases::Scene scene;
  try {
    scene = cases::load_case_text(generated.toml, file.string(), load);
  } catch (const std::exception& e) {
    r.status = "invalid";
    r.reason = e.what();
    return r;
  }
  const comparison::CaseOutcome outcome = run_case(scene, engines_to_run(scene, {}), context);
  const std::string matched = "inhouse@" + code;
  const auto row = std::find_if(outcome.comparisons.begin(), outcome.comparisons.end(), [&](const auto& c) {
    return c.metric == "trace_deviation" && c.engine == matched;
  });
  if (row == outcome.comparisons.end()) {
    r.reason = "no trace_deviation row for " + matched;
    for (const cases::RunResult& run : outcome.runs) {
      if (!run.reason.empty()) r.reason += fmt::format("; {}: {}", run.engine, run.reason);
    }
    return r;
  }
  r.deviation = row->value;
  r.reason = row->note;
  r.roundoff_horizon = row->note.starts_with(comparison::kRoundoffHorizonNote);
  switch (row->status) {
    case comparison::Status::pass: r.status = "agree"; break;
    case comparison::Status::fail: r.status = "disagree"; break;
    case comparison::Status::not_applicable: r.status = "n/a"; break;
    case comparison::Status::missing: r.status = "missing"; break;
    case comparison::Status::error: r.status = "error"; break;
  }
  return r;
}

/// One scene's entry of fuzz.json.
nlohmann::json to_json(const FuzzResult& r) {
  nlohmann::json j{{"seed", r.seed},       {"name", r.scene.name},     {"model", r.scene.model},
                   {"spheres", r.scene.spheres}, {"walls", r.scene.walls}, {"mesh_facets", r.scene.facets},
                   {"gravity", r.scene.gravity},
                   {"status", r.status},   {"reason", r.reason}, {"roundoff_horizon", r.roundoff_horizon}};
  j["trace_deviation"] = r.deviation ? nlohmann::json(*r.deviation) : nlohmann::json();
  return j;
}

/// The separate reasons of an n/a note: a refused run lists one per unmapped feature, "; "
/// apart, each after the engine's name ("lammps: LAMMPS driver: …; LAMMPS driver: …").
std::vector<std::string> split_reasons(const std::string& note) {
  std::string rest = note;
  for (const std::string_view engine : {"lammps: ", "yade: ", "liggghts: "}) {
    if (rest.starts_with(engine)) rest.erase(0, engine.size());
  }
  // Split only where the next reason begins with a driver's name (a reason may hold "; ").
  const auto starts_reason = [&](std::size_t at) {
    return rest.compare(at, 7, "LAMMPS ") == 0 || rest.compare(at, 5, "YADE ") == 0 ||
           rest.compare(at, 9, "LIGGGHTS ") == 0;
  };
  std::vector<std::string> parts;
  std::size_t from = 0;
  for (std::size_t at = rest.find("; "); at != std::string::npos; at = rest.find("; ", at + 2)) {
    if (!starts_reason(at + 2)) continue;
    parts.push_back(rest.substr(from, at - from));
    from = at + 2;
  }
  parts.push_back(rest.substr(from));
  return parts;
}

/// `text` fit for a markdown table cell ("|" escaped).
std::string cell(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

/// The summary: counts by status, each n/a reason counted (a scene with several counts under
/// each), and every scene that is neither agree nor n/a.
std::string summary(const std::vector<FuzzResult>& results, const std::string& code, std::uint64_t seed) {
  std::map<std::string, int> by_status;
  std::map<std::string, int> na_reasons;
  int horizon = 0;
  for (const FuzzResult& r : results) {
    ++by_status[r.status];
    if (r.status == "agree" && r.roundoff_horizon) ++horizon;
    if (r.status == "n/a") {
      for (const std::string& reason : split_reasons(r.reason)) ++na_reasons[reason];
    }
  }
  std::string s = fmt::format("# Matched fuzz against {}: {} scenes from seed {}\n\n| status | scenes |\n|---|---|\n", code,
                              results.size(), seed);
  for (const auto& [status, count] : by_status) s += fmt::format("| {} | {} |\n", status, count);
  std::map<std::string, int> with_mesh;
  for (const FuzzResult& r : results) {
    if (r.scene.facets > 0) ++with_mesh[r.status];
  }
  if (!with_mesh.empty()) {
    s += "\nOf them with a mesh wall:";
    for (const auto& [status, count] : with_mesh) s += fmt::format(" {} {},", status, count);
    s.back() = '.';
    s += "\n";
  }
  if (horizon > 0) {
    s += fmt::format("\n{} of the agreeing scenes are chaotic: they agree up to their round-off horizon, past which "
                     "a one-ulp nudge of the start drifts by more than {:.0e} (docs/metrics.md); listed below.\n",
                     horizon, comparison::kRoundoffDrift);
  }
  if (!na_reasons.empty()) {
    s += "\n| n/a reason | scenes |\n|---|---|\n";
    for (const auto& [reason, count] : na_reasons) s += fmt::format("| {} | {} |\n", cell(reason), count);
  }
  bool header = false;
  for (const FuzzResult& r : results) {
    if ((r.status == "agree" && !r.roundoff_horizon) || r.status == "n/a") continue;
    if (!header) {
      s += "\n| seed | model (normal/damping/tangential/cohesion/rolling) | spheres | walls (mesh facets) | gravity | status | trace deviation | note |\n|---|---|---|---|---|---|---|---|\n";
      header = true;
    }
    s += fmt::format("| {} | {} | {} | {}{} | {} | {} | {} | {} |\n", r.seed, r.scene.model, r.scene.spheres, r.scene.walls,
                     r.scene.facets > 0 ? fmt::format(" ({})", r.scene.facets) : std::string(),
                     r.scene.gravity ? "on" : "off", r.status,
                     r.deviation ? fmt::format("{:.3g}", *r.deviation) : std::string("—"), cell(r.reason));
  }
  return s;
}

}  // namespace

int command_fuzz_matched(const std::vector<std::string>& args, const Invocation& inv) {
  namespace po = boost::program_options;
  po::options_description opts("options");
  opts.add_options()("code", po::value<std::string>()->required(), "reference code: lammps, yade or liggghts")(
      "count", po::value<unsigned>()->default_value(20), "number of scenes")(
      "seed", po::value<std::uint64_t>()->default_value(1), "seed of the first scene (scene k has seed + k)")(
      "jobs,j", po::value<unsigned>()->default_value(1), "scenes run at once")(
      "output,o", po::value<std::string>(), "output directory (default out/fuzz-matched-<code>)");
  add_run_options(opts);
  const auto vm = parse_command(
      args, "usage: demwb fuzz-matched --code lammps|yade|liggghts [--count N] [--seed S] [-j N] [-o DIR]", opts, {});
  if (!vm) return kExitOk;
  refuse_matches(*vm, "fuzz-matched");
  const std::string code = (*vm)["code"].as<std::string>();
  if (!cases::is_reference_code(code)) {
    throw std::invalid_argument(fmt::format("--code: unknown reference code '{}' (known: lammps, yade, liggghts)", code));
  }
  const unsigned count = (*vm)["count"].as<unsigned>();
  const std::uint64_t seed = (*vm)["seed"].as<std::uint64_t>();
  const unsigned jobs = std::max(1U, (*vm)["jobs"].as<unsigned>());
  const std::filesystem::path out = vm->count("output") != 0 ? std::filesystem::path((*vm)["output"].as<std::string>())
                                                             : std::filesystem::path("out/fuzz-matched-" + code);
  RunContext context = run_context(*vm, out / "work");
  context.cache.reset();             // random scenes: nothing to reuse, nothing worth keeping
  context.refine_time_step = false;  // the matched row is the point, not the code's own Δt error
  const cases::LoadOptions load = load_options(*vm);

  // Most seeds redraw until the code's mapping expresses the scene (its supports()), so that the
  // comparisons, not the n/a answers, make up most of a run.
  const std::unique_ptr<reference::Engine> engine = reference::make_engine(code, context.programs);
  const studies::ExpressibleFilter expressible = [&](const studies::FuzzScene& draft) {
    try {
      // A draft's mesh is read from beside its case file, in a scratch folder (a rejected draft's
      // STL must not lie beside the kept case): one seed's drafts share a name and a thread, so
      // they overwrite only their own files.
      const std::filesystem::path file = write_scene(out / "drafts", draft);
      return engine->supports(cases::load_case_text(draft.toml, file.string(), load)).supported();
    } catch (const std::exception&) {
      return false;
    }
  };
  std::vector<FuzzResult> results(count);
  std::atomic<unsigned> next{0};
  std::mutex print;
  const auto worker = [&] {
    for (unsigned k = next++; k < count; k = next++) {
      const std::uint64_t s = seed + k;
      results[k] = run_scene(studies::random_matched_scene(code, s, expressible), s, code, out, context, load);
      const std::lock_guard lock(print);
      std::cout << fmt::format("scene {:>5} ({}): {}{}\n", s, results[k].scene.model, results[k].status,
                               results[k].deviation ? fmt::format(" {:.3g}", *results[k].deviation) : "");
    }
  };
  {
    std::vector<std::jthread> pool;
    for (unsigned t = 0; t < jobs; ++t) pool.emplace_back(worker);
  }

  std::filesystem::remove_all(out / "drafts");
  nlohmann::json all = nlohmann::json::array();
  bool clean = true;
  for (const FuzzResult& r : results) {
    all.push_back(to_json(r));
    if (r.status == "agree" || r.status == "n/a") continue;
    clean = false;
    write_scene(out / "failing", r.scene);
  }
  const std::string report = summary(results, code, seed);
  support::write_file(out / "fuzz.json",
                      nlohmann::json{{"code", code}, {"seed", seed}, {"count", count}, {"scenes", all}}.dump(2) + "\n");
  support::write_file(out / "report.md", report + fmt::format("\nReproduce: `{}`\n", fmt::join(std::vector<std::string>(inv.argv, inv.argv + inv.argc), " ")));
  std::cout << "\n" << report << "\nwrote " << (out / "report.md").string() << " and " << (out / "fuzz.json").string()
            << (clean ? "" : "; failing scenes in " + (out / "failing").string()) << "\n";
  return clean ? kExitOk : kExitFailed;
}

}  // namespace app
