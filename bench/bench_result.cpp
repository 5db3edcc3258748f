// SPDX-License-Identifier: MIT
#include "bench/bench_result.hpp"

#include <algorithm>

#include <fmt/format.h>

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

Shares shares(const LammpsRun& l) {
  const auto get = [&l](const char* k) {
    const auto it = l.log.breakdown_s.find(k);
    return it == l.log.breakdown_s.end() ? 0.0 : it->second;
  };
  return {percent(get("Neigh"), l.log.loop_s), percent(get("Pair"), l.log.loop_s),
          percent(l.log.loop_s - get("Neigh") - get("Pair"), l.log.loop_s)};
}

}  // namespace

std::vector<double> BenchResult::ratios() const {
  std::vector<double> out;
  for (std::size_t k = 0; k < core_runs.size() && k < lammps_runs.size(); ++k) {
    if (lammps_runs[k].status != "ok" || lammps_runs[k].particle_steps_per_s <= 0.0) continue;
    out.push_back(core_runs[k].particle_steps_per_s / lammps_runs[k].particle_steps_per_s);
  }
  return out;
}

std::optional<double> BenchResult::ratio() const {
  std::vector<double> r = ratios();
  if (r.empty()) {
    if (!core || !lammps || lammps->status != "ok" || lammps->particle_steps_per_s <= 0.0) return std::nullopt;
    return core->particle_steps_per_s / lammps->particle_steps_per_s;
  }
  std::sort(r.begin(), r.end());
  const std::size_t m = r.size() / 2;
  return r.size() % 2 == 1 ? r[m] : 0.5 * (r[m - 1] + r[m]);
}

void choose_medians(BenchResult& r) {
  const auto median = [](auto runs, auto speed) {
    std::sort(runs.begin(), runs.end(), [&](const auto& a, const auto& b) { return speed(a) < speed(b); });
    return runs[runs.size() / 2];
  };
  if (!r.core_runs.empty()) r.core = median(r.core_runs, [](const CoreRun& c) { return c.particle_steps_per_s; });
  if (!r.lammps_runs.empty()) {
    std::vector<LammpsRun> ok;
    for (const LammpsRun& l : r.lammps_runs) {
      if (l.status == "ok") ok.push_back(l);
    }
    r.lammps = ok.size() == r.lammps_runs.size()
                   ? median(ok, [](const LammpsRun& l) { return l.particle_steps_per_s; })
                   : r.lammps_runs.front();
    for (const LammpsRun& l : r.lammps_runs) {
      if (l.status != "ok") r.lammps = l;  // a failed repetition is what the result reports
    }
  }
}

bool BenchResult::ok() const {
  for (const EnergyCheck& c : checks) {
    if (!c.match) return false;
  }
  return !lammps || lammps->status == "ok" || lammps->status == "n/a";
}

nlohmann::json bench_json(const BenchResult& r) {
  nlohmann::json j;
  j["scene"] = r.scene;
  j["description"] = r.description;
  j["n_particles"] = r.particles;
  j["steps"] = r.steps;
  j["engines"] = nlohmann::json::object();
  if (r.core) {
    const CoreRun& c = *r.core;
    const Shares s = shares(c);
    j["engines"]["inhouse"] = {
        {"threads", c.threads},
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
        {"reorders", c.reorders}};
  }
  if (r.lammps) {
    const LammpsRun& l = *r.lammps;
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
    j["engines"]["lammps"] = e;
  }
  j["ratio_inhouse_to_lammps"] = r.ratio() ? nlohmann::json(*r.ratio()) : nlohmann::json(nullptr);
  nlohmann::json reps = nlohmann::json::array();
  for (std::size_t k = 0; k < std::max(r.core_runs.size(), r.lammps_runs.size()); ++k) {
    nlohmann::json rep;
    if (k < r.core_runs.size()) rep["inhouse_particle_steps_per_s"] = r.core_runs[k].particle_steps_per_s;
    if (k < r.lammps_runs.size() && r.lammps_runs[k].status == "ok") {
      rep["lammps_particle_steps_per_s"] = r.lammps_runs[k].particle_steps_per_s;
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
  if (r.lammps) {
    const LammpsRun& l = *r.lammps;
    if (l.status == "ok") {
      const Shares s = shares(l);
      out += fmt::format("{:<10} {:>9} {:>10.3f} {:>18.4g} {:>15.0f} {:>9.1f}% {:>7.1f}% {:>11.1f}%\n", "lammps",
                         fmt::format("{} rank{}", l.ranks, l.ranks > 1 ? "s" : ""), l.log.loop_s,
                         l.particle_steps_per_s, l.bytes_per_particle, s.neighbor, s.forces, s.integration);
    } else {
      out += fmt::format("{:<10} {}: {}\n", "lammps", l.status, l.reason);
    }
  }
  if (const auto ratio = r.ratio()) {
    const std::vector<double> all = r.ratios();
    std::string each;
    for (const double x : all) each += fmt::format("{}{:.2f}", each.empty() ? "" : ", ", x);
    out += fmt::format("ratio inhouse / lammps: {:.2f}{}\n", *ratio,
                       all.size() > 1 ? fmt::format(" (median of {} alternating pairs: {})", all.size(), each) : "");
  }
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
  if (r.lammps) {
    const LammpsRun& l = *r.lammps;
    if (l.status == "ok") {
      const Shares s = shares(l);
      md += fmt::format("| LAMMPS {} | {} rank{} | {:.3f} | {:.4g} | {:.0f} | {:.1f} % | {:.1f} % | {:.1f} % |\n",
                        l.version, l.ranks, l.ranks > 1 ? "s" : "", l.log.loop_s, l.particle_steps_per_s,
                        l.bytes_per_particle, s.neighbor, s.forces, s.integration);
    } else {
      md += fmt::format("| LAMMPS | {} ranks | {}: {} | | | | | |\n", l.ranks, l.status, l.reason);
    }
  }
  if (const auto ratio = r.ratio()) {
    md += fmt::format("\nRatio of particle-steps/s, inhouse / LAMMPS, measured in this one run: **{:.2f}**", *ratio);
    const std::vector<double> all = r.ratios();
    if (all.size() > 1) {
      std::string each;
      for (const double x : all) each += fmt::format("{}{:.2f}", each.empty() ? "" : ", ", x);
      md += fmt::format(" (median of {} pairs of runs made one after the other: {}; the table shows each engine's "
                        "median run)", all.size(), each);
    }
    md += ".\n";
  }
  md += "\nBytes per particle: the core counts the capacity of its arrays, lists and history; LAMMPS "
        "reports its own \"Per MPI rank memory allocation\" (times the ranks). Time shares: the core's "
        "neighbour builds and force loops are timed inside the run; LAMMPS's come from its timing "
        "breakdown (Neigh, Pair; the rest is integration, fixes and communication).\n";
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
