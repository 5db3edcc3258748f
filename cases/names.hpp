// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <string_view>

#include "cases/toml_reader.hpp"

namespace cases {

/// Longest name a case file may give a wall, box, population or stage.
inline constexpr std::size_t kMaxNameLength = 64;

/// True when `text` is a name of 1 to 64 characters from A–Z, a–z, 0–9, '_', '-' and '.': the
/// grammar of the names a case file gives its walls, boxes, populations and stages. Such names
/// reach LAMMPS decks, YADE scripts, file names and reports, so nothing else may pass
/// (docs/case-format.md, Names).
[[nodiscard]] bool is_name(std::string_view text) noexcept;

/// True when `text` has 1 to 64 characters, each a digit, '_', a lowercase letter or (when `upper`
/// is set) an uppercase letter: the grammar of case names (lowercase) and material names.
[[nodiscard]] bool is_identifier(std::string_view text, bool upper) noexcept;

/// The string of `value`, or a load error naming the key when it is not a name (is_name); the
/// message shows at most the first 64 bytes of the offending value (cases::excerpt).
[[nodiscard]] std::string read_name(const loader::Value& value);

}  // namespace cases
