// SPDX-License-Identifier: MIT
#include "reports/case_outputs.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "reports/case_report.hpp"
#include "reports/junit.hpp"
#include "reports/packing_plot.hpp"
#include "reports/results_json.hpp"
#include "reports/snapshot_vtk.hpp"
#include "reports/trace_csv.hpp"
#include "support/text_file.hpp"

namespace reports {
namespace {

/// Shell-quotes an argument when it holds anything but safe characters.
std::string shell_quote(const std::string& arg) {
  const bool safe = !arg.empty() && arg.find_first_not_of(
                                        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                        "0123456789_-./=:,+@%") == std::string::npos;
  if (safe) return arg;
  std::string out = "'";
  for (const char c : arg) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

/// The particles every engine received after the preparation stages, one row per particle at
/// full precision (round-trip digits).
std::string prepared_particles_csv(const cases::Scene& scene) {
  std::string out = "particle,radius,effect_radius,material,fixed,x,y,z,vx,vy,vz,wx,wy,wz\n";
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const cases::ParticleSpec& p = scene.particles[i];
    out += fmt::format("{},{:.17g},{:.17g},{},{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", i,
                       p.radius, p.effect_radius, scene.materials.at(p.material).name, p.fixed ? 1 : 0, p.position[0],
                       p.position[1], p.position[2], p.velocity[0], p.velocity[1], p.velocity[2],
                       p.angular_velocity[0], p.angular_velocity[1], p.angular_velocity[2]);
  }
  return out;
}

}  // namespace

std::string reproduce_command(int argc, const char* const* argv) {
  std::string cmd = "cd " + shell_quote(std::filesystem::current_path().string()) + " &&";
  for (int i = 0; i < argc; ++i) cmd += " " + shell_quote(argv[i]);
  return cmd;
}

void write_case_outputs(const comparison::CaseOutcome& outcome, const std::filesystem::path& dir,
                        const std::string& command, bool wall_times) {
  std::filesystem::create_directories(dir);
  support::write_file(dir / "results.json", results_json(outcome, wall_times).dump(2) + "\n");
  support::write_file(dir / "junit.xml", junit_xml({&outcome}, outcome.scene.name));
  for (const auto& run : outcome.runs) {
    if (run.status == cases::RunStatus::ok) {
      support::write_file(dir / ("trace_" + run.engine + ".csv"), trace_csv(run.trace));
      if (!run.energy.empty()) {
        support::write_file(dir / ("energy_" + run.engine + ".csv"), trace_csv(run.energy));
      }
      std::vector<std::pair<std::string, double>> series;
      for (std::size_t k = 0; k < run.snapshots.size(); ++k) {
        const std::string name = fmt::format("{}_{:04d}.vtk", run.engine, k);
        support::write_file(dir / "snapshots" / name, snapshot_vtk(outcome.scene, run.snapshots[k], run.engine));
        series.emplace_back(name, run.snapshots[k].time);
      }
      if (!series.empty()) {
        support::write_file(dir / "snapshots" / (run.engine + ".vtk.series"), vtk_series(series));
      }
      if (outcome.scene.compare.packing && !run.snapshots.empty()) {
        const auto bed = comparison::packing_series(outcome.scene, run);
        if (const auto* samples = std::get_if<std::vector<comparison::PackingSample>>(&bed)) {
          support::write_file(dir / ("packing_" + run.engine + ".csv"), packing_series_csv(*samples));
        }
      }
    }
  }
  support::write_file(dir / "case.toml", outcome.scene.source_text);
  if (!outcome.scene.stage_log.empty()) {
    support::write_file(dir / "prepared_particles.csv", prepared_particles_csv(outcome.scene));
  }
  support::write_file(dir / "command.txt", command + "\n");
  std::string md = "# dem-workbench report\n\n";
  md += "Reproduce with:\n\n```sh\n" + command + "\n```\n\n";
  md += case_section(outcome, dir / "plots", dir, 2);
  support::write_file(dir / "report.md", md);
}

}  // namespace reports
