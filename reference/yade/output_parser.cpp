// SPDX-License-Identifier: MIT
#include "reference/yade/output_parser.hpp"

#include <cmath>
#include <set>
#include <string>

#include <fmt/format.h>

#include "support/text_tokens.hpp"

namespace reference::yade {
namespace {

using support::split_lines;

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  for (;;) {
    const auto comma = line.find(',');
    fields.push_back(line.substr(0, comma));
    if (comma == std::string_view::npos) return fields;
    line.remove_prefix(comma + 1);
  }
}

/// The number in `field` (the whole field), or throws naming file, line and column.
double to_number(std::string_view field, std::string_view file, std::size_t line,
                 std::string_view column) {
  const std::optional<double> value = support::parse_number(field);
  if (!value) {
    throw YadeOutputError(fmt::format("{} line {}, column '{}': '{}' is not a number", file, line,
                                      column, field));
  }
  return *value;
}

/// The header's column names; throws on an empty or duplicate name.
std::vector<std::string> header_columns(std::string_view line, std::string_view file) {
  std::vector<std::string> names;
  std::set<std::string, std::less<>> seen;
  for (const auto field : split_fields(line)) {
    if (field.empty()) throw YadeOutputError(fmt::format("{} line 1: empty column name in the header", file));
    if (!seen.emplace(field).second) {
      throw YadeOutputError(fmt::format("{} line 1: column '{}' appears twice", file, field));
    }
    names.emplace_back(field);
  }
  return names;
}

/// Data lines with their 1-based line numbers; a blank last line is ignored, any other blank
/// line is an error.
std::vector<std::pair<std::size_t, std::string_view>> data_lines(
    const std::vector<std::string_view>& lines, std::string_view file) {
  std::vector<std::pair<std::size_t, std::string_view>> out;
  for (std::size_t k = 1; k < lines.size(); ++k) {
    if (lines[k].empty()) {
      if (k + 1 == lines.size()) break;
      throw YadeOutputError(fmt::format("{} line {}: empty line", file, k + 1));
    }
    out.emplace_back(k + 1, lines[k]);
  }
  return out;
}

/// Values of one data line, checked against the column count.
std::vector<double> row_values(std::string_view line, std::size_t number, std::string_view file,
                               const std::vector<std::string>& columns) {
  const auto fields = split_fields(line);
  if (fields.size() != columns.size()) {
    throw YadeOutputError(fmt::format("{} line {}: expected {} values, found {}", file, number,
                                      columns.size(), fields.size()));
  }
  std::vector<double> row;
  row.reserve(fields.size());
  for (std::size_t c = 0; c < fields.size(); ++c) {
    row.push_back(to_number(fields[c], file, number, columns[c]));
  }
  return row;
}

}  // namespace

cases::Trace parse_trace_csv(std::string_view text, std::string_view file) {
  const auto lines = split_lines(text);
  if (lines.empty() || lines.front().empty()) {
    throw YadeOutputError(fmt::format("{}: empty file (no header line)", file));
  }
  const auto columns = header_columns(lines.front(), file);
  cases::Trace trace;
  for (const auto& c : columns) trace.add_column(c);
  for (const auto& [number, line] : data_lines(lines, file)) {
    trace.append_row(row_values(line, number, file, columns));
  }
  return trace;
}

std::vector<cases::Snapshot> parse_snapshot_csv(std::string_view text, std::string_view file,
                                                std::size_t particle_count) {
  static const std::vector<std::string> kColumns{"time", "particle", "x",  "y",  "z", "vx",
                                                 "vy",   "vz",       "wx", "wy", "wz"};
  const auto lines = split_lines(text);
  if (lines.empty() || lines.front().empty()) {
    throw YadeOutputError(fmt::format("{}: empty file (no header line)", file));
  }
  if (header_columns(lines.front(), file) != kColumns) {
    throw YadeOutputError(fmt::format("{} line 1: expected the header 'time,particle,x,y,z,vx,vy,vz,wx,wy,wz'", file));
  }
  std::vector<cases::Snapshot> snapshots;
  if (particle_count == 0) {
    if (!data_lines(lines, file).empty()) {
      throw YadeOutputError(fmt::format("{}: snapshot rows for a scene without particles", file));
    }
    return snapshots;
  }
  std::size_t expected = 0;  // particle index the next line must carry
  for (const auto& [number, line] : data_lines(lines, file)) {
    const auto v = row_values(line, number, file, kColumns);
    if (v[1] != static_cast<double>(expected)) {
      throw YadeOutputError(fmt::format("{} line {}: expected particle {}, found {}", file, number,
                                        expected, v[1]));
    }
    if (expected == 0) {
      snapshots.emplace_back();
      snapshots.back().time = v[0];
    } else if (v[0] != snapshots.back().time) {
      throw YadeOutputError(fmt::format("{} line {}: time {} differs from the snapshot's {}", file,
                                        number, v[0], snapshots.back().time));
    }
    cases::Snapshot& s = snapshots.back();
    s.position.push_back({v[2], v[3], v[4]});
    s.velocity.push_back({v[5], v[6], v[7]});
    s.angular_velocity.push_back({v[8], v[9], v[10]});
    expected = (expected + 1) % particle_count;
  }
  if (expected != 0) {
    throw YadeOutputError(fmt::format("{}: the last snapshot has {} of {} particles", file, expected,
                                      particle_count));
  }
  return snapshots;
}

}  // namespace reference::yade
