// SPDX-License-Identifier: MIT
#pragma once
// Seeded, deterministic mutations of case-file text for the loader's fuzz test: byte flips,
// truncation, duplicated, deleted and spliced lines, numbers replaced by 0, -1, 1e300, nan, inf,
// 5e-324 or huge integers, strings replaced by injection payloads, quotes or very long text, keys
// renamed, tables duplicated or dropped, arrays emptied or blown up.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace fuzz {

/// One mutated text and what was done to it (for the report of a failing input).
struct Mutant {
  std::string text;
  std::vector<std::string> steps;  ///< the mutations applied, in order
  std::size_t seed_file = 0;       ///< index of the corpus text it started from
};

/// Mutates the texts of a corpus. Input k is a function of (seed, k) alone, so any input of a
/// long run can be replayed by its index.
class CaseMutator {
 public:
  /// A mutator over `corpus` (at least one text) seeded with `seed`; its first `valid` texts are
  /// cases that load, and four inputs in five start from one of them.
  CaseMutator(std::vector<std::string> corpus, std::size_t valid, std::uint64_t seed);
  /// The k-th mutated text: a corpus text with one (most often) to three mutations.
  [[nodiscard]] Mutant mutant(std::uint64_t k) const;

 private:
  /// Applies one randomly chosen mutation to `text`; returns its description.
  std::string mutate_once(std::string& text, std::mt19937_64& rng) const;

  std::vector<std::string> corpus_;
  std::size_t valid_;
  std::vector<std::string> keys_;     ///< every `key =` of the corpus
  std::vector<std::string> strings_;  ///< every "string" of the corpus, quotes included
  std::vector<std::string> lines_;    ///< every line of the corpus
  std::uint64_t seed_;
};

}  // namespace fuzz
