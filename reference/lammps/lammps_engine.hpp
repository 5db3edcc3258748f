// SPDX-License-Identifier: MIT
#pragma once

#include <string>

#include "reference/engine.hpp"

namespace reference {

/// How the LAMMPS engine finds and drives the binary.
struct LammpsOptions {
  std::string program = "lmp";  ///< searched in PATH (or a path)
  std::string extra_commands;   ///< LAMMPS commands inserted just before `run` (diagnostics, tests)
};

/// LAMMPS (Debian 20220106, "29 Sep 2021 - Update 2", pair_style granular) as an engine: writes
/// a deck for the scene (lammps/deck_writer.hpp), runs `lmp` in a fresh directory under the
/// run's work_dir, and reads the trace and snapshots back. Phase 1 maps the linear spring and
/// spring–dashpot; other sub-models are reported as not mapped (n/a) with the reason.
class LammpsEngine final : public Engine {
 public:
  LammpsEngine() = default;
  /// An engine driving `options.program`.
  explicit LammpsEngine(LammpsOptions options) : options_(std::move(options)) {}

  [[nodiscard]] std::string_view name() const noexcept override { return "lammps"; }
  /// The banner version of the installed binary, empty when it is not in PATH.
  [[nodiscard]] std::optional<std::string> version() const override;
  [[nodiscard]] Support supports(const cases::Scene& scene) const override;
  [[nodiscard]] cases::RunResult run(const cases::Scene& scene,
                                     const RunOptions& options) const override;

 private:
  LammpsOptions options_;
};

}  // namespace reference
