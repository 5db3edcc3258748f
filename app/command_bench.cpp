// SPDX-License-Identifier: MIT
// `demwb bench`: the core, LAMMPS and LIGGGHTS timed on the same physics, side by side in one run.
#include <algorithm>
#include <cstdio>
#include <functional>
#include <iostream>

#include <sched.h>

#include <fmt/format.h>

#include "app/cli.hpp"
#include "app/options.hpp"
#include "bench/bench_result.hpp"
#include "bench/box_scene.hpp"
#include "bench/chute_scene.hpp"
#include "bench/core_run.hpp"
#include "bench/code_run.hpp"
#include "bench/cpu_pinning.hpp"
#include "cases/case_loader.hpp"
#include "reference/common/core_setup.hpp"
#include "reference/lammps/deck_writer.hpp"
#include "reference/lammps/simulation_box.hpp"
#include "reference/liggghts/deck_parts.hpp"
#include "reports/case_outputs.hpp"
#include "support/text_file.hpp"
#include "cases/time_step.hpp"

namespace app {
namespace {

namespace po = boost::program_options;

/// What the command line asked for.
struct BenchOptions {
  std::string scene;
  bool inhouse = true;
  std::vector<bench::BenchCode> codes;  ///< the reference codes to time, in the order asked
  int threads = 1;
  int ranks = 1;
  std::optional<std::uint64_t> steps;
  std::size_t particles = 10000;
  std::string chute_dir;
  double timeout_s = 3600.0;
  int repeat = 1;
  bool speedup = false;  ///< also time the core on one thread in every repetition
  std::vector<int> pinned_cpus;  ///< `--per-cpu`: also time one thread pinned to each of these
  std::filesystem::path out;

  [[nodiscard]] bool wants(std::string_view engine) const {
    return std::any_of(codes.begin(), codes.end(), [&](const bench::BenchCode& c) { return c.engine == engine; });
  }
};

/// How to time one reference code on the scene: a run, or why the code cannot run it (n/a).
struct CodeJob {
  std::function<bench::CodeRun()> run;
  std::string not_applicable;
};

/// Runs each code that can run the scene and then the core (on `o.threads` threads, then, with
/// `o.speedup`, on one, then, with `--per-cpu`, on one thread pinned to each CPU — in turn, the
/// order reversed every other repetition), one after the other, `o.repeat` times; a code that fails (missing,
/// crashed, timed out) is not run again and reports that failure, the others go on; a code that
/// cannot express the scene is n/a with its reason. `run_core` takes the thread count.
void alternate(const BenchOptions& o, bench::BenchResult& r, const std::vector<CodeJob>& jobs,
               const std::function<bench::CoreRun(int)>& run_core) {
  for (std::size_t c = 0; c < o.codes.size(); ++c) {
    r.codes.push_back({o.codes[c], {}, std::nullopt});
    if (!jobs[c].run) {
      bench::CodeRun na;
      na.engine = o.codes[c].engine;
      na.status = "n/a";
      na.reason = jobs[c].not_applicable;
      na.ranks = o.ranks;
      r.codes.back().median = na;
    }
  }
  std::vector<bool> failed(o.codes.size(), false);
  for (int k = 0; k < o.repeat; ++k) {
    for (std::size_t c = 0; c < o.codes.size(); ++c) {
      if (!jobs[c].run || failed[c]) continue;
      r.codes[c].runs.push_back(jobs[c].run());
      failed[c] = r.codes[c].runs.back().status != "ok";
    }
    if (run_core) r.core_runs.push_back(run_core(o.threads));
    if (run_core && o.speedup) {
      r.one_thread_runs.push_back(run_core(1));
      r.machine_probes.push_back(bench::probe_machine(o.threads));
    }
    if (run_core && !o.pinned_cpus.empty()) {
      // The team's worker threads exist by now (the run on o.threads came first), so none of them
      // inherits a pin; the pin ends before anything else runs.
      std::vector<bench::PinnedRun> each;
      for (std::size_t i = 0; i < o.pinned_cpus.size(); ++i) {
        const int cpu = o.pinned_cpus[k % 2 == 0 ? i : o.pinned_cpus.size() - 1 - i];
        const bench::PinnedToCpu pin(cpu);
        bench::CoreRun run = run_core(1);
        each.push_back({cpu, sched_getcpu(), static_cast<int>(i), std::move(run)});
      }
      std::sort(each.begin(), each.end(), [](const auto& a, const auto& b) { return a.cpu < b.cpu; });
      r.pinned_runs.push_back(std::move(each));
    }
    if (o.repeat > 1) std::fprintf(stderr, "bench: repetition %d of %d done\n", k + 1, o.repeat);
  }
  bench::choose_medians(r);
}

/// The in-house and LAMMPS runs of LAMMPS's chute benchmark, with the step-100 energy checks.
bench::BenchResult bench_chute(const BenchOptions& o) {
  const auto dir = bench::find_chute_dir(o.chute_dir);
  if (!dir) {
    throw std::invalid_argument(
        "the chute benchmark needs in.chute and data.chute (LAMMPS's bench/ files, not shipped with "
        "Debian's package): pass --chute-dir DIR or set DEMWB_CHUTE_DIR");
  }
  const std::uint64_t steps = o.steps.value_or(1000);
  if (steps < 100) throw std::invalid_argument("--steps: the chute deck runs 100 steps itself; ask for 100 or more");
  bench::BenchResult r;
  r.scene = "chute";
  r.description = fmt::format(
      "LAMMPS's granular benchmark in.chute ({}): 32,000 spheres, gran/hooke/history, frozen rough base, "
      "gravity tilted 26°, periodic in x and y. LAMMPS runs the deck unmodified (a wrapper includes it and "
      "adds `run` for steps past its own 100); the core runs the same scene with LAMMPS's numerics.",
      dir->string());
  r.steps = steps;
  const bench::LammpsData data = bench::read_lammps_data(*dir / "data.chute");
  r.particles = data.atoms.size();
  std::vector<CodeJob> jobs;
  std::function<bench::CoreRun(int)> run_core;
  for (const bench::BenchCode& code : o.codes) {
    CodeJob job;
    if (code.engine == "lammps") {
      std::string deck = fmt::format("# dem-workbench: LAMMPS's own chute benchmark, unmodified\ninclude {}\n",
                                     (*dir / "in.chute").string());
      if (steps > 100) deck += fmt::format("run {}\n", steps - 100);
      job.run = [&o, code, deck, dir] {
        return bench::run_code_bench(code, deck, o.out / code.engine, o.ranks, o.timeout_s, {*dir / "data.chute"});
      };
    } else {
      job.not_applicable = fmt::format("in.chute is a LAMMPS deck ({} has no gran/hooke/history pair style); the chute "
                                       "is LAMMPS's own benchmark",
                                       code.title);
    }
    jobs.push_back(std::move(job));
  }
  if (o.inhouse) {
    run_core = [&data, steps](int threads) {
      const std::vector<std::uint64_t> at{0, 100};
      return bench::run_core(bench::chute_setup(data, threads), steps, at);
    };
  }
  alternate(o, r, jobs, run_core);
  if (o.inhouse) {
    const bench::ChuteReference ref;
    const bench::CodeBench* lammps = r.code("lammps");
    const auto lammps_value = [&](std::uint64_t step, const char* column) -> std::string {
      if (lammps == nullptr || !lammps->median || lammps->median->status != "ok") return "";
      for (const auto& row : lammps->median->log.thermo) {
        if (row.step == step && row.values.count(column) != 0) return bench::lammps_digits(row.values.at(column));
      }
      return "";
    };
    for (const auto& [step, e] : r.core->energies) {
      if (step != 100) continue;
      for (const auto& [name, column, value, expected] :
           {std::tuple{"KinEng at step 100", "KinEng", e.translational, ref.kinetic_energy},
            std::tuple{"c_1 (rotational energy) at step 100", "c_1", e.rotational, ref.rotational_energy}}) {
        bench::EnergyCheck c{name, bench::lammps_digits(value), fmt::format("{:.17g}", value),
                             bench::lammps_digits(expected), lammps_value(step, column), false};
        c.match = c.core == c.reference && (c.lammps.empty() || c.lammps == c.core);
        r.checks.push_back(c);
      }
    }
    r.notes.push_back(fmt::format("core: {} neighbour-list builds in {} steps, {} Morton reorders; at the end {} "
                                  "listed pairs, {} interacting",
                                  r.core->list_builds, steps, r.core->reorders, r.core->list_entries,
                                  r.core->interacting_pairs));
  }
  return r;
}

/// The `box` scene (or a case file's scene) on the core and on LAMMPS through its driver.
bench::BenchResult bench_scene(const BenchOptions& o, const cases::Scene& scene, std::uint64_t steps) {
  bench::BenchResult r;
  r.scene = o.scene;
  r.description = scene.description.empty() ? scene.name : scene.description;
  r.steps = steps;
  r.particles = scene.particles.size();
  const reference::PreparedScene prepared(scene);
  const reference::CoreSetup setup = reference::core_setup(prepared, o.threads);
  std::vector<CodeJob> jobs;
  std::function<bench::CoreRun(int)> run_core;
  // Every code with the same neighbour skin (LAMMPS driver's: a fifth of the smallest radius).
  const double skin = reference::lammps::neighbour_skin(scene);
  for (const bench::BenchCode& code : o.codes) {
    CodeJob job;
    std::string deck;
    std::vector<bench::DeckFile> files;
    if (code.engine == "lammps") {
      reference::lammps::DeckSettings settings;
      settings.timestep = setup.simulation.timestep;
      settings.steps = steps;
      settings.timing_only = true;
      try {
        deck = reference::lammps::write_deck(prepared, settings);
        if (reference::lammps::atoms_in_data_file(scene)) {
          files.push_back({settings.data_file, reference::lammps::write_atom_data(scene, settings)});
        }
      } catch (const std::invalid_argument& e) {
        job.not_applicable = e.what();
      }
    } else {
      const reference::liggghts::TimingDeck t =
          reference::liggghts::timing_deck(prepared, setup.simulation.timestep, steps, skin);
      for (const std::string& reason : t.reasons) {
        job.not_applicable += (job.not_applicable.empty() ? "" : "; ") + reason;
      }
      deck = t.deck;
      if (!t.data.empty()) files.push_back({t.data_file, t.data});
    }
    if (job.not_applicable.empty()) {
      job.run = [&o, code, deck, files] {
        return bench::run_code_bench(code, deck, o.out / code.engine, o.ranks, o.timeout_s, {}, files);
      };
    }
    jobs.push_back(std::move(job));
  }
  dem::SimulationSetup core = setup.simulation;
  core.scheme_settings.orientation = false;  // LAMMPS' atom_style sphere keeps none either
  core.track_energy = scene.output.trace_energy;
  if (o.inhouse) {
    run_core = [core, steps](int threads) {
      const std::vector<std::uint64_t> at{steps};
      dem::SimulationSetup on = core;
      on.threads = threads;
      return bench::run_core(on, steps, at);
    };
  }
  alternate(o, r, jobs, run_core);
  // The same physics: each engine's translational kinetic energy at the last step (LAMMPS' default
  // thermo prints TotEng, which is kinetic alone under a granular pair style).
  if (r.core && !r.core->energies.empty()) r.kinetic_energy_at_end["inhouse"] = r.core->energies.back().second.translational;
  for (const bench::CodeBench& c : r.codes) {
    if (!c.median || c.median->status != "ok") continue;
    const auto& thermo = c.median->log.thermo;
    for (const char* column : {"KinEng", "TotEng"}) {
      if (!thermo.empty() && thermo.back().step == steps && thermo.back().values.count(column) != 0) {
        r.kinetic_energy_at_end[c.code.engine] = thermo.back().values.at(column);
        break;
      }
    }
    if (r.kinetic_energy_at_end.count(c.code.engine) == 0) {
      r.notes.push_back(fmt::format("{}'s log has no kinetic energy at step {}: its physics is not compared", c.code.title,
                                    steps));
    }
  }
  if (!r.kinetic_energy_at_end.empty()) {
    std::string each;
    for (const auto& [engine, e] : r.kinetic_energy_at_end) each += fmt::format("{}{} {:.6g}", each.empty() ? "" : ", ", engine, e);
    r.notes.push_back(fmt::format("translational kinetic energy at step {} [J]: {}", steps, each));
  }
  if (o.inhouse) {
    r.notes.push_back(fmt::format("core: {} neighbour-list builds in {} steps, {} Morton reorders; Δt = {:.3g} s",
                                  r.core->list_builds, steps, r.core->reorders, setup.simulation.timestep));
  }
  return r;
}

}  // namespace

int command_bench(const std::vector<std::string>& args, const Invocation& inv) {
  po::options_description opts("options");
  opts.add_options()
      ("engines", po::value<std::vector<std::string>>()->multitoken(),
       "engines to time: inhouse, lammps, liggghts (default inhouse,lammps)")
      ("threads", po::value<int>()->default_value(1), "OpenMP threads of the core")
      ("ranks", po::value<int>()->default_value(1), "MPI ranks of LAMMPS and LIGGGHTS (mpirun -np N)")
      ("steps", po::value<std::uint64_t>(), "time steps (chute: 1000, box: 200, a case: its duration)")
      ("particles", po::value<std::size_t>()->default_value(10000), "spheres of the box scene")
      ("chute-dir", po::value<std::string>(), "where in.chute and data.chute live")
      ("timeout", po::value<double>()->default_value(3600.0), "seconds before a LAMMPS or LIGGGHTS run is killed")
      ("lammps", po::value<std::string>(), "LAMMPS binary to time (default $DEMWB_LAMMPS, else lmp in PATH)")
      ("liggghts", po::value<std::string>(), "LIGGGHTS binary to time (default $DEMWB_LIGGGHTS, else liggghts in PATH)")
      ("repeat", po::value<int>()->default_value(1), "run every engine this many times, alternating; report medians")
      ("speedup", "also run the core on one thread right after each run on --threads N (N >= 2): reports the "
                  "speed-up and checks that both end in the same state to the last bit")
      ("per-cpu", "also run the core on one thread pinned to each CPU in turn (at most 16, or N) after each run on --threads "
                  "N (N >= 2): reports how far the CPUs' unequal speeds cap the speed-up and what share of their "
                  "summed speed the threads reached")
      ("output,o", po::value<std::string>(), "output directory (default out/bench-<scene>)");
  const auto vm = parse_command(
      args,
      "usage: demwb bench chute|box|CASE.toml [--engines inhouse,lammps,liggghts] [--threads N] [--ranks N]\n"
      "                   [--steps S] [--particles N] [--repeat N] [--speedup] [--per-cpu] [-o DIR]",
      opts, {"scene"});
  if (!vm) return kExitOk;
  BenchOptions o;
  o.scene = (*vm)["scene"].as<std::string>();
  o.timeout_s = timeout_option(*vm);
  const reference::ExternalPrograms programs = external_programs(*vm, o.timeout_s);
  std::vector<std::string> names{"inhouse", "lammps"};
  if (vm->count("engines") != 0) names = split_names((*vm)["engines"].as<std::vector<std::string>>());
  if (names.empty()) throw std::invalid_argument("--engines: name at least one of inhouse, lammps, liggghts");
  o.inhouse = false;
  for (const std::string& n : names) {
    if (n == "inhouse") {
      o.inhouse = true;
    } else if (n == "lammps" || n == "liggghts") {
      if (o.wants(n)) continue;  // named twice
      o.codes.push_back(n == "lammps" ? bench::lammps_code(programs.lammps, programs.probe_timeout_s)
                                      : bench::liggghts_code(programs.liggghts, programs.probe_timeout_s));
    } else {
      throw std::invalid_argument(
          fmt::format("--engines: '{}' cannot be benchmarked (known: inhouse, lammps, liggghts)", n));
    }
  }
  o.threads = (*vm)["threads"].as<int>();
  o.ranks = (*vm)["ranks"].as<int>();
  if (o.threads < 1 || o.threads > 1024) throw std::invalid_argument("--threads must be between 1 and 1024");
  if (o.ranks < 1 || o.ranks > 1024) throw std::invalid_argument("--ranks must be between 1 and 1024");
  if (vm->count("steps") != 0) o.steps = (*vm)["steps"].as<std::uint64_t>();
  o.particles = (*vm)["particles"].as<std::size_t>();
  if (o.particles < 1 || o.particles > 100'000'000) throw std::invalid_argument("--particles must be between 1 and 1e8");
  if (vm->count("chute-dir") != 0) o.chute_dir = (*vm)["chute-dir"].as<std::string>();
  o.repeat = (*vm)["repeat"].as<int>();
  if (o.repeat < 1 || o.repeat > 100) throw std::invalid_argument("--repeat must be between 1 and 100");
  // --speedup and --per-cpu both set the core on N threads beside one thread.
  const auto needs_team = [&o](const char* flag, const char* one_thread) {
    if (o.threads < 2 || !o.inhouse) {
      throw std::invalid_argument(fmt::format("{} compares the core on --threads N (N >= 2) with {}: give --threads 2 "
                                              "or more and keep inhouse among --engines",
                                              flag, one_thread));
    }
  };
  o.speedup = vm->count("speedup") != 0;
  if (o.speedup) needs_team("--speedup", "one thread");
  if (vm->count("per-cpu") != 0) {
    needs_team("--per-cpu", "one thread on each CPU");
    // At most 16 CPUs are timed, but never fewer than the team's threads: the ceiling adds up
    // the N fastest of the timed CPUs, which must be as many as the team can use.
    o.pinned_cpus = bench::allowed_cpus();
    const std::size_t timed = std::max<std::size_t>(16, static_cast<std::size_t>(o.threads));
    if (o.pinned_cpus.size() > timed) o.pinned_cpus.resize(timed);
  }
  o.out = vm->count("output") != 0 ? std::filesystem::path((*vm)["output"].as<std::string>())
                                   : std::filesystem::path("out/bench-" + std::filesystem::path(o.scene).stem().string());

  bench::BenchResult result;
  if (o.scene == "chute") {
    result = bench_chute(o);
  } else if (o.scene == "box") {
    const std::uint64_t steps = o.steps.value_or(200);
    result = bench_scene(o, bench::box_scene(o.particles, steps), steps);
  } else if (o.scene.ends_with(".toml")) {
    const cases::Scene scene = cases::load_case(o.scene);
    const std::uint64_t steps =
        o.steps.value_or(cases::step_count(scene.integration.duration, reference::core_setup(reference::PreparedScene(scene)).simulation.timestep));
    result = bench_scene(o, scene, steps);
    result.scene = scene.name;
  } else {
    throw std::invalid_argument(fmt::format("unknown bench scene '{}' (known: chute, box, or a case file *.toml)", o.scene));
  }
  const std::string command = reports::reproduce_command(inv.argc, inv.argv);
  std::filesystem::create_directories(o.out);
  support::write_file(o.out / "bench.json", bench::bench_json(result).dump(2) + "\n");
  support::write_file(o.out / "report.md", bench::bench_markdown(result, command));
  support::write_file(o.out / "command.txt", command + "\n");
  std::cout << bench::bench_table(result) << "wrote " << (o.out / "bench.json").string() << " and "
            << (o.out / "report.md").string() << "\n";
  return result.ok() ? kExitOk : kExitFailed;
}

}  // namespace app
