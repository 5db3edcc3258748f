// SPDX-License-Identifier: MIT
#pragma once

#include "reference/common/engine.hpp"
#include "reference/yade/yade_installation.hpp"

namespace reference {

/// YADE 2023.02a (Debian) as a reference engine (docs/engines.md, section YADE): writes a Python
/// script for the scene, runs it by importing yade as a module under python3.11 (never the
/// `yade` launcher, which opens network listeners), and reads back a trace with exactly the
/// in-house engine's columns and sample times. Phase 1: linear spring with damping
/// none/restitution, frictionless, fixed spheres, gravity.
class YadeEngine final : public Engine {
 public:
  using Engine::input_fingerprint;
  using Engine::run;
  using Engine::supports;
  /// The engine for the YADE found at `install` (the Debian layout by default).
  explicit YadeEngine(yade::YadeInstallation install = yade::default_yade_installation());
  /// The engine for the YADE whose launcher script is `program` (a path or a name in PATH); a
  /// launcher that is absent or unreadable gives an engine that is `missing`, with the reason.
  static YadeEngine from_launcher(const std::string& program);

  [[nodiscard]] std::string_view name() const noexcept override { return "yade"; }
  [[nodiscard]] std::optional<std::string> version() const override;
  /// The launcher, interpreter and module directory, or why YADE was not found.
  [[nodiscard]] std::string location() const override;
  [[nodiscard]] Support supports(const PreparedScene& prepared) const override;
  [[nodiscard]] cases::RunResult run(const PreparedScene& prepared, const RunOptions& options) const override;
  /// SHA-256 of the Python script run() would give YADE.
  [[nodiscard]] std::string input_fingerprint(const PreparedScene& prepared) const override;

 private:
  yade::YadeInstallation install_;
  std::string launcher_;  ///< the launcher the installation was read from, if any
  std::string problem_;   ///< why there is no installation (the engine is then missing)
};

}  // namespace reference
