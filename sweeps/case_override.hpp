// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace sweeps {

/// A case-file key a sweep holds at one value in every run ([sweep] set): a string (a model
/// choice such as "model.mindlin_form"), a number or a boolean.
struct FixedSetting {
  std::string key;
  std::variant<double, bool, std::string> value;
};

/// The case text of one sweep run: `text` (a case file, named `path` in messages) with each
/// `fixed` setting and then each (dotted key, value) replaced — the key must already hold a value
/// of the same kind (a number for the swept values), so a misspelt key is an error, never a silent
/// new entry — and, with `seed`, every [[populations]] entry's seed set to seed + its index. An
/// integer value stays an integer when the new value is integral. Throws cases::CaseError naming
/// the file and key when a key is missing, holds another kind of value, or the case has no
/// [[populations]] to seed.
std::string override_case(std::string_view text, const std::string& path,
                          const std::vector<std::pair<std::string, double>>& values, std::optional<std::uint64_t> seed,
                          const std::vector<FixedSetting>& fixed = {});

}  // namespace sweeps
