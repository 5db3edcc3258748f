// SPDX-License-Identifier: MIT
#include "cases/tier.hpp"

namespace cases {

std::string_view to_string(Tier tier) noexcept { return tier == Tier::full ? "full" : "fast"; }

std::optional<Tier> parse_tier(std::string_view word) noexcept {
  if (word == "fast") return Tier::fast;
  if (word == "full") return Tier::full;
  return std::nullopt;
}

}  // namespace cases
