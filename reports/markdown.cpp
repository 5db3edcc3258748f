// SPDX-License-Identifier: MIT
#include "reports/markdown.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace reports {

MarkdownTable::MarkdownTable(std::vector<std::string> header) : header_(std::move(header)) {}

void MarkdownTable::add_row(std::vector<std::string> cells) {
  if (cells.size() > header_.size()) throw std::invalid_argument("table row has too many cells");
  cells.resize(header_.size());
  rows_.push_back(std::move(cells));
}

std::string MarkdownTable::render() const {
  std::string out = "|";
  for (const auto& h : header_) out += " " + cell_text(h) + " |";
  out += "\n|";
  for (std::size_t i = 0; i < header_.size(); ++i) out += "---|";
  out += "\n";
  for (const auto& row : rows_) {
    out += "|";
    for (const auto& c : row) out += " " + cell_text(c) + " |";
    out += "\n";
  }
  return out;
}

std::string inert_text(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) {
      out += ' ';
    } else if (c == '&') {
      out += "&amp;";
    } else if (c == '<') {
      out += "&lt;";
    } else if (c == '>') {
      out += "&gt;";
    } else if (std::string_view("\\`*[]!#|").find(c) != std::string_view::npos) {
      out += '\\';
      out += c;
    } else {
      out += c;
    }
  }
  return out;
}

std::string format_number(std::optional<double> v) {
  if (!v || !std::isfinite(*v)) return "—";
  return fmt::format("{:.6g}", *v);
}

std::string format_ratio(std::optional<double> v) {
  if (!v || !std::isfinite(*v)) return "—";
  return fmt::format("{:.2e}", *v);
}

std::string status_cell(comparison::Status status) {
  switch (status) {
    case comparison::Status::pass: return "✅ pass";
    case comparison::Status::fail: return "❌ fail";
    case comparison::Status::error: return "💥 error";
    case comparison::Status::missing: return "❔ missing";
    case comparison::Status::not_applicable: return "➖ n/a";
  }
  return "error";
}

std::string cell_text(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') {
      out += "\\|";
    } else if (c == '\n' || c == '\r') {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace reports
