// SPDX-License-Identifier: MIT
#include "store/run_result_json.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "store/packed_column.hpp"

namespace store {
namespace {

using Json = nlohmann::ordered_json;

cases::RunStatus parse_status(const std::string& s) {
  for (const auto st : {cases::RunStatus::ok, cases::RunStatus::error, cases::RunStatus::missing,
                        cases::RunStatus::not_applicable}) {
    if (cases::to_string(st) == s) return st;
  }
  throw std::runtime_error("unknown run status '" + s + "'");
}

/// Names what packed traces are, so that a reader meets a format it knows or a clear refusal.
constexpr const char* kPackedEncoding = "demwb-packed-1";

/// Marks a column stored as a copy of an earlier one: "=" + that column's name. Packed text is
/// canonical Base64, which never starts with "=", so the two cannot be confused.
constexpr char kSameAs = '=';

/// A trace in packed form (docs/results-format.md, "Packed traces"): the row count and, per
/// column in order, its pack_column text, or "=<name>" when an earlier column holds the same
/// values bit for bit (a two-body trace's contact force is often its sphere's force).
Json trace_json(const cases::Trace& t) {
  Json columns = Json::object();
  std::vector<std::pair<std::string, std::string>> packed;  // (text, name) of the columns so far
  for (std::size_t c = 0; c < t.columns().size(); ++c) {
    std::string text = pack_column(t.values(c));
    std::string stored = text;
    for (const auto& [earlier_text, earlier_name] : packed) {
      // Equal packed texts are equal bit patterns (the packing is lossless and deterministic).
      if (earlier_text == text) {
        stored = std::string(1, kSameAs) + earlier_name;
        break;
      }
    }
    if (stored.front() != kSameAs) packed.emplace_back(text, t.columns()[c]);
    columns[t.columns()[c]] = std::move(stored);
  }
  return Json{{"encoding", kPackedEncoding}, {"rows", t.rows()}, {"columns", std::move(columns)}};
}

/// A trace from its packed form, or from the plain form older files hold (column name →
/// array of numbers).
cases::Trace trace_from(const Json& j) {
  std::vector<std::pair<std::string, std::vector<double>>> columns;
  std::size_t rows = 0;
  if (j.contains("encoding")) {
    const auto encoding = j.at("encoding").get<std::string>();
    if (encoding != kPackedEncoding) {
      throw std::runtime_error("trace encoding '" + encoding + "' is not " + kPackedEncoding);
    }
    rows = j.at("rows").get<std::size_t>();
    for (const auto& [name, text] : j.at("columns").items()) {
      const std::string value = text.get<std::string>();
      if (!value.empty() && value.front() == kSameAs) {
        // A copy of an earlier column that is stored in full (never a chain, never itself).
        const std::string source = value.substr(1);
        const auto found = std::find_if(columns.begin(), columns.end(), [&](const auto& c) { return c.first == source; });
        const Json& source_text = j.at("columns").contains(source) ? j.at("columns").at(source) : Json();
        if (found == columns.end() || !source_text.is_string() || source_text.get<std::string>().starts_with(kSameAs)) {
          throw std::runtime_error("trace column '" + name + "': names '" + source.substr(0, 64) +
                                   "' as its copy, which is not an earlier column stored in full");
        }
        columns.emplace_back(name, found->second);
        continue;
      }
      try {
        columns.emplace_back(name, unpack_column(value, rows));
      } catch (const std::runtime_error& e) {
        throw std::runtime_error("trace column '" + name + "': " + e.what());
      }
    }
  } else {
    for (const auto& [name, values] : j.items()) columns.emplace_back(name, values.get<std::vector<double>>());
    rows = columns.empty() ? 0 : columns.front().second.size();
  }
  cases::Trace t;
  for (const auto& [name, values] : columns) {
    if (values.size() != rows) throw std::runtime_error("trace columns of different lengths");
    t.add_column(name);
  }
  std::vector<double> row(columns.size());
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < columns.size(); ++c) row[c] = columns[c].second[r];
    t.append_row(row);
  }
  return t;
}

}  // namespace

nlohmann::ordered_json run_result_json(const cases::RunResult& run) {
  Json j;
  j["engine"] = run.engine;
  j["status"] = std::string(cases::to_string(run.status));
  j["reason"] = run.reason;
  j["version"] = run.version;
  j["source"] = run.source;
  j["wall_time_s"] = run.wall_time_s;
  j["log_tail"] = run.log_tail;
  if (!run.scratch_dir.empty()) j["scratch_dir"] = run.scratch_dir;
  j["conventions"] = run.conventions;
  j["warnings"] = run.warnings;
  j["exact_metrics"] = run.exact_metrics;
  j["inexpressible_metrics"] = run.inexpressible_metrics;
  Json calibrations = Json::array();
  for (const auto& c : run.calibrations) {
    calibrations.push_back({{"parameter", c.parameter},
                            {"target", c.target},
                            {"chosen", c.chosen},
                            {"samples", c.samples},
                            {"method", c.method}});
  }
  j["calibrations"] = calibrations;
  if (const auto& f = run.refinement) {
    j["refinement"] = {{"timestep", f->timestep}, {"halvings", f->halvings},   {"limit", f->limit},
                       {"limit_reached", f->limit_reached}, {"metrics", f->metrics},
                       {"estimates", f->estimates},         {"problem", f->problem}};
  }
  j["trace"] = trace_json(run.trace);
  j["energy"] = trace_json(run.energy);
  Json snaps = Json::array();
  for (const auto& s : run.snapshots) {
    snaps.push_back({{"time", s.time},
                     {"position", s.position},
                     {"velocity", s.velocity},
                     {"angular_velocity", s.angular_velocity}});
  }
  j["snapshots"] = snaps;
  return j;
}

cases::RunResult run_result_from_json(const nlohmann::ordered_json& j) {
  try {
    cases::RunResult r;
    r.engine = j.at("engine").get<std::string>();
    r.status = parse_status(j.at("status").get<std::string>());
    r.reason = j.at("reason").get<std::string>();
    r.version = j.at("version").get<std::string>();
    r.source = j.value("source", std::string("run"));
    r.wall_time_s = j.at("wall_time_s").get<double>();
    r.log_tail = j.at("log_tail").get<std::string>();
    r.scratch_dir = j.value("scratch_dir", std::string());
    r.conventions = j.at("conventions").get<std::map<std::string, std::string>>();
    r.warnings = j.at("warnings").get<std::vector<std::string>>();
    r.exact_metrics = j.at("exact_metrics").get<std::map<std::string, double>>();
    r.inexpressible_metrics =
        j.value("inexpressible_metrics", std::map<std::string, std::string>{});
    if (j.contains("calibrations")) {
      for (const auto& c : j.at("calibrations")) {
        r.calibrations.push_back({c.at("parameter").get<std::string>(), c.at("target").get<double>(),
                                  c.at("chosen").get<double>(),
                                  c.at("samples").get<std::vector<std::pair<double, double>>>(),
                                  c.at("method").get<std::string>()});
      }
    }
    if (j.contains("refinement")) {
      const auto& f = j.at("refinement");
      cases::TimeStepRefinement t;
      t.timestep = f.at("timestep").get<double>();
      t.halvings = f.at("halvings").get<int>();
      t.limit = f.at("limit").get<int>();
      t.limit_reached = f.at("limit_reached").get<bool>();
      t.metrics = f.at("metrics").get<std::map<std::string, double>>();
      t.estimates = f.at("estimates").get<std::map<std::string, double>>();
      t.problem = f.at("problem").get<std::string>();
      r.refinement = t;
    }
    r.trace = trace_from(j.at("trace"));
    r.energy = trace_from(j.at("energy"));
    for (const auto& s : j.at("snapshots")) {
      r.snapshots.push_back({s.at("time").get<double>(), s.at("position").get<std::vector<cases::Vector3>>(),
                             s.at("velocity").get<std::vector<cases::Vector3>>(),
                             s.at("angular_velocity").get<std::vector<cases::Vector3>>()});
    }
    return r;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("malformed stored run result: ") + e.what());
  }
}

}  // namespace store
