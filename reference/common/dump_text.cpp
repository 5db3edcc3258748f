// SPDX-License-Identifier: MIT
#include "reference/common/dump_text.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "support/text_tokens.hpp"

namespace reference {

using support::split_lines;
using support::split_words;
using support::parse_number;
namespace {

/// Reads `text` line by line, with errors that name the file and line.
class LineReader {
 public:
  LineReader(std::string_view text, std::string_view file_name)
      : lines_(split_lines(text)), file_name_(file_name) {}
  /// True when every line has been read (trailing blank lines ignored).
  [[nodiscard]] bool done() {
    while (next_ < lines_.size() && split_words(lines_[next_]).empty()) ++next_;
    return next_ >= lines_.size();
  }
  /// The next line; throws when there is none, saying what was expected.
  std::string_view next(std::string_view expected) {
    if (next_ >= lines_.size()) {
      fail_at(lines_.size() + 1, fmt::format("expected {}, found the end of the file", expected));
    }
    return lines_[next_++];
  }
  /// The next line, which must start with `header`; returns the rest of it.
  std::string_view expect_item(std::string_view header) {
    const std::string_view line = next(fmt::format("\"{}\"", header));
    if (line.substr(0, header.size()) != header) {
      fail(fmt::format("expected \"{}\", found \"{}\"", header, line));
    }
    return line.substr(header.size());
  }
  /// The next line as one non-negative integer.
  std::uint64_t integer(std::string_view what) {
    const auto words = split_words(next(what));
    const auto value = words.size() == 1 ? parse_number(words.front()) : std::nullopt;
    if (!value || *value < 0 || std::floor(*value) != *value) {
      fail(fmt::format("expected {}", what));
    }
    return static_cast<std::uint64_t>(*value);
  }
  /// Throws naming the line read last.
  [[noreturn]] void fail(const std::string& message) const { fail_at(next_, message); }

 private:
  [[noreturn]] void fail_at(std::size_t line, const std::string& message) const {
    throw std::runtime_error(fmt::format("{} line {}: {}", file_name_, line, message));
  }
  std::vector<std::string_view> lines_;
  std::string_view file_name_;
  std::size_t next_ = 0;
};

}  // namespace

std::vector<DumpFrame> parse_dump(std::string_view text, std::string_view file_name) {
  std::vector<DumpFrame> frames;
  LineReader in(text, file_name);
  while (!in.done()) {
    DumpFrame frame;
    in.expect_item("ITEM: TIMESTEP");
    frame.step = in.integer("the time step");
    in.expect_item("ITEM: NUMBER OF ATOMS");
    const std::uint64_t atoms = in.integer("the number of atoms");
    in.expect_item("ITEM: BOX BOUNDS");
    for (int k = 0; k < 3; ++k) static_cast<void>(in.next("a box bounds line"));
    for (const auto word : split_words(in.expect_item("ITEM: ATOMS"))) {
      frame.columns.emplace_back(word);
    }
    if (frame.columns.empty()) in.fail("\"ITEM: ATOMS\" names no column");
    for (std::uint64_t a = 0; a < atoms; ++a) {
      const auto words = split_words(in.next("an atom line"));
      if (words.size() != frame.columns.size()) {
        in.fail(fmt::format("{} values for {} columns", words.size(), frame.columns.size()));
      }
      std::vector<double> row;
      for (std::size_t k = 0; k < words.size(); ++k) {
        const auto value = parse_number(words[k]);
        if (!value) {
          in.fail(fmt::format("value of column '{}' is \"{}\", not a number", frame.columns[k],
                              words[k]));
        }
        row.push_back(*value);
      }
      frame.rows.push_back(std::move(row));
    }
    frames.push_back(std::move(frame));
  }
  return frames;
}

}  // namespace reference
