// SPDX-License-Identifier: MIT
#pragma once
// The engines this build has, one row each: the only place that knows every driver. Adding an
// engine is one folder under reference/, one row here (registry.cpp) and one CMake line
// (docs/architecture.md, "Adding an engine").

#include <memory>
#include <span>
#include <string_view>

#include "reference/common/code_conventions.hpp"
#include "reference/common/engine.hpp"

namespace reference {

/// One engine of the build: its name in case files, a factory driving the given programs and,
/// for a reference code whose numerics the core can adopt, the conventions its driver exports.
struct EngineEntry {
  std::string_view name;  ///< "inhouse", "analytic", "lammps", "yade", "liggghts"
  std::unique_ptr<Engine> (*make)(const ExternalPrograms& programs);
  /// The code's numerics for the matched engine "inhouse@<name>"; null when it has none.
  const CodeConventions& (*conventions)() noexcept = nullptr;
};

/// Every engine of the build, in the order `demwb engines` lists them. The matched engines
/// ("inhouse@<code>") are not rows: make_engine builds one for any row with conventions.
[[nodiscard]] std::span<const EngineEntry> engine_registry() noexcept;

/// The engine called `name` driving `programs`, or nullptr when no such engine exists.
[[nodiscard]] std::unique_ptr<Engine> make_engine(std::string_view name, const ExternalPrograms& programs = {});

/// The numerics of reference code `code` for the matched engine, or nullptr when the build has no
/// such code or the code has no matched variant.
[[nodiscard]] const CodeConventions* code_conventions(std::string_view code) noexcept;

}  // namespace reference
