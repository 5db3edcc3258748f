// SPDX-License-Identifier: MIT
#include "sweeps/sweep_spec.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "cases/case_file.hpp"
#include "cases/case_loader.hpp"
#include "cases/catalogue.hpp"
#include "cases/toml_reader.hpp"

namespace sweeps {
namespace {

using cases::loader::Table;
using cases::loader::Value;

constexpr auto kTopKeys = std::to_array<std::string_view>({"sweep", "parameters", "beverloo"});
constexpr auto kBeverlooKeys = std::to_array<std::string_view>(
    {"orifice", "orifice_scale", "grain_diameter", "grain_density", "flow_rate", "packing_fraction", "gravity"});
constexpr auto kSweepKeys =
    std::to_array<std::string_view>({"name", "description", "case", "seeds", "engines", "metrics", "timeout", "set"});
constexpr auto kAxisKeys = std::to_array<std::string_view>({"key", "label", "values", "scale", "with"});
constexpr auto kLinkedKeys = std::to_array<std::string_view>({"key", "values"});
constexpr std::array<std::string_view, 2> kScales{"linear", "log"};

/// The keys of a sweep axis must name a value of the case file, not a table or a label.
void check_axis_key(const Value& v, const std::string& key) {
  static constexpr std::string_view kAllowed = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.[]-";
  if (key.empty() || key.find_first_not_of(kAllowed) != std::string::npos || key.front() == '.' ||
      key.back() == '.' || key.find("..") != std::string::npos) {
    v.fail(fmt::format("'{}' is not a dotted case-file key such as \"materials.NAME.cohesive_stiffness\" or "
                       "\"stages[0].pull\"",
                       key));
  }
}

/// [beverloo]: the orifice axis, the grains, and the metrics the fit reads.
BeverlooSpec read_beverloo(const Table& t, const SweepSpec& spec) {
  t.allow_only(kBeverlooKeys);
  BeverlooSpec b;
  const Value orifice = t.require("orifice");
  const std::string key = orifice.string();
  const auto axis = std::find_if(spec.axes.begin(), spec.axes.end(), [&](const SweepAxis& a) { return a.key == key; });
  if (axis == spec.axes.end()) orifice.fail(fmt::format("'{}' is not one of the sweep's parameters", key));
  b.axis = static_cast<std::size_t>(axis - spec.axes.begin());
  if (axis->values.size() < 2) orifice.fail("the orifice axis needs at least two values to fit C and k");
  const dem::ValueRange positive{0.0, std::numeric_limits<double>::infinity(), true, true};
  if (const auto v = t.find("orifice_scale")) b.orifice_scale = v->number(positive);
  b.grain_diameter = t.require("grain_diameter").number(positive);
  b.grain_density = t.require("grain_density").number(positive);
  if (const auto v = t.find("gravity")) b.gravity = v->number(positive);
  const auto metric = [&](const char* name, std::string& out) {
    const auto v = t.find(name);
    if (v) out = v->string();
    if (!spec.metrics.empty() && std::find(spec.metrics.begin(), spec.metrics.end(), out) == spec.metrics.end()) {
      if (v) v->fail(fmt::format("'{}' is not among sweep.metrics", out));
      t.fail(name, fmt::format("the default '{}' is not among sweep.metrics; list it or name the metric", out));
    }
  };
  metric("flow_rate", b.flow_rate);
  metric("packing_fraction", b.packing_fraction);
  return b;
}

}  // namespace

SweepSpec load_sweep(const std::filesystem::path& file) {
  // Untrusted like a case file: a regular file of bounded size (cases/case_file.hpp).
  return load_sweep_text(cases::read_case_file(file), file);
}

SweepSpec load_sweep_text(const std::string& text, const std::filesystem::path& path) {
  toml::table document;
  try {
    document = toml::parse(text, std::string_view(path.string()));
  } catch (const toml::parse_error& e) {
    throw cases::CaseError(path.string(), "(syntax)", std::string(e.description()),
                           static_cast<int>(e.source().begin.line), static_cast<int>(e.source().begin.column));
  }
  cases::loader::Diagnostics diag(path.string());
  const Table root(document, "", diag);
  root.allow_only(kTopKeys);
  SweepSpec spec;
  spec.source_path = path;
  spec.source_text = text;
  const Table sweep = root.require("sweep", "table [sweep]").table();
  sweep.allow_only(kSweepKeys);
  spec.name = sweep.require("name").string();
  if (const auto v = sweep.find("description")) spec.description = v->string();
  const Value case_value = sweep.require("case");
  spec.case_file = path.parent_path() / case_value.string();
  if (!std::filesystem::is_regular_file(spec.case_file)) {
    case_value.fail(fmt::format("no case file {} (paths are relative to the sweep file)", spec.case_file.string()));
  }
  for (const Value& s : sweep.require("seeds").elements()) {
    const auto seed = static_cast<std::uint64_t>(s.integer(0, std::numeric_limits<std::int64_t>::max()));
    if (std::find(spec.seeds.begin(), spec.seeds.end(), seed) != spec.seeds.end()) {
      s.fail(fmt::format("seed {} is listed twice", seed));
    }
    spec.seeds.push_back(seed);
  }
  if (spec.seeds.empty()) sweep.fail("seeds", "must list at least one seed");
  if (const auto v = sweep.find("engines")) {
    for (const Value& e : v->elements()) {
      const std::string name = e.string();
      if (!cases::is_known_engine(name)) e.fail(fmt::format("unknown engine '{}'", name));
      spec.engines.push_back(name);
    }
  }
  if (const auto v = sweep.find("timeout")) {
    spec.timeout_s = v->number(dem::ValueRange{0.0, 1e7, true, false});
  }
  if (const auto v = sweep.find("metrics")) {
    for (const Value& m : v->elements()) {
      const std::string name = m.string();
      if (!cases::is_known_metric(name)) m.fail(fmt::format("unknown metric '{}'", name));
      spec.metrics.push_back(name);
    }
  }
  std::set<std::string> taken;  // every key a setting, an axis or a linked key sets
  if (const auto v = sweep.find("set")) {
    for (const auto& [key, value] : v->table().entries()) {
      check_axis_key(value, key);
      if (key.starts_with("populations") && key.ends_with(".seed")) {
        value.fail("a population's seed is the sweep's: list it in sweep.seeds");
      }
      taken.insert(key);
      const toml::node& node = value.node();
      if (node.is_string()) {
        spec.fixed.push_back({key, value.string()});
      } else if (node.is_boolean()) {
        spec.fixed.push_back({key, value.boolean()});
      } else if (node.is_number()) {
        spec.fixed.push_back({key, value.number()});
      } else {
        value.fail("a setting is a string, a number or a boolean; quote a dotted key: set = { \"model.mindlin_form\" = "
                   "\"total\" }");
      }
    }
  }
  const Value parameters = root.require("parameters", "array of tables [[parameters]]");
  for (const Value& entry : parameters.elements()) {
    const Table t = entry.table();
    t.allow_only(kAxisKeys);
    SweepAxis axis;
    const Value key = t.require("key");
    axis.key = key.string();
    check_axis_key(key, axis.key);
    if (!taken.insert(axis.key).second) {
      key.fail(fmt::format("'{}' is set twice in the sweep (by sweep.set, an axis or a linked key)", axis.key));
    }
    axis.label = t.has("label") ? t.require("label").string() : axis.key.substr(axis.key.find_last_of('.') + 1);
    for (const Value& x : t.require("values").elements()) axis.values.push_back(x.number());
    if (axis.values.empty()) t.fail("values", "must list at least one value");
    if (const auto v = t.find("scale")) axis.log_scale = v->keyword(kScales, "scale") == "log";
    if (axis.log_scale) {
      for (const double x : axis.values) {
        if (!(x > 0.0)) t.fail("values", fmt::format("a log-scale axis needs values > 0, got {}", x));
      }
    }
    if (const auto with = t.find("with")) {
      for (const Value& item : with->elements()) {
        const Table w = item.table();
        w.allow_only(kLinkedKeys);
        LinkedKey linked;
        const Value linked_key = w.require("key");
        linked.key = linked_key.string();
        check_axis_key(linked_key, linked.key);
        if (!taken.insert(linked.key).second) {
          t.fail("with", fmt::format("'{}' is set twice in the sweep", linked.key));
        }
        for (const Value& x : w.require("values").elements()) linked.values.push_back(x.number());
        if (linked.values.size() != axis.values.size()) {
          w.fail("values", fmt::format("must list one value per value of '{}' ({}), got {}", axis.key,
                                       axis.values.size(), linked.values.size()));
        }
        axis.linked.push_back(std::move(linked));
      }
    }
    spec.axes.push_back(axis);
  }
  if (spec.axes.empty()) parameters.fail("must list at least one parameter");
  if (const auto v = root.find("beverloo")) spec.beverloo = read_beverloo(v->table(), spec);
  std::size_t points = 1;
  for (const SweepAxis& a : spec.axes) points *= a.values.size();
  if (points * spec.seeds.size() > 1000000) {
    parameters.fail(fmt::format("{} points × {} seeds is more than a million runs", points, spec.seeds.size()));
  }
  return spec;
}

std::vector<SweepPoint> expand(const SweepSpec& spec) {
  std::size_t total = 1;
  for (const SweepAxis& a : spec.axes) total *= a.values.size();
  std::vector<SweepPoint> out;
  out.reserve(total);
  for (std::size_t k = 0; k < total; ++k) {
    SweepPoint p{k, std::vector<double>(spec.axes.size()), std::vector<std::size_t>(spec.axes.size())};
    std::size_t rest = k;
    for (std::size_t a = spec.axes.size(); a-- > 0;) {
      const std::size_t n = spec.axes[a].values.size();
      p.positions[a] = rest % n;
      p.values[a] = spec.axes[a].values[rest % n];
      rest /= n;
    }
    out.push_back(p);
  }
  return out;
}

std::vector<std::pair<std::string, double>> point_overrides(const SweepSpec& spec, const SweepPoint& point) {
  std::vector<std::pair<std::string, double>> out;
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    out.emplace_back(spec.axes[a].key, point.values[a]);
    for (const LinkedKey& l : spec.axes[a].linked) out.emplace_back(l.key, l.values.at(point.positions.at(a)));
  }
  return out;
}

}  // namespace sweeps
