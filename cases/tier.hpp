// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string_view>

namespace cases {

/// How expensive a case is, and so where it runs (docs/case-format.md, "[case]"): `fast` cases
/// run in CI on every engine; `full` cases (ensembles, long studies) run outside CI, and in the
/// fast tier their reference-code results come from the committed baseline.
enum class Tier { fast, full };

/// The keyword of a tier ("fast", "full").
std::string_view to_string(Tier tier) noexcept;
/// The tier called `word`, or empty.
std::optional<Tier> parse_tier(std::string_view word) noexcept;

}  // namespace cases
