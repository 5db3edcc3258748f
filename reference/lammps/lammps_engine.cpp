// SPDX-License-Identifier: MIT
#include "reference/lammps/lammps_engine.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>

#include <fmt/format.h>

#include "cases/time_step.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/core/model_error.hpp"
#include "reference/common/core_setup.hpp"
#include "reference/common/dump_snapshots.hpp"
#include "reference/common/dump_text.hpp"
#include "reference/common/fix_print_table.hpp"
#include "reference/lammps/atom_types.hpp"
#include "reference/lammps/deck_writer.hpp"
#include "reference/lammps/lammps_runner.hpp"
#include "reference/lammps/pair_coeff_mapping.hpp"
#include "reference/lammps/run_conventions.hpp"
#include "reference/lammps/trace_columns.hpp"
#include "reference/lammps/wall_mapping.hpp"
#include "support/interrupts.hpp"
#include "support/process.hpp"
#include "support/sha256.hpp"
#include "support/text_file.hpp"

namespace reference {

const lammps::LammpsProbe& LammpsEngine::probe() const {
  std::call_once(probed_, [this] { probe_ = lammps::probe_lammps(options_.program, options_.probe_timeout_s); });
  return probe_;
}

std::optional<std::string> LammpsEngine::version() const { return probe().version; }

std::string LammpsEngine::location() const {
  if (const auto path = support::find_program(options_.program)) return path->string();
  return fmt::format("'{}' not found (choose the binary with --lammps PATH or DEMWB_LAMMPS)", options_.program);
}

Support LammpsEngine::supports(const PreparedScene& prepared) const {
  const cases::Scene& scene = prepared.scene();
  Support s;
  for (std::size_t w = 0; w < scene.walls.size(); ++w) {
    for (auto& reason : lammps::unmapped_wall(scene.walls[w], w)) s.reasons.push_back(reason);
  }
  for (const auto& mesh : scene.meshes) s.reasons.push_back(lammps::unmapped_mesh(mesh));
  for (const auto& [p, w] : scene.output.trace_walls) {
    if (!lammps::wall_plane(scene.walls.at(w))) {
      s.reasons.push_back(fmt::format("LAMMPS driver: the traced contact of particle {} with wall {} ('{}'): only a "
                                      "plane wall's overlap and force are traced (fix wall/gran/region reports "
                                      "neither per wall)",
                                      p, w, scene.walls.at(w).name));
    }
  }
  if (scene.model.pair_lever_arm == dem::PairLeverArm::radius) {
    s.reasons.emplace_back(
        "LAMMPS driver: pair_lever_arm = 'radius' is gran/hooke/history's convention; the driver writes "
        "pair granular, whose torque lever arm is r − δ/2 (its contact-point velocity uses r)");
  }
  if (scene.model.tangential_history == dem::TangentialHistory::increment_project) {
    s.reasons.emplace_back(
        "LAMMPS driver: tangential_history = 'increment_project' is gran/hooke/history's rule; the "
        "driver writes pair granular, which rotates and rescales the slip (project_rescale)");
  }
  if (scene.model.coulomb_test == dem::CoulombTest::spring && scene.model.tangential != "none") {
    s.reasons.emplace_back(
        "LAMMPS driver: coulomb_test = 'spring' is LIGGGHTS' rule; pair granular caps the spring and dashpot "
        "force together (coulomb_test = 'total')");
  }
  if (scene.model.pair_lever_arm == dem::PairLeverArm::yade_incident ||
      scene.model.wall_lever_arm == dem::WallLeverArm::yade_incident ||
      scene.model.tangential_history == dem::TangentialHistory::yade_rotate) {
    s.reasons.emplace_back(
        "LAMMPS driver: the lever arm 'yade_incident' and the tangential_history 'yade_rotate' are "
        "YADE's conventions (α-scaled shear increment, first-order shear rotation), not LAMMPS'");
  }
  if (scene.model.adhesive_dashpot == dem::AdhesiveDashpot::pulloff_cap &&
      (scene.model.cohesion == "jkr" || scene.model.cohesion == "dmt") && scene.model.damping != "none") {
    s.reasons.emplace_back(
        "LAMMPS driver: adhesive_dashpot = 'pulloff_cap' is YADE's rule; pair granular never caps the "
        "dashpot at the pull-off force (set adhesive_dashpot = 'clamp' to compare)");
  }
  if (scene.domain.any_periodic()) {
    s.reasons.emplace_back(
        "LAMMPS driver: periodic boundaries are not mapped yet: the trace formulas read wrapped "
        "positions x[i] and plain differences x[p] − x[q], which break across the box (a mapping "
        "needs unwrapped xu and minimum-image pair formulas)");
  }
  if (scene.fluid) {
    s.reasons.emplace_back(
        "LAMMPS driver: fluid forces (drag, buoyancy, plug flow) are not mapped (LAMMPS "
        "GRANULAR has no Brenn drag, buoyancy or plug-flow field)");
  }
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    if (!scene.particles[i].motion.empty() && !scene.particles[i].fixed) {
      s.reasons.push_back(fmt::format(
          "LAMMPS driver: particle {} has a prescribed motion but is not fixed", i));
    }
    if (scene.particles[i].charge != 0.0) {
      s.reasons.push_back(fmt::format(
          "LAMMPS driver: particle {} is charged; pair granular has no electrostatics", i));
    }
  }
  try {
    const dem::PairTable& table = prepared.pair_table();
    if (table.material_count() > 0) {
      // The sub-model types are global, but whether a pair maps can depend on its values (a JKR
      // pair with γ = 0 is plain Hertz, which a wall can take): check every pair of materials
      // the particles use, and every wall against each of them.
      const bool per_atom = lammps::classify_particles(scene).per_atom_diameter;
      std::vector<std::size_t> used;
      for (const auto& p : scene.particles) {
        if (std::find(used.begin(), used.end(), p.material) == used.end()) used.push_back(p.material);
      }
      if (used.empty()) used.push_back(0);
      const auto add = [&](std::vector<std::string> reasons) {
        for (auto& reason : reasons) {
          if (std::find(s.reasons.begin(), s.reasons.end(), reason) == s.reasons.end()) {
            s.reasons.push_back(std::move(reason));
          }
        }
      };
      for (const std::size_t a : used) {
        for (const std::size_t b : used) add(lammps::unmapped_sub_models(table.law(a, b), false, per_atom));
        for (const auto& wall : scene.walls) {
          add(lammps::unmapped_sub_models(table.law(a, wall.material), true, per_atom));
        }
      }
    }
  } catch (const dem::ModelError& e) {
    s.reasons.push_back(std::string("LAMMPS driver: the contact model is incomplete: ") + e.what());
  }
  return s;
}

lammps::DeckSettings LammpsEngine::deck_settings(const cases::Scene& scene, double timestep) const {
  lammps::DeckSettings settings;
  settings.timestep = timestep;
  settings.steps = cases::step_count(scene.integration.duration, settings.timestep);
  settings.extra_commands = options_.extra_commands;
  return settings;
}

std::string LammpsEngine::input_fingerprint(const PreparedScene& prepared) const {
  const cases::Scene& scene = prepared.scene();
  if (!supports(prepared).supported()) return {};
  try {
    const lammps::DeckSettings settings = deck_settings(scene, core_setup(prepared).simulation.timestep);
    std::string input = lammps::write_deck(prepared, settings);
    if (lammps::atoms_in_data_file(scene)) input += "\n--- data file ---\n" + lammps::write_atom_data(scene, settings);
    return support::sha256_hex(input);
  } catch (const std::exception&) {
    return {};  // the run itself reports why the deck cannot be written
  }
}

cases::RunResult LammpsEngine::run(const PreparedScene& prepared, const RunOptions& options) const {
  const cases::Scene& scene = prepared.scene();
  // The version probe counts against the run's time limit; a binary that hung on an empty input
  // is not given the deck.
  const lammps::LammpsProbe& checked = probe();
  if (checked.timed_out) return error_result(*checked.version + ": not run", "");
  const double time_left = options.timeout_s - checked.seconds;
  if (time_left <= 0.0) {
    return error_result(fmt::format("LAMMPS timed out: its version probe used the whole time limit ({:.3g} s)", options.timeout_s),
                   "");
  }
  const CoreSetup setup = core_setup(prepared);
  const lammps::DeckSettings settings = deck_settings(scene, setup.simulation.timestep);
  const double dt = settings.timestep;
  const std::uint64_t steps = settings.steps;
  const std::string deck = lammps::write_deck(prepared, settings);

  const std::filesystem::path dir = lammps::make_run_directory(options.work_dir);
  const support::OwnedPathGuard partial(dir);  // removed if interrupted mid-run
  support::write_file(dir / lammps::kDeckFile, deck);
  if (lammps::atoms_in_data_file(scene)) {
    support::write_file(dir / settings.data_file, lammps::write_atom_data(scene, settings));
  }
  const lammps::LammpsRunOutcome outcome =
      lammps::run_lammps(options_.program, dir, time_left);
  if (!outcome.ok) return error_result(outcome.reason, outcome.log_tail);

  cases::RunResult result;
  const std::filesystem::path trace_path = dir / settings.trace_file;
  try {
    if (!std::filesystem::exists(trace_path)) {
      return error_result(fmt::format("LAMMPS exited normally but wrote no trace file {}",
                                 trace_path.string()),
                     outcome.log_tail);
    }
    const cases::Trace printed =
        parse_fix_print(support::read_file(trace_path), trace_path.string());
    lammps::AssembledTrace assembled = lammps::assemble_trace(scene, printed, steps);
    result.trace = std::move(assembled.trace);
    result.warnings = setup.warnings;
    for (auto& w : assembled.warnings) result.warnings.push_back(std::move(w));

    const std::vector<std::uint64_t> snapshot_steps =
        cases::snapshot_steps(scene.output.snapshot_times, dt, steps);
    if (!snapshot_steps.empty()) {
      const std::filesystem::path dump_path = dir / settings.snapshot_file;
      if (!std::filesystem::exists(dump_path)) {
        return error_result(fmt::format("LAMMPS exited normally but wrote no snapshot file {}",
                                   dump_path.string()),
                       outcome.log_tail);
      }
      result.snapshots = snapshots_from_dump(
          parse_dump(support::read_file(dump_path), dump_path.string()), snapshot_steps,
          dt, scene.particles.size(), "LAMMPS");
    }
  } catch (const std::exception& e) {
    return error_result(e.what(), outcome.log_tail);
  }
  if (const std::string bad = cases::first_non_finite(result.trace); !bad.empty()) {
    return error_result("LAMMPS produced a non-finite value: " + bad, outcome.log_tail);
  }
  for (const auto& w : outcome.warnings) result.warnings.push_back("LAMMPS log: " + w);
  if (scene.output.trace_energy) {
    result.warnings.emplace_back(
        "output.trace_energy: the LAMMPS driver records no energy ledger (its energy trace is "
        "empty)");
  }
  result.status = cases::RunStatus::ok;
  result.conventions =
      lammps::run_conventions(prepared, dt, steps, outcome.version.value_or("unknown"));
  result.inexpressible_metrics = lammps::inexpressible_metrics(scene);
  result.scratch_dir = dir.string();
  return result;
}

}  // namespace reference
