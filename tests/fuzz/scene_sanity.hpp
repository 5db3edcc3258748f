// SPDX-License-Identifier: MIT
#pragma once
// What every scene the loader returns must satisfy, whatever the case file said: the invariants
// the loader promises the engines (docs/case-format.md), checked by the fuzz test.
#include <string>
#include <vector>

#include "cases/case_loader.hpp"

namespace fuzz {

/// Every broken invariant of `scene`, as readable sentences (empty when it is sane): finite,
/// positive sizes; masses, moments of inertia and time step inside the derived-quantity window;
/// speeds below light; indices in range; at most the limits of cases/limits.hpp; an output
/// estimate within the machine's memory; warnings on one bounded line.
[[nodiscard]] std::vector<std::string> scene_problems(const cases::Scene& scene);

/// Every broken promise of a load error: what() starts with `file`, is one line of printable
/// text of bounded length, and names a key.
[[nodiscard]] std::vector<std::string> error_problems(const cases::CaseError& error, const std::string& file);

}  // namespace fuzz
