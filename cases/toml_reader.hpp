// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "cases/scene.hpp"
#include "dem/materials/material_properties.hpp"

// Typed, position-aware reading of a parsed case file. Every value carries the full dotted key
// that names it ("particles[1].radius"), so each error and warning says exactly where to look.
namespace cases::loader {

/// "FILE:LINE:COL: KEY: text", or "FILE: KEY: text" when the line is unknown (0).
std::string located_message(std::string_view file, std::string_view key, std::string_view text,
                            int line, int column);

/// The case file's name and the warnings gathered while reading it.
class Diagnostics {
 public:
  /// Diagnostics for the case file named `file` in messages.
  explicit Diagnostics(std::string file) : file_(std::move(file)) {}
  /// Name of the case file in messages.
  [[nodiscard]] const std::string& file() const noexcept { return file_; }
  /// Throws CaseError about `key` at `where` (the position is left out when unknown).
  [[noreturn]] void fail(const std::string& key, const std::string& problem,
                         const toml::source_region& where) const;
  /// Records a non-fatal finding about `key` at `where`.
  void warn(const std::string& key, const std::string& message, const toml::source_region& where);
  /// The warnings recorded so far, in the order they were found.
  [[nodiscard]] const std::vector<std::string>& warnings() const noexcept { return warnings_; }

 private:
  std::string file_;
  std::vector<std::string> warnings_;
};

/// The interval (0, ∞).
dem::ValueRange positive_range() noexcept;
/// The interval [0, ∞).
dem::ValueRange non_negative_range() noexcept;
/// How a message states a range: "> 0", ">= 0" or "in (0, 0.001]".
std::string requirement(const dem::ValueRange& range);
/// Short description of a TOML value for messages: `string "fast"`, `integer 3`, `table`.
std::string describe(const toml::node& node);

class Table;

/// One value of the case file together with the full dotted key that names it.
class Value {
 public:
  /// The value `node`, named `key` in messages.
  Value(const toml::node& node, std::string key, Diagnostics& diag)
      : node_(&node), key_(std::move(key)), diag_(&diag) {}
  /// Full dotted key, e.g. "particles[1].radius".
  [[nodiscard]] const std::string& key() const noexcept { return key_; }
  /// Where the value starts in the file.
  [[nodiscard]] const toml::source_region& where() const noexcept { return node_->source(); }
  /// The underlying TOML node.
  [[nodiscard]] const toml::node& node() const noexcept { return *node_; }
  /// Throws CaseError about this value.
  [[noreturn]] void fail(const std::string& problem) const;
  /// Records a warning about this value.
  void warn(const std::string& message) const;

  /// A finite number; TOML integers are accepted.
  [[nodiscard]] double number() const;
  /// A finite number inside `range`.
  [[nodiscard]] double number(const dem::ValueRange& range) const;
  /// An integer in [min, max]; a floating-point value is accepted only when integral.
  [[nodiscard]] std::int64_t integer(std::int64_t min, std::int64_t max) const;
  /// An index into a list of `count` items called `items` in messages ("particles").
  [[nodiscard]] std::size_t index(std::size_t count, std::string_view items) const;
  /// A string.
  [[nodiscard]] std::string string() const;
  /// A string that must be one of `known`; `what` names the kind ("scheme") in messages.
  [[nodiscard]] std::string keyword(std::span<const std::string_view> known,
                                    std::string_view what) const;
  /// A boolean.
  [[nodiscard]] bool boolean() const;
  /// An array of exactly three finite numbers.
  [[nodiscard]] Vector3 vector3() const;
  /// Two different particle indices, each below `count`.
  [[nodiscard]] ParticlePair particle_pair(std::size_t count) const;
  /// The elements of an array, each named "key[i]".
  [[nodiscard]] std::vector<Value> elements() const;
  /// A table.
  [[nodiscard]] Table table() const;

 private:
  const toml::node* node_;
  std::string key_;
  Diagnostics* diag_;
};

/// One table of the case file together with its dotted key ("" for the whole file).
class Table {
 public:
  /// The table `table`, named `key` in messages.
  Table(const toml::table& table, std::string key, Diagnostics& diag)
      : table_(&table), key_(std::move(key)), diag_(&diag) {}
  /// Dotted key of the table itself.
  [[nodiscard]] const std::string& key() const noexcept { return key_; }
  /// Dotted key of the entry `name` of this table.
  [[nodiscard]] std::string key_of(std::string_view name) const;
  /// Where the table starts in the file.
  [[nodiscard]] const toml::source_region& where() const noexcept { return table_->source(); }
  /// True when the table has an entry `name`.
  [[nodiscard]] bool has(std::string_view name) const;
  /// The entry `name`, or empty.
  [[nodiscard]] std::optional<Value> find(std::string_view name) const;
  /// The entry `name`; throws "missing required <what>" at the table when absent.
  [[nodiscard]] Value require(std::string_view name, std::string_view what = "key") const;
  /// The entry `name` as a table, or `empty` (named as the entry would be) when absent.
  [[nodiscard]] Table table_or(std::string_view name, const toml::table& empty) const;
  /// Every entry in file order, with its key.
  [[nodiscard]] std::vector<std::pair<std::string, Value>> entries() const;
  /// Throws on the first (in file order) key not in `known`, suggesting the closest one.
  void allow_only(std::span<const std::string_view> known) const;
  /// Throws CaseError about the entry `name`, at the entry when present, else at the table.
  [[noreturn]] void fail(std::string_view name, const std::string& problem) const;
  /// Throws CaseError about the table itself.
  [[noreturn]] void fail(const std::string& problem) const;
  /// Records a warning about the entry `name`, at the entry when present, else at the table.
  void warn(std::string_view name, const std::string& message) const;

 private:
  const toml::table* table_;
  std::string key_;
  Diagnostics* diag_;
};

}  // namespace cases::loader
