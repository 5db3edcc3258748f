// SPDX-License-Identifier: MIT
#pragma once

#include <string>

#include "reference/common/code_conventions.hpp"
#include "reference/common/engine.hpp"

namespace reference {

/// The in-house core run with a reference code's own numerics ("inhouse@lammps", "inhouse@yade"):
/// integrator, velocity convention, damping formula, friction-limit basis and tangential-history
/// rule of that code (the CodeConventions its driver exports), so that comparing it with the code isolates the
/// force model down to round-off (docs/engines.md, "Native and matched comparisons").
class MatchedInhouseEngine final : public Engine {
 public:
  using Engine::run;
  using Engine::supports;
  /// The core matched to the code whose numerics `conventions` describe.
  explicit MatchedInhouseEngine(const CodeConventions& conventions);
  [[nodiscard]] std::string_view name() const noexcept override { return name_; }
  [[nodiscard]] std::optional<std::string> version() const override;
  [[nodiscard]] Support supports(const PreparedScene& prepared) const override;
  [[nodiscard]] cases::RunResult run(const PreparedScene& prepared, const RunOptions& options) const override;

 private:
  CodeConventions conventions_;
  std::string name_;
};

}  // namespace reference
