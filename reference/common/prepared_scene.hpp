// SPDX-License-Identifier: MIT
#pragma once
// A scene resolved once for every engine that runs it (docs/architecture.md, "Layers").

#include <exception>
#include <memory>

#include "cases/scene.hpp"
#include "dem/contact/pair_table.hpp"

namespace reference {

/// A scene with what every engine derives from it built once: the pair table (every material
/// pair mixed, overridden and given its contact law). The closed forms, the drivers and the core
/// all read the same table instead of rebuilding it. Refers to the scene, which must outlive it.
class PreparedScene {
 public:
  /// Resolves `scene`. A model that lacks a parameter does not throw here: pair_table() throws
  /// the same dem::ModelError at every call, so that each engine reports it as building the
  /// table itself would.
  explicit PreparedScene(const cases::Scene& scene);
  explicit PreparedScene(cases::Scene&&) = delete;  ///< would refer to a temporary

  /// The scene as given.
  [[nodiscard]] const cases::Scene& scene() const noexcept { return *scene_; }
  /// The scene's pair table; throws the dem::ModelError its construction raised.
  [[nodiscard]] const dem::PairTable& pair_table() const { return *shared_pair_table(); }
  /// The same table, shared with a dem::Simulation (dem::SimulationSetup::pair_table).
  [[nodiscard]] const std::shared_ptr<const dem::PairTable>& shared_pair_table() const;

 private:
  const cases::Scene* scene_;
  std::shared_ptr<const dem::PairTable> table_;
  std::exception_ptr table_error_;  ///< set when the table could not be built
};

}  // namespace reference
