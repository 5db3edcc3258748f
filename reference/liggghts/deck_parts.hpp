// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "reference/common/prepared_scene.hpp"
#include "reference/liggghts/atom_types.hpp"
#include "reference/liggghts/contact_mapping.hpp"

namespace reference::liggghts {

/// Everything a deck is made of, or the reasons (one each) it cannot be written.
struct DeckParts {
  AtomTypes types;                          ///< atom types of the particles and wall materials
  std::optional<ContactSettings> contacts;  ///< the mapped contact model (empty when it is incomplete)
  std::vector<std::string> reasons;         ///< why LIGGGHTS cannot run the scene; empty when it can
};

/// The atom types, contact settings and refusals of a scene: walls other than resting
/// axis-aligned planes, meshes, periodic boundaries, fluid, prescribed motion, charges and every
/// unmapped sub-model give a reason (docs/engines.md, "What LIGGGHTS 3.8.0 cannot express here").
DeckParts deck_parts(const PreparedScene& prepared);

/// A deck that only times a scene for `demwb bench`: the reference deck without trace columns,
/// stored forces or snapshots, thermo at the last step only, neighbour skin `skin` [m]. `data`
/// is the data file's content (empty when the atoms are inline).
struct TimingDeck {
  std::string deck;
  std::string data_file;  ///< the name the deck reads the data file by
  std::string data;
  std::vector<std::string> reasons;  ///< non-empty: LIGGGHTS cannot run the scene (deck empty)
};
TimingDeck timing_deck(const PreparedScene& prepared, double timestep, std::uint64_t steps, double skin);

}  // namespace reference::liggghts
