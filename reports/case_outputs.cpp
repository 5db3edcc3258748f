// SPDX-License-Identifier: MIT
#include "reports/case_outputs.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "reports/case_report.hpp"
#include "reports/junit.hpp"
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
      for (std::size_t k = 0; k < run.snapshots.size(); ++k) {
        support::write_file(dir / "snapshots" / fmt::format("{}_{:04d}.vtk", run.engine, k),
                            snapshot_vtk(outcome.scene, run.snapshots[k], run.engine));
      }
    }
  }
  support::write_file(dir / "case.toml", outcome.scene.source_text);
  support::write_file(dir / "command.txt", command + "\n");
  std::string md = "# dem-workbench report\n\n";
  md += "Reproduce with:\n\n```sh\n" + command + "\n```\n\n";
  md += case_section(outcome, dir / "plots", dir, 2);
  support::write_file(dir / "report.md", md);
}

}  // namespace reports
