// SPDX-License-Identifier: MIT
#pragma once

#include <mutex>
#include <string>

#include "reference/common/engine.hpp"
#include "reference/liggghts/deck_writer.hpp"
#include "reference/liggghts/liggghts_runner.hpp"

namespace reference {

/// How the LIGGGHTS engine finds and drives the binary.
struct LiggghtsOptions {
  std::string program = "liggghts";                   ///< searched in PATH (or a path)
  double probe_timeout_s = liggghts::kProbeTimeout;    ///< limit of the version probe
};

/// LIGGGHTS-PUBLIC 3.8.0 (Debian `liggghts`) as an engine: writes a deck for the scene
/// (liggghts/deck_writer.hpp), runs it in a fresh directory under the run's work_dir, and reads
/// the thermo table and snapshots back. What it cannot express is n/a with the reason
/// (docs/engines.md, "LIGGGHTS").
class LiggghtsEngine final : public Engine {
 public:
  using Engine::input_fingerprint;
  using Engine::run;
  using Engine::supports;
  LiggghtsEngine() : LiggghtsEngine(LiggghtsOptions{}) {}
  /// An engine driving `options.program`.
  explicit LiggghtsEngine(LiggghtsOptions options) : options_(std::move(options)) {}

  [[nodiscard]] std::string_view name() const noexcept override { return "liggghts"; }
  /// The banner version ("LIGGGHTS-PUBLIC 3.8.0"), empty when the binary is not found; probed
  /// once per engine object.
  [[nodiscard]] std::optional<std::string> version() const override;
  /// The binary's full path, or why it was not found.
  [[nodiscard]] std::string location() const override;
  [[nodiscard]] Support supports(const PreparedScene& prepared) const override;
  [[nodiscard]] cases::RunResult run(const PreparedScene& prepared, const RunOptions& options) const override;
  /// SHA-256 of the deck run() would write.
  [[nodiscard]] std::string input_fingerprint(const PreparedScene& prepared) const override;

 private:
  const liggghts::LiggghtsProbe& probe() const;

  LiggghtsOptions options_;
  mutable std::once_flag probed_;
  mutable liggghts::LiggghtsProbe probe_;
};

}  // namespace reference
