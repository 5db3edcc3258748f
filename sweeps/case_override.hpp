// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sweeps {

/// The case text of one sweep run: `text` (a case file, named `path` in messages) with each
/// (dotted key, value) replaced — the key must already hold a number, so a misspelt key is an
/// error, never a silent new entry — and, with `seed`, every [[populations]] entry's seed set to
/// seed + its index. An integer value stays an integer when the new value is integral. Throws
/// cases::CaseError naming the file and key when a key is missing, holds no number, or the case
/// has no [[populations]] to seed.
std::string override_case(std::string_view text, const std::string& path,
                          const std::vector<std::pair<std::string, double>>& values, std::optional<std::uint64_t> seed);

}  // namespace sweeps
