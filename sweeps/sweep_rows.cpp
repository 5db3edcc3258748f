// SPDX-License-Identifier: MIT
#include "sweeps/sweep_rows.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace sweeps {
namespace {

/// A CSV field: quoted when it holds a comma, quote or line break (line breaks become spaces).
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (const char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return out + "\"";
}

}  // namespace

std::vector<SweepRow> error_rows(std::size_t point, std::uint64_t seed, const std::vector<std::string>& engines,
                                 std::size_t metrics, const std::string& reason) {
  std::vector<SweepRow> rows;
  for (const auto& e : engines) {
    rows.push_back({point, seed, e, "error", std::vector<std::optional<double>>(metrics), reason, {}});
  }
  return rows;
}

std::string sweep_csv(const SweepSpec& spec, const std::vector<SweepPoint>& points,
                      const std::vector<std::string>& metrics, const std::vector<SweepRow>& rows) {
  std::string out = "point";
  for (const auto& a : spec.axes) out += "," + csv_field(a.key);
  out += ",seed,engine,status";
  for (const auto& m : metrics) out += "," + m;
  out += ",reason\n";
  for (const SweepRow& r : rows) {
    out += fmt::format("{}", r.point);
    for (const double v : points.at(r.point).values) out += fmt::format(",{:.17g}", v);
    out += fmt::format(",{},{},{}", r.seed, r.engine, r.status);
    for (std::size_t m = 0; m < metrics.size(); ++m) {
      const bool has = m < r.values.size() && r.values[m].has_value();
      out += has ? fmt::format(",{:.17g}", *r.values[m]) : std::string(",");
    }
    out += "," + csv_field(r.reason) + "\n";
  }
  return out;
}

std::string bed_csv(const SweepSpec& spec, const std::vector<SweepPoint>& points, const std::vector<SweepRow>& rows) {
  const bool any = std::any_of(rows.begin(), rows.end(), [](const SweepRow& r) { return !r.bed.empty(); });
  if (!any) return {};
  std::string out = "point";
  for (const auto& a : spec.axes) out += "," + csv_field(a.key);
  out += ",seed,engine,time,orf,dose_remaining\n";
  for (const SweepRow& r : rows) {
    std::string lead = fmt::format("{}", r.point);
    for (const double v : points.at(r.point).values) lead += fmt::format(",{:.17g}", v);
    lead += fmt::format(",{},{}", r.seed, r.engine);
    for (const comparison::PackingSample& b : r.bed) {
      out += lead + fmt::format(",{:.17g},{:.17g},{:.17g}\n", b.time, b.orf, b.dose_remaining);
    }
  }
  return out;
}

MeanCurve mean_bed_curve(const std::vector<SweepRow>& rows, std::size_t point, const std::string& engine, bool dose) {
  std::vector<const SweepRow*> runs;
  std::size_t longest = 0;
  for (const SweepRow& r : rows) {
    if (r.point != point || r.engine != engine || r.bed.empty()) continue;
    runs.push_back(&r);
    longest = std::max(longest, r.bed.size());
  }
  MeanCurve curve;
  std::vector<double> times;
  std::vector<double> values;
  for (std::size_t k = 0; k < longest; ++k) {
    times.clear();
    values.clear();
    for (const SweepRow* r : runs) {
      if (k >= r->bed.size()) continue;
      times.push_back(r->bed[k].time);
      values.push_back(dose ? r->bed[k].dose_remaining : r->bed[k].orf);
    }
    curve.time.push_back(seed_statistics(times).mean);
    curve.value.push_back(seed_statistics(values));
  }
  return curve;
}

std::string encode_runs(const std::vector<SweepRun>& runs) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& run : runs) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& r : run.rows) {
      nlohmann::json values = nlohmann::json::array();
      for (const auto& v : r.values) values.push_back(v ? nlohmann::json(*v) : nlohmann::json());
      nlohmann::json bed = nlohmann::json::array();
      for (const auto& b : r.bed) bed.push_back({b.time, b.orf, b.dose_remaining});
      rows.push_back({{"point", r.point}, {"seed", r.seed}, {"engine", r.engine}, {"status", r.status},
                      {"values", values}, {"reason", r.reason}, {"bed", bed}});
    }
    out.push_back({{"job", run.job}, {"seconds", run.seconds}, {"rows", rows}});
  }
  return out.dump();
}

std::vector<SweepRun> decode_runs(const std::string& text) {
  std::vector<SweepRun> runs;
  try {
    for (const auto& j : nlohmann::json::parse(text)) {
      SweepRun run{j.at("job").get<std::size_t>(), {}, j.at("seconds").get<double>()};
      for (const auto& r : j.at("rows")) {
        SweepRow row{r.at("point").get<std::size_t>(), r.at("seed").get<std::uint64_t>(),
                     r.at("engine").get<std::string>(), r.at("status").get<std::string>(), {},
                     r.at("reason").get<std::string>(), {}};
        for (const auto& v : r.at("values")) {
          row.values.push_back(v.is_null() ? std::nullopt : std::optional<double>(v.get<double>()));
        }
        for (const auto& b : r.at("bed")) {
          row.bed.push_back({b.at(0).get<double>(), b.at(1).get<double>(), b.at(2).get<double>()});
        }
        run.rows.push_back(std::move(row));
      }
      runs.push_back(std::move(run));
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(std::string("sweep results from another rank are unreadable: ") + e.what());
  }
  return runs;
}

SeedStatistics point_statistics(const std::vector<SweepRow>& rows, std::size_t point, const std::string& engine,
                                std::size_t metric) {
  std::vector<double> values;
  for (const auto& r : rows) {
    if (r.point == point && r.engine == engine && metric < r.values.size() && r.values[metric]) {
      values.push_back(*r.values[metric]);
    }
  }
  return seed_statistics(values);
}

}  // namespace sweeps
