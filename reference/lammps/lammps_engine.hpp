// SPDX-License-Identifier: MIT
#pragma once

#include <mutex>
#include <string>

#include "reference/common/engine.hpp"
#include "reference/lammps/deck_writer.hpp"
#include "reference/lammps/lammps_runner.hpp"

namespace reference {

/// How the LAMMPS engine finds and drives the binary.
struct LammpsOptions {
  std::string program = "lmp";  ///< searched in PATH (or a path)
  std::string extra_commands;   ///< LAMMPS commands inserted just before `run` (diagnostics, tests)
  double probe_timeout_s = lammps::kProbeTimeout;  ///< limit of the version probe
};

/// LAMMPS (Debian 20220106, "29 Sep 2021 - Update 2", pair_style granular) as an engine: writes
/// a deck for the scene (lammps/deck_writer.hpp), runs `lmp` in a fresh directory under the
/// run's work_dir, and reads the trace and snapshots back. Phase 1 maps the linear spring and
/// spring–dashpot; other sub-models are reported as not mapped (n/a) with the reason.
class LammpsEngine final : public Engine {
 public:
  using Engine::input_fingerprint;
  using Engine::run;
  using Engine::supports;
  LammpsEngine() : LammpsEngine(LammpsOptions{}) {}
  /// An engine driving `options.program`.
  explicit LammpsEngine(LammpsOptions options) : options_(std::move(options)) {}

  [[nodiscard]] std::string_view name() const noexcept override { return "lammps"; }
  /// The banner version of the binary, empty when it is not found. The binary is probed once per
  /// engine object (an empty run, at most options.probe_timeout_s).
  [[nodiscard]] std::optional<std::string> version() const override;
  /// The binary's full path, or why it was not found.
  [[nodiscard]] std::string location() const override;
  [[nodiscard]] Support supports(const PreparedScene& prepared) const override;
  [[nodiscard]] cases::RunResult run(const PreparedScene& prepared, const RunOptions& options) const override;
  /// SHA-256 of the deck and, for a large scene, the data file run() would write.
  [[nodiscard]] std::string input_fingerprint(const PreparedScene& prepared) const override;

 private:
  /// The deck settings of `scene` run with time step `timestep` (the core's resolved one).
  [[nodiscard]] lammps::DeckSettings deck_settings(const cases::Scene& scene, double timestep) const;
  /// The probe of the binary, run on first use.
  const lammps::LammpsProbe& probe() const;

  LammpsOptions options_;
  mutable std::once_flag probed_;
  mutable lammps::LammpsProbe probe_;
};

}  // namespace reference
