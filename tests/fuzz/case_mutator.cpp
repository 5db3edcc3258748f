// SPDX-License-Identifier: MIT
#include "case_mutator.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <string_view>

#include <fmt/format.h>

namespace fuzz {
namespace {

/// Numbers a mutation puts in place of a number: edges of every range check, non-finite values,
/// subnormals and integers beyond int64.
constexpr auto kNumbers = std::to_array<std::string_view>(
    {"0", "-1", "1e300", "-1e300", "nan", "inf", "-inf", "+inf", "5e-324", "-5e-324", "1e-300",
     "9223372036854775807", "-9223372036854775808", "18446744073709551616", "99999999999999999999999",
     "0.0", "-0.0", "1", "2", "2.5", "1e3", "1e-9", "0.5", "1.0e9", "100000000", "3"});

/// String contents (already TOML-escaped) a mutation puts in place of a string's content.
constexpr auto kPayloads = std::to_array<std::string_view>(
    {"a\\nshell touch x\\n#", "$(id)", "`id`", "; rm -rf /tmp/demwb_fuzz", "../../../etc/passwd", "%s%n%x",
     "\\\"\\\"\\\"", "'''", "\\u0000", "\\u001b[31m", "é日本", "", " ", "auto", "launch", "inhouse", "x\\ty",
     "${HOME}", "\\\\", "a\\\"b", "NaN", "C:\\\\con"});

/// Whole tokens a mutation puts in place of a string token (syntax-level damage).
constexpr auto kRawTokens = std::to_array<std::string_view>({"\"\"\"", "'''", "\"", "'", "\"\"\"a\n\"\"\"", "[", "{", "="});

/// splitmix64: the seed of input k, well mixed.
std::uint64_t mix(std::uint64_t x) noexcept {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30U)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27U)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31U);
}

/// A uniform index below n (n > 0).
std::size_t pick(std::mt19937_64& rng, std::size_t n) {
  return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
}

/// Start offsets of the lines of `text`.
std::vector<std::size_t> line_starts(const std::string& text) {
  std::vector<std::size_t> out{0};
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n' && i + 1 < text.size()) out.push_back(i + 1);
  }
  return out;
}

/// [begin, end) of line `k` including its newline.
std::pair<std::size_t, std::size_t> line_span(const std::string& text, const std::vector<std::size_t>& starts,
                                              std::size_t k) {
  const std::size_t end = k + 1 < starts.size() ? starts[k + 1] : text.size();
  return {starts[k], end};
}

/// A character that may appear in a TOML number.
bool number_char(char c) noexcept {
  return std::isdigit(static_cast<unsigned char>(c)) != 0 || c == '.' || c == 'e' || c == 'E' || c == '+' ||
         c == '-' || c == '_';
}

/// [begin, end) of every number token that follows '=', '[', ',' or '{' (spaces allowed).
std::vector<std::pair<std::size_t, std::size_t>> numbers_of(const std::string& text) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const bool starts = std::isdigit(static_cast<unsigned char>(c)) != 0 ||
                        ((c == '-' || c == '+') && i + 1 < text.size() &&
                         std::isdigit(static_cast<unsigned char>(text[i + 1])) != 0);
    if (!starts) continue;
    std::size_t before = i;
    while (before > 0 && (text[before - 1] == ' ' || text[before - 1] == '\t')) --before;
    if (before == 0 || std::string_view("=[,{").find(text[before - 1]) == std::string_view::npos) continue;
    std::size_t end = i;
    while (end < text.size() && number_char(text[end])) ++end;
    out.emplace_back(i, end);
    i = end;
  }
  return out;
}

/// [begin, end) of every basic string "…" (quotes included) on one line, escapes honoured.
std::vector<std::pair<std::size_t, std::size_t>> strings_of(const std::string& text) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  bool comment = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') comment = false;
    if (comment) continue;
    if (text[i] == '#') {
      comment = true;
      continue;
    }
    if (text[i] != '"') continue;
    std::size_t j = i + 1;
    while (j < text.size() && text[j] != '"' && text[j] != '\n') j += text[j] == '\\' ? 2 : 1;
    if (j >= text.size() || text[j] != '"') break;
    out.emplace_back(i, j + 1);
    i = j;
  }
  return out;
}

/// [begin, end) of the key of every `key = value` line.
std::vector<std::pair<std::size_t, std::size_t>> keys_of(const std::string& text) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (const std::size_t start : line_starts(text)) {
    std::size_t i = start;
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    std::size_t j = i;
    while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) != 0 || text[j] == '_' ||
                               text[j] == '.' || text[j] == '-')) {
      ++j;
    }
    std::size_t k = j;
    while (k < text.size() && text[k] == ' ') ++k;
    if (j > i && k < text.size() && text[k] == '=') out.emplace_back(i, j);
  }
  return out;
}

/// Indices of the lines that open a table: `[name]` or `[[name]]`.
std::vector<std::size_t> header_lines(const std::string& text, const std::vector<std::size_t>& starts) {
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    if (starts[k] < text.size() && text[starts[k]] == '[') out.push_back(k);
  }
  return out;
}

/// [begin, end) of every one-line array value `= [ … ]`.
std::vector<std::pair<std::size_t, std::size_t>> arrays_of(const std::string& text) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t i = 0; i + 1 < text.size(); ++i) {
    if (text[i] != '=') continue;
    std::size_t j = i + 1;
    while (j < text.size() && text[j] == ' ') ++j;
    if (j >= text.size() || text[j] != '[') continue;
    int depth = 0;
    std::size_t k = j;
    for (; k < text.size() && text[k] != '\n'; ++k) {
      if (text[k] == '[') ++depth;
      if (text[k] == ']' && --depth == 0) break;
    }
    if (k < text.size() && text[k] == ']') out.emplace_back(j, k + 1);
  }
  return out;
}

/// A long run of one character, sometimes megabytes.
std::string long_text(std::mt19937_64& rng) {
  constexpr std::array<std::size_t, 4> kLengths{100, 10'000, 100'000, 1'000'000};
  const std::size_t n = kLengths[pick(rng, kLengths.size())];
  return std::string(n, "aZ_9"[pick(rng, 4)]);
}

}  // namespace

CaseMutator::CaseMutator(std::vector<std::string> corpus, std::size_t valid, std::uint64_t seed)
    : corpus_(std::move(corpus)), valid_(std::min(valid, corpus_.size())), seed_(seed) {
  for (const std::string& text : corpus_) {
    for (const auto& [b, e] : keys_of(text)) keys_.push_back(text.substr(b, e - b));
    for (const auto& [b, e] : strings_of(text)) strings_.push_back(text.substr(b, e - b));
    const auto starts = line_starts(text);
    for (std::size_t k = 0; k < starts.size(); ++k) {
      const auto [b, e] = line_span(text, starts, k);
      lines_.push_back(text.substr(b, e - b));
    }
  }
  std::sort(keys_.begin(), keys_.end());
  keys_.erase(std::unique(keys_.begin(), keys_.end()), keys_.end());
  std::sort(strings_.begin(), strings_.end());
  strings_.erase(std::unique(strings_.begin(), strings_.end()), strings_.end());
  keys_.push_back("x");
  strings_.push_back("\"\"");
  lines_.push_back("\n");
}

Mutant CaseMutator::mutant(std::uint64_t k) const {
  std::mt19937_64 rng(mix(seed_ ^ mix(k)));
  Mutant m;
  const bool from_valid = valid_ > 0 && pick(rng, 5) != 0;
  m.seed_file = from_valid ? pick(rng, valid_) : pick(rng, corpus_.size());
  m.text = corpus_[m.seed_file];
  constexpr std::array<std::size_t, 10> kCounts{1, 1, 1, 1, 1, 1, 2, 2, 2, 3};
  const std::size_t count = kCounts[pick(rng, kCounts.size())];
  for (std::size_t i = 0; i < count; ++i) m.steps.push_back(mutate_once(m.text, rng));
  return m;
}

std::string CaseMutator::mutate_once(std::string& text, std::mt19937_64& rng) const {
  if (text.empty()) text = "\n";
  const auto starts = line_starts(text);
  switch (pick(rng, 16)) {
    case 0: {  // flip one bit
      const std::size_t i = pick(rng, text.size());
      text[i] = static_cast<char>(text[i] ^ static_cast<char>(1U << pick(rng, 8)));
      return fmt::format("flip a bit at byte {}", i);
    }
    case 1: {  // insert a byte that matters to TOML (or any byte)
      constexpr std::string_view kBytes("\0\x01\x7f\xff\n\r\t\"'[]{}=#\\,.", 17);
      const std::size_t i = pick(rng, text.size() + 1);
      const char c = pick(rng, 4) == 0 ? static_cast<char>(pick(rng, 256)) : kBytes[pick(rng, kBytes.size())];
      text.insert(i, 1, c);
      return fmt::format("insert byte {:#04x} at {}", static_cast<unsigned char>(c), i);
    }
    case 2: {  // truncate
      const std::size_t i = pick(rng, text.size());
      text.resize(i);
      return fmt::format("truncate to {} bytes", i);
    }
    case 3: {  // duplicate a line
      const auto [b, e] = line_span(text, starts, pick(rng, starts.size()));
      text.insert(e, text.substr(b, e - b));
      return fmt::format("duplicate the line at {}", b);
    }
    case 4: {  // delete a line
      const auto [b, e] = line_span(text, starts, pick(rng, starts.size()));
      text.erase(b, e - b);
      return fmt::format("delete the line at {}", b);
    }
    case 5: {  // splice a line of some corpus text in
      const std::size_t at = starts[pick(rng, starts.size())];
      const std::string& line = lines_[pick(rng, lines_.size())];
      text.insert(at, line.back() == '\n' ? line : line + "\n");
      return fmt::format("insert a corpus line at {}", at);
    }
    case 6:
    case 7:
    case 8: {  // replace a number
      const auto numbers = numbers_of(text);
      if (numbers.empty()) return "no number to replace";
      const auto [b, e] = numbers[pick(rng, numbers.size())];
      const std::string_view by = kNumbers[pick(rng, kNumbers.size())];
      text.replace(b, e - b, by);
      return fmt::format("replace the number at {} by {}", b, by);
    }
    case 9:
    case 10: {  // replace a string's content, or the whole token
      const auto strings = strings_of(text);
      if (strings.empty()) return "no string to replace";
      const auto [b, e] = strings[pick(rng, strings.size())];
      switch (pick(rng, 4)) {
        case 0: {
          const std::string by = long_text(rng);
          text.replace(b + 1, e - b - 2, by);
          return fmt::format("replace the string at {} by {} characters", b, by.size());
        }
        case 1: {
          const std::string_view by = kRawTokens[pick(rng, kRawTokens.size())];
          text.replace(b, e - b, by);
          return fmt::format("replace the string token at {} by raw {}", b, by);
        }
        case 2: {
          const std::string& by = strings_[pick(rng, strings_.size())];
          text.replace(b, e - b, by);
          return fmt::format("replace the string at {} by corpus string {}", b, by);
        }
        default: {
          const std::string_view by = kPayloads[pick(rng, kPayloads.size())];
          text.replace(b + 1, e - b - 2, by);
          return fmt::format("replace the string at {} by payload \"{}\"", b, by);
        }
      }
    }
    case 11: {  // rename a key
      const auto keys = keys_of(text);
      if (keys.empty()) return "no key to rename";
      const auto [b, e] = keys[pick(rng, keys.size())];
      std::string by;
      switch (pick(rng, 5)) {
        case 0: by = keys_[pick(rng, keys_.size())]; break;
        case 1: by = text.substr(b, e - b) + "x"; break;
        case 2: by = text.substr(b, e - b - 1); break;
        case 3: by = "\"" + std::string(kPayloads[pick(rng, kPayloads.size())]) + "\""; break;
        default: by = long_text(rng); break;
      }
      if (by.empty()) by = "\"\"";
      text.replace(b, e - b, by);
      return fmt::format("rename the key at {} to {} bytes", b, by.size());
    }
    case 12: {  // duplicate or delete a table, up to the next header
      const auto headers = header_lines(text, starts);
      if (headers.empty()) return "no table";
      const std::size_t h = pick(rng, headers.size());
      const std::size_t b = starts[headers[h]];
      const std::size_t e = h + 1 < headers.size() ? starts[headers[h + 1]] : text.size();
      std::string block = text.substr(b, e - b);
      if (!block.empty() && block.back() != '\n') block += '\n';
      if (pick(rng, 3) == 0) {
        text.erase(b, e - b);
        return fmt::format("delete the table at {}", b);
      }
      text.insert(e, block);
      return fmt::format("duplicate the table at {}", b);
    }
    case 13: {  // empty or blow up an array
      const auto arrays = arrays_of(text);
      if (arrays.empty()) return "no array";
      const auto [b, e] = arrays[pick(rng, arrays.size())];
      switch (pick(rng, 4)) {
        case 0: text.replace(b, e - b, "[]"); return fmt::format("empty the array at {}", b);
        case 1: {
          std::string big = "[";
          const std::size_t n = pick(rng, 2) == 0 ? 4 : 10'000;
          for (std::size_t i = 0; i < n; ++i) big += i == 0 ? "0" : ", 0";
          text.replace(b, e - b, big + "]");
          return fmt::format("replace the array at {} by {} zeros", b, n);
        }
        case 2: text.replace(b, e - b, std::string(200, '[') + std::string(200, ']')); return "nest an array deeply";
        default: text.replace(b, e - b, "[1, \"a\", true, [2]]"); return fmt::format("mix types in the array at {}", b);
      }
    }
    case 14: {  // add a known key with a wild value somewhere
      const std::size_t at = starts[pick(rng, starts.size())];
      const std::string line = fmt::format("{} = {}\n", keys_[pick(rng, keys_.size())],
                                           pick(rng, 2) == 0 ? std::string(kNumbers[pick(rng, kNumbers.size())])
                                                             : strings_[pick(rng, strings_.size())]);
      text.insert(at, line);
      return fmt::format("insert `{}` at {}", line.substr(0, line.size() - 1), at);
    }
    default: {  // swap two lines
      const std::size_t a = pick(rng, starts.size());
      const std::size_t c = pick(rng, starts.size());
      if (a == c) return "swap a line with itself";
      const auto [ab, ae] = line_span(text, starts, std::min(a, c));
      const auto [cb, ce] = line_span(text, starts, std::max(a, c));
      std::string first = text.substr(ab, ae - ab);
      std::string second = text.substr(cb, ce - cb);
      if (first.empty() || first.back() != '\n') first += '\n';
      if (second.empty() || second.back() != '\n') second += '\n';
      text = text.substr(0, ab) + second + text.substr(ae, cb - ae) + first + text.substr(ce);
      return fmt::format("swap the lines at {} and {}", ab, cb);
    }
  }
}

}  // namespace fuzz
