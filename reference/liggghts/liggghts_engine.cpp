// SPDX-License-Identifier: MIT
#include "reference/liggghts/liggghts_engine.hpp"

#include <exception>
#include <filesystem>

#include <fmt/format.h>

#include "cases/time_step.hpp"
#include "reference/common/core_setup.hpp"
#include "reference/common/dump_snapshots.hpp"
#include "reference/common/dump_text.hpp"
#include "reference/liggghts/atom_types.hpp"
#include "reference/liggghts/deck_parts.hpp"
#include "reference/liggghts/run_conventions.hpp"
#include "reference/liggghts/trace_columns.hpp"
#include "support/interrupts.hpp"
#include "support/process.hpp"
#include "support/sha256.hpp"
#include "support/text_file.hpp"

namespace reference {


const liggghts::LiggghtsProbe& LiggghtsEngine::probe() const {
  std::call_once(probed_, [this] { probe_ = liggghts::probe_liggghts(options_.program, options_.probe_timeout_s); });
  return probe_;
}

std::optional<std::string> LiggghtsEngine::version() const { return probe().version; }

std::string LiggghtsEngine::location() const {
  if (const auto path = support::find_program(options_.program)) return path->string();
  return fmt::format("'{}' not found (install the Debian package liggghts, or choose the binary with --liggghts "
                     "PATH or DEMWB_LIGGGHTS)",
                     options_.program);
}

Support LiggghtsEngine::supports(const PreparedScene& prepared) const {
  Support s;
  s.reasons = liggghts::deck_parts(prepared).reasons;
  return s;
}

std::string LiggghtsEngine::input_fingerprint(const PreparedScene& prepared) const {
  const liggghts::DeckParts parts = liggghts::deck_parts(prepared);
  if (!parts.reasons.empty() || !parts.contacts) return {};
  try {
    const cases::Scene& scene = prepared.scene();
    liggghts::DeckSettings settings;
    settings.timestep = core_setup(prepared).simulation.timestep;
    settings.steps = cases::step_count(scene.integration.duration, settings.timestep);
    const liggghts::TracePlan plan = liggghts::trace_plan(scene, parts.types);
    std::string input = liggghts::write_deck(scene, parts.types, *parts.contacts, plan, settings);
    if (liggghts::atoms_in_data_file(scene, parts.types)) {
      input += "\n--- data file ---\n" + liggghts::write_atom_data(scene, parts.types, settings);
    }
    for (const auto& [name, text] : liggghts::mesh_files(scene)) input += "\n--- " + name + " ---\n" + text;
    return support::sha256_hex(input);
  } catch (const std::exception&) {
    return {};  // the run reports why the deck cannot be written
  }
}

cases::RunResult LiggghtsEngine::run(const PreparedScene& prepared, const RunOptions& options) const {
  const cases::Scene& scene = prepared.scene();
  const liggghts::LiggghtsProbe& checked = probe();
  if (checked.timed_out) return error_result(*checked.version + ": not run", "");
  const double time_left = options.timeout_s - checked.seconds;
  if (time_left <= 0.0) {
    return error_result(
        fmt::format("LIGGGHTS timed out: its version probe used the whole time limit ({:.3g} s)", options.timeout_s),
        "");
  }
  const liggghts::DeckParts parts = liggghts::deck_parts(prepared);
  if (!parts.reasons.empty() || !parts.contacts) {
    Support s;
    s.reasons = parts.reasons;
    return error_result("LIGGGHTS driver cannot express the scene: " + s.explain(), "");
  }
  const CoreSetup setup = core_setup(prepared);
  liggghts::DeckSettings settings;
  settings.timestep = setup.simulation.timestep;
  settings.steps = cases::step_count(scene.integration.duration, settings.timestep);
  const liggghts::TracePlan plan = liggghts::trace_plan(scene, parts.types);
  const std::string deck = liggghts::write_deck(scene, parts.types, *parts.contacts, plan, settings);

  const std::filesystem::path dir = liggghts::make_run_directory(options.work_dir);
  const support::OwnedPathGuard partial(dir);  // removed if interrupted mid-run
  support::write_file(dir / liggghts::kDeckFile, deck);
  if (liggghts::atoms_in_data_file(scene, parts.types)) {
    support::write_file(dir / settings.data_file, liggghts::write_atom_data(scene, parts.types, settings));
  }
  for (const auto& [name, text] : liggghts::mesh_files(scene)) support::write_file(dir / name, text);
  const liggghts::LiggghtsRunOutcome outcome = liggghts::run_liggghts(options_.program, dir, time_left);
  if (!outcome.ok) return error_result(outcome.reason, outcome.log_tail);

  cases::RunResult result;
  try {
    const std::filesystem::path log_path = dir / liggghts::kLogFile;
    const cases::Trace printed = liggghts::trace_from_thermo(scene, plan, support::read_file(log_path),
                                                             log_path.string(), settings.steps);
    liggghts::AssembledTrace assembled = liggghts::assemble_trace(scene, printed);
    result.trace = std::move(assembled.trace);
    result.warnings = setup.warnings;
    for (auto& w : assembled.warnings) result.warnings.push_back(std::move(w));
    const std::vector<std::uint64_t> snapshot_steps =
        cases::snapshot_steps(scene.output.snapshot_times, settings.timestep, settings.steps);
    if (!snapshot_steps.empty()) {
      const std::filesystem::path dump_path = dir / settings.snapshot_file;
      if (!std::filesystem::exists(dump_path)) {
        return error_result(fmt::format("LIGGGHTS exited normally but wrote no snapshot file {}", dump_path.string()),
                       outcome.log_tail);
      }
      result.snapshots = snapshots_from_dump(parse_dump(support::read_file(dump_path), dump_path.string()),
                                             snapshot_steps, settings.timestep, scene.particles.size(), "LIGGGHTS");
    }
  } catch (const std::exception& e) {
    return error_result(e.what(), outcome.log_tail);
  }
  if (const std::string bad = cases::first_non_finite(result.trace); !bad.empty()) {
    return error_result("LIGGGHTS produced a non-finite value: " + bad, outcome.log_tail);
  }
  for (const auto& w : outcome.warnings) result.warnings.push_back("LIGGGHTS log: " + w);
  if (scene.output.trace_energy) {
    result.warnings.emplace_back("output.trace_energy: the LIGGGHTS driver records no energy ledger (its energy "
                                 "trace is empty)");
  }
  result.status = cases::RunStatus::ok;
  result.conventions = liggghts::run_conventions(scene, *parts.contacts, plan, settings,
                                                 outcome.version.value_or("unknown"));
  result.scratch_dir = dir.string();
  return result;
}

}  // namespace reference
