// SPDX-License-Identifier: MIT
#include "sweeps/stored_ensembles.hpp"

#include <algorithm>
#include <exception>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cases/case_loader.hpp"
#include "reports/markdown.hpp"
#include "support/sha256.hpp"
#include "support/text_file.hpp"
#include "sweeps/sweep_spec.hpp"

namespace sweeps {
namespace {

namespace fs = std::filesystem;

/// The lines of the "## Engines compared" section of a stored report that form its table.
std::string engines_compared_table(const std::string& report) {
  std::istringstream in(report);
  std::string line, table;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0) {
      if (inside) break;
      inside = line == "## Engines compared";
      continue;
    }
    if (inside && line.rfind('|', 0) == 0) table += line + "\n";
  }
  return table;
}

/// Number of bold cells (the report marks |Δ| / combined s.e. above 2 in bold).
std::size_t bold_cells(const std::string& table) {
  std::size_t n = 0;
  for (std::size_t at = table.find("| **"); at != std::string::npos; at = table.find("| **", at + 1)) ++n;
  return n;
}

}  // namespace

std::map<std::string, std::string> mesh_sha256(const cases::Scene& scene) {
  std::map<std::string, std::string> out;
  for (const cases::MeshSpec& m : scene.meshes) out[m.file] = m.sha256;
  return out;
}

namespace {

/// Checks the stored results of one sweep against its files; fills `e` or its problem.
void read_store(StoredEnsemble& e, const SweepSpec& spec) {
  const fs::path json_file = e.stored_dir / "sweep.json";
  const fs::path report_file = e.stored_dir / "report.md";
  if (!fs::exists(json_file) || !fs::exists(report_file)) {
    e.problem = fmt::format("no stored results in {}: run `demwb refresh --sweep {}`", e.stored_dir.string(),
                            e.sweep_file.string());
    return;
  }
  const auto j = nlohmann::json::parse(support::read_file(json_file));
  const bool sweep_same = j.at("sweep_sha256") == support::sha256_hex(spec.source_text);
  const bool case_same = j.at("case_sha256") == support::sha256_hex(support::read_file(spec.case_file));
  const bool csv_same = fs::exists(e.stored_dir / "sweep.csv") &&
                        j.at("sweep_csv_sha256") == support::sha256_hex(support::read_file(e.stored_dir / "sweep.csv"));
  // bed.csv (the fluidisation curves) is fingerprinted when the sweep wrote one.
  const bool bed_same = !j.contains("bed_csv_sha256") ||
                        (fs::exists(e.stored_dir / "bed.csv") &&
                         j.at("bed_csv_sha256") == support::sha256_hex(support::read_file(e.stored_dir / "bed.csv")));
  // The meshes the case reads, by their files' SHA-256 (none stored: the case read none).
  std::string mesh_changed;
  if (case_same) {
    const auto stored = j.contains("mesh_sha256") ? j.at("mesh_sha256").get<std::map<std::string, std::string>>()
                                                  : std::map<std::string, std::string>{};
    const auto now = mesh_sha256(cases::load_case(spec.case_file));
    if (stored != now) {
      mesh_changed = "the set of mesh files";  // unless a file the case reads now names the change
      for (const auto& [file, sha] : now) {
        if (!stored.contains(file) || stored.at(file) != sha) mesh_changed = file;
      }
    }
  }
  if (!sweep_same || !case_same || !csv_same || !bed_same || !mesh_changed.empty()) {
    e.problem = fmt::format("stale: {} changed since the results were stored; run `demwb refresh --sweep {}`",
                            !sweep_same         ? e.sweep_file.string()
                            : !case_same        ? spec.case_file.string()
                            : !mesh_changed.empty() ? mesh_changed
                                                : std::string(!csv_same ? "sweep.csv" : "bed.csv"),
                            e.sweep_file.string());
  }
  e.comparison_table = engines_compared_table(support::read_file(report_file));
  if (e.comparison_table.empty() && e.problem.empty()) e.problem = "the stored report has no engines-compared table";
  e.beyond_two = bold_cells(e.comparison_table);
  e.current = e.problem.empty();
}

/// `to` relative to `from` when both are on one file system tree, else `to` as given.
std::string relative_link(const fs::path& to, const fs::path& from) {
  std::error_code ec;
  const fs::path rel = fs::relative(fs::absolute(to), fs::absolute(from), ec);
  return ec || rel.empty() ? to.string() : rel.generic_string();
}

}  // namespace

std::vector<StoredEnsemble> stored_ensembles(const fs::path& sweeps_dir, const fs::path& stored_root) {
  std::vector<StoredEnsemble> out;
  if (!fs::is_directory(sweeps_dir)) return out;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(sweeps_dir)) {
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& file : files) {
    StoredEnsemble e;
    e.sweep_file = file;
    e.name = file.stem().string();
    e.stored_dir = stored_root / e.name;
    try {
      const SweepSpec spec = load_sweep(file);
      if (spec.engines.size() < 2) continue;  // one engine: a study, not a cross-code comparison
      e.name = spec.name;
      e.description = spec.description;
      e.engines = spec.engines;
      e.stored_dir = stored_root / spec.name;
      read_store(e, spec);
    } catch (const std::exception& error) {
      e.problem = fmt::format("cannot be read: {}", error.what());
    }
    out.push_back(std::move(e));
  }
  return out;
}

std::string stored_ensembles_section(const std::vector<StoredEnsemble>& ensembles, const fs::path& report_dir,
                                     bool ran_now) {
  if (ensembles.empty()) return {};
  std::string md = ran_now ? "## Cross-code ensembles (run now, full tier)\n\n" : "## Cross-code ensembles (stored)\n\n";
  md += "Many-body breakup is chaotic, so codes are compared on ensembles over seeds, not on one run. ";
  md += ran_now ? "This full-tier run ran each sweep afresh; the committed results stay under cases/baselines/sweeps. "
                : "These sweeps run outside CI (`demwb refresh --sweep`, or the full tier); their results are stored "
                  "with a fingerprint of the sweep and case files they came from. ";
  md += "Each cell is the difference of an engine's mean and the first engine's over the seeds, in units of their "
        "combined standard error; above 2 (bold) the ensembles differ by more than their spread explains.\n\n";
  for (const auto& e : ensembles) {
    md += fmt::format("### `{}`\n\n", e.name);
    if (!e.description.empty()) md += reports::inert_text(e.description) + "\n\n";
    if (!e.engines.empty()) {
      std::string names;
      for (const auto& n : e.engines) names += (names.empty() ? "" : ", ") + n;
      md += fmt::format("Engines: {}. Sweep `{}`; {} results [{}]({}).\n\n", names,
                        relative_link(e.sweep_file, report_dir), ran_now ? "this run's" : "stored",
                        e.stored_dir.filename().string(),
                        relative_link(e.stored_dir / "report.md", report_dir));
    }
    md += e.current ? fmt::format("{}: current. Cells above 2 combined standard errors: {}.\n\n",
                                  ran_now ? "Results" : "Store", e.beyond_two)
                    : fmt::format("{}: **{}**\n\n", ran_now ? "Results" : "Store", e.problem);
    if (!e.comparison_table.empty()) md += e.comparison_table + "\n";
  }
  return md;
}

}  // namespace sweeps
