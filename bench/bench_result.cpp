// SPDX-License-Identifier: MIT
#include "bench/bench_result.hpp"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "bench/median.hpp"

namespace bench {
namespace {

/// Share of `part` in `total`, in percent.
double percent(double part, double total) { return total > 0.0 ? 100.0 * part / total : 0.0; }

/// Time shares of the core: neighbour build, forces (pair, wall and field loops), integration
/// and bookkeeping (the rest of the step loop).
struct Shares {
  double neighbor = 0.0;
  double forces = 0.0;
  double integration = 0.0;
};

Shares shares(const CoreRun& c) {
  const double neighbor = c.timing.neighbor_build;
  const double forces = c.timing.pair_loop + c.timing.sphere_loop;
  return {percent(neighbor, c.wall_s), percent(forces, c.wall_s),
          percent(c.wall_s - neighbor - forces, c.wall_s)};
}

Shares shares(const CodeRun& l) {
  const auto get = [&l](const char* k) {
    const auto it = l.log.breakdown_s.find(k);
    return it == l.log.breakdown_s.end() ? 0.0 : it->second;
  };
  return {percent(get("Neigh"), l.log.loop_s), percent(get("Pair"), l.log.loop_s),
          percent(l.log.loop_s - get("Neigh") - get("Pair"), l.log.loop_s)};
}


/// "1 rank" / "2 ranks".
std::string ranks_text(int ranks) { return fmt::format("{} rank{}", ranks, ranks > 1 ? "s" : ""); }

/// Every pairwise ratio as "1.23, 1.25".
std::string ratio_list(const std::vector<double>& all) {
  std::string each;
  for (const double x : all) each += fmt::format("{}{:.2f}", each.empty() ? "" : ", ", x);
  return each;
}

/// One run of the core as bench.json reports it.
nlohmann::json core_json(const CoreRun& c) {
  const Shares s = shares(c);
  return {{"threads", c.threads},
          {"particle_steps_per_s", c.particle_steps_per_s},
          {"wall_s", c.wall_s},
          {"bytes_per_particle", static_cast<double>(c.bytes) / static_cast<double>(c.particles)},
          {"peak_rss_bytes_per_particle", c.peak_rss_bytes / static_cast<double>(c.particles)},
          {"time_share_percent", {{"neighbor_build", s.neighbor}, {"forces", s.forces}, {"integration", s.integration}}},
          {"seconds", {{"neighbor_build", c.timing.neighbor_build},
                       {"pair_loop", c.timing.pair_loop},
                       {"sphere_loop", c.timing.sphere_loop},
                       {"packing_and_observation", c.timing.other},
                       {"integration_and_rest", c.wall_s - c.timing.neighbor_build - c.timing.pair_loop -
                                                    c.timing.sphere_loop - c.timing.other}}},
          {"neighbor_builds", c.list_builds},
          {"reorders", c.reorders},
          {"state_sha256", c.state_sha256}};
}

/// The one-thread run beside the speed-up: core_json without the peak resident set, which is the
/// process's and so also the N-thread runs'.
nlohmann::json one_thread_json(const CoreRun& c) {
  nlohmann::json j = core_json(c);
  j.erase("peak_rss_bytes_per_particle");
  return j;
}

/// The speed-up: "on 2 threads / on 1 thread: 1.86 (median of ...); final states identical ...".
std::string speedup_text(const BenchResult& r) {
  const std::vector<double> all = r.speedups();
  const bool same = r.identical_across_threads().value_or(false);
  return fmt::format("on {} threads / on 1 thread: {:.2f}{}; final states {}", r.core->threads, *r.speedup(),
                     all.size() > 1 ? fmt::format(" (median of {} pairs, {} threads then 1: {})", all.size(),
                                                  r.core->threads, ratio_list(all))
                                    : "",
                     same ? "identical to the last bit" : "DIFFER between runs (the deterministic mode is broken)");
}

/// The machine's own ratios: "the machine on 2 threads / on 1 thread, same minutes: ...".
std::string machine_text(const MachineProbe& m) {
  return fmt::format("the machine itself on {} threads / on 1 thread, probed in the same minutes with kernels "
                     "independent of the core: arithmetic {:.2f}, memory stream {:.2f} (ideal {}); its slowest "
                     "thread took {:.2f}× its fastest's time",
                     m.threads, m.arithmetic, m.memory, m.threads, m.unequal);
}

/// The pinned runs: "on 1 thread pinned to each CPU (medians of 5): CPU 0 loop 1.52 s, ...".
std::string per_cpu_text(const BenchResult& r, const PerCpuSummary& p) {
  std::string each;
  for (const auto& [cpu, loop] : p.loop_s) each += fmt::format("{}CPU {} loop {:.3f} s", each.empty() ? "" : ", ", cpu, loop);
  std::string reps;
  for (std::size_t k = 0; k < r.pinned_runs.size(); ++k) {
    const auto c = r.ceiling_at(k);
    reps += (reps.empty() ? "" : ", ") + (c ? fmt::format("{:.0f} %", 100.0 * c->efficiency) : std::string("untimed"));
  }
  const bool same = r.identical_across_threads().value_or(false);
  return fmt::format("on 1 thread pinned to each CPU in turn (medians of {} repetitions, each taken on its own): {}; "
                     "on {} threads over one thread on the fastest CPU {:.2f}, these CPUs' summed one-thread speeds "
                     "allowing {:.2f}; the threads reached {:.0f} % of that sum (per repetition: {}); final states {}",
                     p.repetitions, each, r.core->threads, p.speedup, p.ceiling, 100.0 * p.efficiency, reps,
                     same ? "identical to the last bit" : "DIFFER between runs (the deterministic mode is broken)");
}

}  // namespace

const CodeBench* BenchResult::code(std::string_view engine) const {
  for (const CodeBench& c : codes) {
    if (c.code.engine == engine) return &c;
  }
  return nullptr;
}

std::vector<double> BenchResult::ratios(std::string_view engine) const {
  std::vector<double> out;
  const CodeBench* c = code(engine);
  if (c == nullptr) return out;
  for (std::size_t k = 0; k < core_runs.size() && k < c->runs.size(); ++k) {
    if (c->runs[k].status != "ok" || c->runs[k].particle_steps_per_s <= 0.0) continue;
    out.push_back(core_runs[k].particle_steps_per_s / c->runs[k].particle_steps_per_s);
  }
  return out;
}

std::optional<double> BenchResult::ratio(std::string_view engine) const {
  const std::vector<double> r = ratios(engine);
  if (!r.empty()) return median_of(r);
  const CodeBench* c = code(engine);
  if (!core || c == nullptr || !c->median || c->median->status != "ok" || c->median->particle_steps_per_s <= 0.0) {
    return std::nullopt;
  }
  return core->particle_steps_per_s / c->median->particle_steps_per_s;
}

std::vector<double> BenchResult::speedups() const {
  std::vector<double> out;
  for (std::size_t k = 0; k < core_runs.size() && k < one_thread_runs.size(); ++k) {
    if (one_thread_runs[k].particle_steps_per_s <= 0.0) continue;
    out.push_back(core_runs[k].particle_steps_per_s / one_thread_runs[k].particle_steps_per_s);
  }
  return out;
}

std::optional<double> BenchResult::speedup() const {
  const std::vector<double> s = speedups();
  if (s.empty()) return std::nullopt;
  return median_of(s);
}

std::optional<MachineProbe> BenchResult::machine() const {
  if (machine_probes.empty()) return std::nullopt;
  MachineProbe m;
  m.threads = machine_probes.front().threads;
  m.arithmetic = median_by(machine_probes, [](const MachineProbe& p) { return p.arithmetic; });
  m.memory = median_by(machine_probes, [](const MachineProbe& p) { return p.memory; });
  m.unequal = median_by(machine_probes, [](const MachineProbe& p) { return p.unequal; });
  return m;
}

std::optional<CpuCeiling> BenchResult::ceiling_at(std::size_t k) const {
  if (k >= core_runs.size() || k >= pinned_runs.size() || pinned_runs[k].empty()) return std::nullopt;
  std::vector<CpuSpeed> speeds;
  for (const PinnedRun& p : pinned_runs[k]) {
    // A run too short for the clock to time says nothing about the CPUs.
    if (!is_speed(p.run.particle_steps_per_s)) return std::nullopt;
    speeds.push_back({p.cpu, p.run.particle_steps_per_s});
  }
  if (!is_speed(core_runs[k].particle_steps_per_s)) return std::nullopt;
  return cpu_ceiling(speeds, core_runs[k].threads, core_runs[k].particle_steps_per_s);
}

std::vector<CpuCeiling> BenchResult::ceilings() const {
  std::vector<CpuCeiling> out;
  for (std::size_t k = 0; k < pinned_runs.size(); ++k) {
    if (const auto c = ceiling_at(k)) out.push_back(*c);
  }
  return out;
}

std::optional<PerCpuSummary> BenchResult::per_cpu() const {
  std::vector<CpuCeiling> each;
  std::map<int, std::vector<double>> loops;
  for (std::size_t k = 0; k < pinned_runs.size(); ++k) {
    const auto c = ceiling_at(k);
    if (!c) continue;  // untimed: left out of every median
    each.push_back(*c);
    for (const PinnedRun& p : pinned_runs[k]) loops[p.cpu].push_back(p.run.wall_s);
  }
  if (each.empty()) return std::nullopt;
  PerCpuSummary s;
  s.repetitions = each.size();
  for (const auto& [cpu, l] : loops) s.loop_s.emplace_back(cpu, median_of(l));
  s.ceiling = median_by(each, [](const CpuCeiling& c) { return c.ceiling; });
  s.speedup = median_by(each, [](const CpuCeiling& c) { return c.speedup; });
  s.efficiency = median_by(each, [](const CpuCeiling& c) { return c.efficiency; });
  return s;
}

std::optional<bool> BenchResult::identical_across_threads() const {
  if ((one_thread_runs.empty() && pinned_runs.empty()) || core_runs.empty()) return std::nullopt;
  const std::string& first = core_runs.front().state_sha256;
  const auto same = [&first](const CoreRun& c) { return !c.state_sha256.empty() && c.state_sha256 == first; };
  for (const auto* runs : {&core_runs, &one_thread_runs}) {
    if (!std::all_of(runs->begin(), runs->end(), same)) return false;
  }
  for (const auto& rep : pinned_runs) {
    for (const PinnedRun& p : rep) {
      if (!same(p.run)) return false;
    }
  }
  return true;
}

void choose_medians(BenchResult& r) {
  const auto median = [](auto runs, auto speed) {
    std::sort(runs.begin(), runs.end(), [&](const auto& a, const auto& b) { return speed(a) < speed(b); });
    return runs[runs.size() / 2];
  };
  if (!r.core_runs.empty()) r.core = median(r.core_runs, [](const CoreRun& c) { return c.particle_steps_per_s; });
  if (!r.one_thread_runs.empty()) {
    r.one_thread = median(r.one_thread_runs, [](const CoreRun& c) { return c.particle_steps_per_s; });
  }
  for (CodeBench& c : r.codes) {
    if (c.runs.empty()) continue;
    std::vector<CodeRun> ok;
    for (const CodeRun& l : c.runs) {
      if (l.status == "ok") ok.push_back(l);
    }
    c.median = ok.size() == c.runs.size() ? median(ok, [](const CodeRun& l) { return l.particle_steps_per_s; })
                                          : c.runs.front();
    for (const CodeRun& l : c.runs) {
      if (l.status != "ok") c.median = l;  // a failed repetition is what the result reports
    }
  }
}

bool BenchResult::ok() const {
  for (const EnergyCheck& c : checks) {
    if (!c.match) return false;
  }
  if (identical_across_threads() == false) return false;
  for (const CodeBench& c : codes) {
    if (!c.median || (c.median->status != "ok" && c.median->status != "n/a")) return false;
  }
  return true;
}

nlohmann::json bench_json(const BenchResult& r) {
  nlohmann::json j;
  j["scene"] = r.scene;
  j["description"] = r.description;
  j["n_particles"] = r.particles;
  j["steps"] = r.steps;
  j["engines"] = nlohmann::json::object();
  if (r.core) j["engines"]["inhouse"] = core_json(*r.core);
  for (const CodeBench& c : r.codes) {
    if (!c.median) continue;
    const CodeRun& l = *c.median;
    nlohmann::json e{{"ranks", l.ranks}, {"status", l.status}, {"version", l.version}};
    if (l.status == "ok") {
      const Shares s = shares(l);
      e["particle_steps_per_s"] = l.particle_steps_per_s;
      e["wall_s"] = l.log.loop_s;
      e["bytes_per_particle"] = l.bytes_per_particle;
      e["time_share_percent"] = {{"neighbor_build", s.neighbor}, {"forces", s.forces}, {"integration", s.integration}};
    } else {
      e["reason"] = l.reason;
    }
    j["engines"][c.code.engine] = e;
  }
  for (const char* engine : {"lammps", "liggghts"}) {
    const auto ratio = r.ratio(engine);
    j[fmt::format("ratio_inhouse_to_{}", engine)] = ratio ? nlohmann::json(*ratio) : nlohmann::json(nullptr);
  }
  j["thread_speedup"] = nullptr;
  if (const auto speedup = r.speedup(); speedup && r.one_thread && r.core) {
    j["thread_speedup"] = {{"threads", r.core->threads},
                           {"median", *speedup},
                           {"pairs", r.speedups()},
                           {"one_thread", one_thread_json(*r.one_thread)},
                           {"identical_across_threads", *r.identical_across_threads()},
                           {"state_sha256", r.core->state_sha256}};
    j["thread_speedup"]["machine"] = nullptr;
    if (const auto m = r.machine()) {
      nlohmann::json probes = nlohmann::json::array();
      for (const MachineProbe& p : r.machine_probes) {
        probes.push_back({{"arithmetic", p.arithmetic}, {"memory", p.memory}, {"unequal", p.unequal}});
      }
      j["thread_speedup"]["machine"] = {{"threads", m->threads},       {"arithmetic", m->arithmetic},
                                        {"memory", m->memory},         {"unequal", m->unequal},
                                        {"probes", probes}};
    }
  }
  j["per_cpu"] = nullptr;
  if (const auto p = r.per_cpu(); p && r.core) {
    nlohmann::json cpus = nlohmann::json::array();
    for (const auto& [cpu, loop] : p->loop_s) cpus.push_back({{"cpu", cpu}, {"median_wall_s", loop}});
    nlohmann::json reps = nlohmann::json::array();
    for (std::size_t k = 0; k < r.pinned_runs.size(); ++k) {
      nlohmann::json runs = nlohmann::json::array();
      for (const PinnedRun& pr : r.pinned_runs[k]) {
        runs.push_back({{"cpu", pr.cpu}, {"ran_on", pr.ran_on}, {"order", pr.order}, {"wall_s", pr.run.wall_s},
                        {"particle_steps_per_s", pr.run.particle_steps_per_s}});
      }
      nlohmann::json rep{{"runs", runs}, {"fastest_cpu", nullptr}, {"ceiling", nullptr},
                         {"speedup_over_fastest_cpu", nullptr}, {"efficiency", nullptr}};
      if (const auto c = r.ceiling_at(k)) {
        rep["fastest_cpu"] = c->fastest_cpu;
        rep["ceiling"] = c->ceiling;
        rep["speedup_over_fastest_cpu"] = c->speedup;
        rep["efficiency"] = c->efficiency;
      }
      reps.push_back(rep);
    }
    j["per_cpu"] = {{"threads", r.core->threads},
                    {"timed_repetitions", p->repetitions},
                    {"cpus", cpus},
                    {"ceiling", p->ceiling},
                    {"speedup_over_fastest_cpu", p->speedup},
                    {"efficiency", p->efficiency},
                    {"identical_across_threads", *r.identical_across_threads()},
                    {"repetitions", reps}};
  }
  std::size_t repetitions = r.core_runs.size();
  for (const CodeBench& c : r.codes) repetitions = std::max(repetitions, c.runs.size());
  nlohmann::json reps = nlohmann::json::array();
  for (std::size_t k = 0; k < repetitions; ++k) {
    nlohmann::json rep = nlohmann::json::object();
    if (k < r.core_runs.size()) rep["inhouse_particle_steps_per_s"] = r.core_runs[k].particle_steps_per_s;
    if (k < r.one_thread_runs.size()) rep["inhouse_one_thread_particle_steps_per_s"] = r.one_thread_runs[k].particle_steps_per_s;
    for (const CodeBench& c : r.codes) {
      if (k < c.runs.size() && c.runs[k].status == "ok") {
        rep[c.code.engine + "_particle_steps_per_s"] = c.runs[k].particle_steps_per_s;
      }
    }
    reps.push_back(rep);
  }
  j["repetitions"] = reps;
  nlohmann::json checks = nlohmann::json::array();
  for (const EnergyCheck& c : r.checks) {
    checks.push_back({{"quantity", c.quantity}, {"inhouse", c.core}, {"inhouse_exact", c.core_exact}, {"reference_log", c.reference},
                      {"lammps", c.lammps}, {"match", c.match}});
  }
  j["checks"] = checks;
  if (!r.kinetic_energy_at_end.empty()) j["kinetic_energy_at_end"] = r.kinetic_energy_at_end;
  j["notes"] = r.notes;
  return j;
}

std::string bench_table(const BenchResult& r) {
  std::string out = fmt::format("scene {}: {} particles, {} steps\n", r.scene, r.particles, r.steps);
  out += fmt::format("{:<10} {:>9} {:>10} {:>18} {:>15} {:>10} {:>8} {:>12}\n", "engine", "threads", "loop s",
                     "particle-steps/s", "bytes/particle", "neighbour", "forces", "integration");
  if (r.core) {
    const CoreRun& c = *r.core;
    const Shares s = shares(c);
    out += fmt::format("{:<10} {:>9} {:>10.3f} {:>18.4g} {:>15.0f} {:>9.1f}% {:>7.1f}% {:>11.1f}%\n", "inhouse",
                       c.threads, c.wall_s, c.particle_steps_per_s,
                       static_cast<double>(c.bytes) / static_cast<double>(c.particles), s.neighbor, s.forces,
                       s.integration);
  }
  for (const CodeBench& c : r.codes) {
    if (!c.median) continue;
    const CodeRun& l = *c.median;
    if (l.status == "ok") {
      const Shares s = shares(l);
      out += fmt::format("{:<10} {:>9} {:>10.3f} {:>18.4g} {:>15.0f} {:>9.1f}% {:>7.1f}% {:>11.1f}%\n", c.code.engine,
                         ranks_text(l.ranks), l.log.loop_s, l.particle_steps_per_s, l.bytes_per_particle, s.neighbor,
                         s.forces, s.integration);
    } else {
      out += fmt::format("{:<10} {}: {}\n", c.code.engine, l.status, l.reason);
    }
  }
  for (const CodeBench& c : r.codes) {
    if (const auto ratio = r.ratio(c.code.engine)) {
      const std::vector<double> all = r.ratios(c.code.engine);
      out += fmt::format("ratio inhouse / {}: {:.2f}{}\n", c.code.engine, *ratio,
                         all.size() > 1 ? fmt::format(" (median of {} alternating pairs: {})", all.size(), ratio_list(all))
                                        : "");
    }
  }
  if (r.speedup() && r.one_thread && r.core) {
    out += fmt::format("inhouse on 1 thread: loop {:.3f} s, {:.4g} particle-steps/s (median run)\n", r.one_thread->wall_s,
                       r.one_thread->particle_steps_per_s);
    out += "inhouse " + speedup_text(r) + "\n";
    if (const auto m = r.machine()) out += machine_text(*m) + "\n";
  }
  if (const auto p = r.per_cpu(); p && r.core) out += "inhouse " + per_cpu_text(r, *p) + "\n";
  for (const EnergyCheck& c : r.checks) {
    out += fmt::format("{}: inhouse {}, LAMMPS reference log {}{} — {}\n", c.quantity, c.core, c.reference,
                       c.lammps.empty() ? "" : ", LAMMPS here " + c.lammps, c.match ? "match" : "MISMATCH");
  }
  for (const std::string& n : r.notes) out += "note: " + n + "\n";
  return out;
}

std::string bench_markdown(const BenchResult& r, const std::string& command) {
  std::string md = fmt::format("# Benchmark: {}\n\n{}\n\n{} particles, {} steps. Reproduce with:\n\n```sh\n{}\n```\n\n",
                               r.scene, r.description, r.particles, r.steps, command);
  md += "| engine | threads / ranks | loop time [s] | particle-steps/s | bytes/particle | neighbour build | "
        "forces | integration and rest |\n|---|---|---|---|---|---|---|---|\n";
  if (r.core) {
    const CoreRun& c = *r.core;
    const Shares s = shares(c);
    md += fmt::format("| inhouse | {} thread{} | {:.3f} | {:.4g} | {:.0f} | {:.1f} % | {:.1f} % | {:.1f} % |\n",
                      c.threads, c.threads > 1 ? "s" : "", c.wall_s, c.particle_steps_per_s,
                      static_cast<double>(c.bytes) / static_cast<double>(c.particles), s.neighbor, s.forces,
                      s.integration);
  }
  for (const CodeBench& c : r.codes) {
    if (!c.median) continue;
    const CodeRun& l = *c.median;
    if (l.status == "ok") {
      const Shares s = shares(l);
      md += fmt::format("| {} {} | {} | {:.3f} | {:.4g} | {:.0f} | {:.1f} % | {:.1f} % | {:.1f} % |\n", c.code.title,
                        l.version, ranks_text(l.ranks), l.log.loop_s, l.particle_steps_per_s, l.bytes_per_particle,
                        s.neighbor, s.forces, s.integration);
    } else {
      md += fmt::format("| {} | {} | {}: {} | | | | | |\n", c.code.title, ranks_text(l.ranks), l.status, l.reason);
    }
  }
  for (const CodeBench& c : r.codes) {
    const auto ratio = r.ratio(c.code.engine);
    if (!ratio) continue;
    md += fmt::format("\nRatio of particle-steps/s, inhouse / {}, measured in this one run: **{:.2f}**", c.code.title,
                      *ratio);
    const std::vector<double> all = r.ratios(c.code.engine);
    if (all.size() > 1) {
      md += fmt::format(" (median of {} pairs of runs made one after the other: {}; the table shows each engine's "
                        "median run)",
                        all.size(), ratio_list(all));
    }
    md += ".\n";
  }
  if (r.speedup() && r.one_thread && r.core) {
    md += fmt::format("\nThe core on one thread, run right after each run on {} threads: loop {:.3f} s, {:.4g} "
                      "particle-steps/s (median run). Speed-up {}.\n",
                      r.core->threads, r.one_thread->wall_s, r.one_thread->particle_steps_per_s, speedup_text(r));
    if (const auto m = r.machine()) {
      md += fmt::format("\nFor comparison, {} (medians of {} probes, one after each pair of core runs). A speed-up "
                        "below the ideal there is the machine's (shared cores, other guests), not the code's.\n",
                        machine_text(*m), r.machine_probes.size());
    }
  }
  if (const auto p = r.per_cpu(); p && r.core) {
    md += fmt::format("\nThe core {}. On a virtual machine the CPUs need not run at one speed; a team can at best "
                      "add up its CPUs' one-thread speeds, so that percentage is the code's share of a speed-up "
                      "below {}, the rest the machine's.\n",
                      per_cpu_text(r, *p), r.core->threads);
  }
  md += "\nBytes per particle: the core counts the capacity of its arrays, lists and history; LAMMPS "
        "reports its own \"Per MPI rank memory allocation\", LIGGGHTS its \"Memory usage per processor\" "
        "(times the ranks). Time shares: the core's neighbour builds and force loops are timed inside the "
        "run; the codes' come from their timing breakdown (Neigh, Pair; the rest is integration, fixes, "
        "walls and communication).\n";
  if (!r.checks.empty()) {
    md += "\n| check | inhouse | LAMMPS reference log | LAMMPS here | |\n|---|---|---|---|---|\n";
    for (const EnergyCheck& c : r.checks) {
      md += fmt::format("| {} | {} | {} | {} | {} |\n", c.quantity, c.core, c.reference,
                        c.lammps.empty() ? "—" : c.lammps, c.match ? "match" : "**mismatch**");
    }
  }
  for (const std::string& n : r.notes) md += "\n- " + n;
  if (!r.notes.empty()) md += "\n";
  return md;
}

}  // namespace bench
