// SPDX-License-Identifier: MIT
#include "cases/toml_reader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "cases/case_loader.hpp"
#include "cases/excerpt.hpp"
#include "cases/suggestion.hpp"

namespace cases::loader {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Human name of a TOML type, with its article.
std::string_view type_name(toml::node_type type) noexcept {
  switch (type) {
    case toml::node_type::string: return "string";
    case toml::node_type::integer: return "integer";
    case toml::node_type::floating_point: return "floating-point number";
    case toml::node_type::boolean: return "boolean";
    case toml::node_type::date: return "date";
    case toml::node_type::time: return "time";
    case toml::node_type::date_time: return "date-time";
    case toml::node_type::table: return "table";
    case toml::node_type::array: return "array";
    case toml::node_type::none: break;
  }
  return "nothing";
}

/// True when `a` starts before `b` in the file.
bool earlier(const toml::source_position& a, const toml::source_position& b) noexcept {
  return a.line != b.line ? a.line < b.line : a.column < b.column;
}

}  // namespace

std::string located_message(std::string_view file, std::string_view key, std::string_view text,
                            int line, int column) {
  const std::string shown_file = excerpt(file, kMaxEchoedProblem);
  const std::string shown_key = excerpt(key, kMaxEchoedKey);
  const std::string shown_text = excerpt(text, kMaxEchoedProblem);
  if (line <= 0) return fmt::format("{}: {}: {}", shown_file, shown_key, shown_text);
  return fmt::format("{}:{}:{}: {}: {}", shown_file, line, column, shown_key, shown_text);
}

void Diagnostics::fail(const std::string& key, const std::string& problem,
                       const toml::source_region& where) const {
  throw CaseError(file_, key, problem, static_cast<int>(where.begin.line),
                  static_cast<int>(where.begin.column));
}

void Diagnostics::warn(const std::string& key, const std::string& message,
                       const toml::source_region& where) {
  warnings_.push_back(located_message(file_, key, message, static_cast<int>(where.begin.line),
                                      static_cast<int>(where.begin.column)));
}

dem::ValueRange positive_range() noexcept { return {0.0, kInf, true, true}; }

dem::ValueRange non_negative_range() noexcept { return {0.0, kInf, false, true}; }

std::string requirement(const dem::ValueRange& range) {
  if (std::isinf(range.max) && range.max > 0) {
    return fmt::format("{} {}", range.min_open ? ">" : ">=", range.min);
  }
  return "in " + range.describe();
}

std::string describe(const toml::node& node) {
  if (node.is_table() || node.is_array()) return std::string(type_name(node.type()));
  if (const auto* s = node.as_string()) return fmt::format("string \"{}\"", excerpt(s->get()));
  std::ostringstream os;
  node.visit([&os](const auto& v) { os << v; });
  return fmt::format("{} {}", type_name(node.type()), os.str());
}

void Value::fail(const std::string& problem) const { diag_->fail(key_, problem, where()); }

void Value::warn(const std::string& message) const { diag_->warn(key_, message, where()); }

double Value::number() const {
  if (const auto* i = node_->as_integer()) return static_cast<double>(i->get());
  const auto* f = node_->as_floating_point();
  if (f == nullptr) fail("expected a number, got " + describe(*node_));
  const double v = f->get();
  if (!std::isfinite(v)) fail(fmt::format("must be finite, got {}", v));
  return v;
}

double Value::number(const dem::ValueRange& range) const {
  const double v = number();
  if (!range.contains(v)) fail(fmt::format("must be {}, got {}", requirement(range), v));
  return v;
}

std::int64_t Value::integer(std::int64_t min, std::int64_t max) const {
  std::int64_t v = 0;
  if (const auto* i = node_->as_integer()) {
    v = i->get();
  } else if (node_->is_floating_point()) {
    const double d = number();
    constexpr double kLimit = 9.0e18;  // well inside the int64 range
    if (d != std::floor(d) || std::fabs(d) > kLimit) {
      fail(fmt::format("must be an integer, got {}", d));
    }
    v = static_cast<std::int64_t>(d);
  } else {
    fail("expected an integer, got " + describe(*node_));
  }
  if (v < min) fail(fmt::format("must be >= {}, got {}", min, v));
  if (v > max) fail(fmt::format("must be <= {}, got {}", max, v));
  return v;
}

std::size_t Value::index(std::size_t count, std::string_view items) const {
  const auto v = static_cast<std::size_t>(integer(0, std::numeric_limits<std::int64_t>::max()));
  if (v >= count) {
    fail(fmt::format("index {} is out of range: the case has {} {} (indices 0 to {})", v, count,
                     items, count == 0 ? 0 : count - 1));
  }
  return v;
}

std::string Value::string() const {
  const auto* s = node_->as_string();
  if (s == nullptr) fail("expected a string, got " + describe(*node_));
  return s->get();
}

std::string Value::keyword(std::span<const std::string_view> known, std::string_view what) const {
  std::string word = string();
  if (std::find(known.begin(), known.end(), word) == known.end()) {
    fail(fmt::format("unknown {} '{}'{} (known: {})", what, excerpt(word), did_you_mean(word, known),
                     join(known)));
  }
  return word;
}

bool Value::boolean() const {
  const auto* b = node_->as_boolean();
  if (b == nullptr) fail("expected a boolean (true or false), got " + describe(*node_));
  return b->get();
}

Vector3 Value::vector3() const {
  const std::vector<Value> items = elements();
  if (items.size() != 3) {
    fail(fmt::format("expected an array of 3 numbers, got {} element{}", items.size(),
                     items.size() == 1 ? "" : "s"));
  }
  return {items[0].number(), items[1].number(), items[2].number()};
}

ParticlePair Value::particle_pair(std::size_t count) const {
  const std::vector<Value> items = elements();
  if (items.size() != 2) {
    fail(fmt::format("expected an array of 2 particle indices, got {} element{}", items.size(),
                     items.size() == 1 ? "" : "s"));
  }
  const ParticlePair pair{items[0].index(count, "particles"), items[1].index(count, "particles")};
  if (pair.first == pair.second) {
    fail(fmt::format("must name two different particles, got [{}, {}]", pair.first, pair.second));
  }
  return pair;
}

std::vector<Value> Value::elements() const {
  const auto* array = node_->as_array();
  if (array == nullptr) fail("expected an array, got " + describe(*node_));
  std::vector<Value> out;
  out.reserve(array->size());
  for (std::size_t i = 0; i < array->size(); ++i) {
    out.emplace_back((*array)[i], fmt::format("{}[{}]", key_, i), *diag_);
  }
  return out;
}

Table Value::table() const {
  const auto* t = node_->as_table();
  if (t == nullptr) fail("expected a table, got " + describe(*node_));
  return Table(*t, key_, *diag_);
}

std::string Table::key_of(std::string_view name) const {
  return key_.empty() ? std::string(name) : key_ + "." + std::string(name);
}

bool Table::has(std::string_view name) const { return table_->contains(name); }

std::optional<Value> Table::find(std::string_view name) const {
  const toml::node* node = table_->get(name);
  if (node == nullptr) return std::nullopt;
  return Value(*node, key_of(name), *diag_);
}

Value Table::require(std::string_view name, std::string_view what) const {
  auto value = find(name);
  if (!value) diag_->fail(key_of(name), fmt::format("missing required {}", what), where());
  return *value;
}

Table Table::table_or(std::string_view name, const toml::table& empty) const {
  if (const auto value = find(name)) return value->table();
  return Table(empty, key_of(name), *diag_);
}

std::vector<std::pair<std::string, Value>> Table::entries() const {
  std::vector<std::pair<const toml::key*, const toml::node*>> raw;
  for (const auto& [k, v] : *table_) raw.emplace_back(&k, &v);
  std::stable_sort(raw.begin(), raw.end(), [](const auto& a, const auto& b) {
    return earlier(a.first->source().begin, b.first->source().begin);
  });
  std::vector<std::pair<std::string, Value>> out;
  out.reserve(raw.size());
  for (const auto& [k, v] : raw) {
    out.emplace_back(std::string(k->str()), Value(*v, key_of(k->str()), *diag_));
  }
  return out;
}

void Table::allow_only(std::span<const std::string_view> known) const {
  const toml::key* first = nullptr;
  for (const auto& [k, v] : *table_) {
    const bool is_known = std::find(known.begin(), known.end(), k.str()) != known.end();
    if (!is_known && (first == nullptr || earlier(k.source().begin, first->source().begin))) {
      first = &k;
    }
  }
  if (first == nullptr) return;
  const std::string suggestion = did_you_mean(first->str(), known);
  const std::string problem =
      suggestion.empty() ? fmt::format("unknown key '{}' (known: {})", excerpt(first->str()), join(known))
                         : fmt::format("unknown key '{}'{}", excerpt(first->str()), suggestion);
  diag_->fail(key_of(first->str()), problem, first->source());
}

void Table::fail(std::string_view name, const std::string& problem) const {
  const toml::node* node = table_->get(name);
  diag_->fail(key_of(name), problem, node != nullptr ? node->source() : where());
}

void Table::fail(const std::string& problem) const { diag_->fail(key_, problem, where()); }

void Table::warn(std::string_view name, const std::string& message) const {
  const toml::node* node = table_->get(name);
  diag_->warn(key_of(name), message, node != nullptr ? node->source() : where());
}

}  // namespace cases::loader
