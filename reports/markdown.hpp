// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compare/status.hpp"

namespace reports {

/// A GitHub-flavoured markdown table built row by row.
class MarkdownTable {
 public:
  /// A table with these column headers.
  explicit MarkdownTable(std::vector<std::string> header);
  /// Appends a row (missing cells are left empty, extra cells are an error).
  void add_row(std::vector<std::string> cells);
  /// The table as markdown, ending with a newline.
  [[nodiscard]] std::string render() const;
  /// Number of data rows.
  [[nodiscard]] std::size_t rows() const noexcept { return rows_.size(); }

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

/// A number with 6 significant digits, or "—" when empty (tables never show NaN).
std::string format_number(std::optional<double> v);
/// A relative difference as a percentage-free scientific value, "—" when empty.
std::string format_ratio(std::optional<double> v);
/// Status with a mark for reading at a glance, e.g. "✅ pass".
std::string status_cell(comparison::Status status);
/// Text safe inside a table cell (pipes escaped, newlines flattened).
std::string cell_text(std::string_view text);
/// Free text from a case file (description, thesis reference) made inert for a markdown report:
/// control characters become spaces, `&`, `<` and `>` HTML entities, and the punctuation that
/// makes links, images, code, emphasis, headings and table cells (backslash, backtick, '*', '[',
/// ']', '!', '#', '|') is backslash-escaped, so the text shows as written and never becomes
/// active markdown or HTML.
std::string inert_text(std::string_view text);

}  // namespace reports
