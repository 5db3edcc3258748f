// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cases/run_result.hpp"
#include "cases/scene.hpp"
#include "reference/common/prepared_scene.hpp"

namespace reference {

/// Whether an engine can express a scene, and if not, every reason why.
struct Support {
  std::vector<std::string> reasons;  ///< empty when supported
  /// True when the engine can run the scene.
  [[nodiscard]] bool supported() const noexcept { return reasons.empty(); }
  /// Reasons joined with "; ".
  [[nodiscard]] std::string explain() const;
};

/// Options of one run.
struct RunOptions {
  std::filesystem::path work_dir;  ///< scratch directory the engine may use (created if needed)
  double timeout_s = 600.0;        ///< external engines are killed after this
  int threads = 1;                 ///< OpenMP threads of the core (results do not depend on it)
};

/// One way of running a Scene: the in-house core, a closed-form solution, or a reference code.
/// run() never throws for engine failures: it returns status error / missing / n/a with a reason.
class Engine {
 public:
  virtual ~Engine() = default;
  /// Name used in case files, tables and results.json ("inhouse", "analytic", …).
  [[nodiscard]] virtual std::string_view name() const noexcept = 0;
  /// Version string, or empty when the engine is not installed.
  [[nodiscard]] virtual std::optional<std::string> version() const = 0;
  /// Where the engine's program was found (or why it was not): `demwb engines` and `missing`
  /// reasons show it.
  [[nodiscard]] virtual std::string location() const { return "built in"; }
  /// Can the engine express the prepared scene?
  [[nodiscard]] virtual Support supports(const PreparedScene& prepared) const = 0;
  /// Runs the prepared scene and returns its traces (status ok) or why not.
  [[nodiscard]] virtual cases::RunResult run(const PreparedScene& prepared, const RunOptions& options) const = 0;
  /// SHA-256 of everything the engine would feed its program for the scene (a reference code's
  /// input deck, data file or script), without running it: a stored result whose fingerprint
  /// differs was made from another input. Empty for engines with no external input (the core,
  /// closed forms) and for scenes the engine cannot express.
  [[nodiscard]] virtual std::string input_fingerprint(const PreparedScene& /*prepared*/) const { return {}; }

  /// supports() of `scene` prepared for this one call.
  [[nodiscard]] Support supports(const cases::Scene& scene) const { return supports(PreparedScene(scene)); }
  /// run() of `scene` prepared for this one call.
  [[nodiscard]] cases::RunResult run(const cases::Scene& scene, const RunOptions& options) const {
    return run(PreparedScene(scene), options);
  }
  /// input_fingerprint() of `scene` prepared for this one call.
  [[nodiscard]] std::string input_fingerprint(const cases::Scene& scene) const {
    return input_fingerprint(PreparedScene(scene));
  }
};

/// Which external programs the reference engines drive (docs/user-guide.md, "Choosing the
/// reference binaries").
struct ExternalPrograms {
  std::string lammps = "lmp";   ///< LAMMPS binary: a path, or a name searched in PATH
  std::string yade = "yade";    ///< YADE launcher script: a path, or a name searched in PATH
  std::string liggghts = "liggghts";  ///< LIGGGHTS binary: a path, or a name searched in PATH
  double probe_timeout_s = 10.0;  ///< limit of a version probe that starts a process
};

// The engines themselves are made by make_engine (reference/registry.hpp), the one place that
// knows every driver: this header is what every engine and caller shares.

/// A failed run (status error) with its reason and the tail of the code's log.
cases::RunResult error_result(std::string reason, std::string log_tail);

/// Runs `engine` on the prepared scene with the common bookkeeping: `missing` when not
/// installed, `n/a` with reasons when unsupported, `error` with the message when run() throws,
/// and `error` when the trace holds a non-finite value. Sets engine name, version and wall time.
cases::RunResult run_engine(const Engine& engine, const PreparedScene& prepared, const RunOptions& options);

/// run_engine on `scene` prepared for this one run.
cases::RunResult run_engine(const Engine& engine, const cases::Scene& scene, const RunOptions& options);

}  // namespace reference
