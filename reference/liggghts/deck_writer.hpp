// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string>

#include "reference/common/prepared_scene.hpp"
#include "reference/liggghts/contact_mapping.hpp"
#include "reference/liggghts/trace_columns.hpp"

namespace reference::liggghts {

/// What the deck needs besides the scene.
struct DeckSettings {
  double timestep = 0.0;                         ///< Δt [s], the core's
  std::uint64_t steps = 0;                       ///< steps to run
  std::string snapshot_file = "snapshots.dump";  ///< dump custom output
};

/// The whole LIGGGHTS deck: a pure function of the scene, its contact settings, trace plan and
/// the settings (docs/engines.md, "LIGGGHTS").
std::string write_deck(const cases::Scene& scene, const AtomTypes& types, const ContactSettings& contacts,
                       const TracePlan& plan, const DeckSettings& settings);

}  // namespace reference::liggghts
