// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace cases {

/// Optimal-string-alignment distance: insertions, deletions, substitutions and swaps of two
/// neighbouring characters each cost 1 ("restitutoin" is 1 away from "restitution").
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The candidate closest to `word` when it is at most 2 edits away (first one on a tie). Costs
/// O(|word|·|candidate|) only for candidates within 2 characters of the word's length.
std::optional<std::string_view> closest_match(std::string_view word,
                                              std::span<const std::string_view> candidates);

/// "; did you mean 'x'?" when a candidate is close to `word`, else "".
std::string did_you_mean(std::string_view word, std::span<const std::string_view> candidates);

/// Candidates joined with ", " (for "known: …" lists in messages).
std::string join(std::span<const std::string_view> words);

}  // namespace cases
