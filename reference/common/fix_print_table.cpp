// SPDX-License-Identifier: MIT
#include "reference/common/fix_print_table.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "support/text_tokens.hpp"

namespace reference {

using support::split_lines;
using support::split_words;
using support::parse_number;

cases::Trace parse_fix_print(std::string_view text, std::string_view file_name) {
  cases::Trace trace;
  bool have_header = false;
  std::vector<double> row;
  std::size_t line_number = 0;
  for (const std::string_view line : split_lines(text)) {
    ++line_number;
    const std::vector<std::string_view> tokens = split_words(line);
    if (tokens.empty()) continue;
    if (!have_header) {
      if (tokens.front() != "#" || tokens.size() < 2) {
        throw std::runtime_error(fmt::format(
            "{} line {}: expected the header \"# name …\", found \"{}\"", file_name, line_number,
            line));
      }
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        if (trace.column(tokens[k]) != nullptr) {
          throw std::runtime_error(fmt::format("{} line {}: column '{}' appears twice", file_name,
                                               line_number, tokens[k]));
        }
        trace.add_column(std::string(tokens[k]));
      }
      have_header = true;
      continue;
    }
    if (tokens.size() != trace.columns().size()) {
      throw std::runtime_error(fmt::format("{} line {}: {} values for {} columns", file_name,
                                           line_number, tokens.size(), trace.columns().size()));
    }
    row.clear();
    for (std::size_t k = 0; k < tokens.size(); ++k) {
      const auto value = parse_number(tokens[k]);
      if (!value) {
        throw std::runtime_error(fmt::format("{} line {}: value {} of column '{}' is \"{}\", not a "
                                             "number",
                                             file_name, line_number, k + 1, trace.columns()[k],
                                             tokens[k]));
      }
      row.push_back(*value);
    }
    trace.append_row(row);
  }
  if (!have_header) {
    throw std::runtime_error(fmt::format("{} is empty (no header line)", file_name));
  }
  return trace;
}

}  // namespace reference
