// SPDX-License-Identifier: MIT
#pragma once
// The engines this build has, one row each: the only place that knows every driver. Adding an
// engine is one folder under reference/, one row here (registry.cpp) and one CMake line
// (docs/architecture.md, "Adding an engine").

#include <memory>
#include <span>
#include <string_view>

#include "reference/engine.hpp"

namespace reference {

/// One engine of the build: its name in case files and a factory driving the given programs.
struct EngineEntry {
  std::string_view name;  ///< "inhouse", "analytic", "lammps", "yade"
  std::unique_ptr<Engine> (*make)(const ExternalPrograms& programs);
};

/// Every engine of the build, in the order `demwb engines` lists them. The matched engines
/// ("inhouse@<code>") are not rows: make_engine builds one for any code with matched numerics.
[[nodiscard]] std::span<const EngineEntry> engine_registry() noexcept;

/// The engine called `name` driving `programs`, or nullptr when no such engine exists.
[[nodiscard]] std::unique_ptr<Engine> make_engine(std::string_view name, const ExternalPrograms& programs = {});

}  // namespace reference
