// SPDX-License-Identifier: MIT
#include "results/suite_results.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "compare/discrepancy.hpp"

namespace results {
namespace {

using Json = nlohmann::ordered_json;

/// `v` when it is a finite number, else empty (results.json writes null for "no value").
std::optional<double> finite(std::optional<double> v) {
  if (v && std::isfinite(*v)) return v;
  return std::nullopt;
}

/// Reads the parts of results.json the gate needs, naming the file and the key on a bad field.
class Reader {
 public:
  explicit Reader(std::string where) : where_(std::move(where)) {}

  [[nodiscard]] std::string text(const Json& object, const char* key, const std::string& path,
                                 std::optional<std::string> otherwise = std::nullopt) const {
    if (!object.contains(key)) {
      if (otherwise) return *otherwise;
      fail(path + "." + key, "is missing");
    }
    if (!object[key].is_string()) fail(path + "." + key, "is not a string");
    return object[key].get<std::string>();
  }

  [[nodiscard]] std::optional<double> number(const Json& object, const char* key, const std::string& path) const {
    if (!object.contains(key) || object[key].is_null()) return std::nullopt;
    if (!object[key].is_number()) fail(path + "." + key, "is neither a number nor null");
    return finite(object[key].get<double>());
  }

  [[nodiscard]] cases::Tolerance tolerance(const Json& t, const std::string& path) const {
    if (!t.is_object()) fail(path, "is not an object");
    return {number(t, "rel", path).value_or(0.0), number(t, "abs", path).value_or(0.0)};
  }

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw std::runtime_error(fmt::format("{}: {} {}", where_, key, what));
  }

 private:
  std::string where_;
};

cases::RunStatus run_status(std::string_view word) {
  for (const auto s : {cases::RunStatus::ok, cases::RunStatus::error, cases::RunStatus::missing,
                       cases::RunStatus::not_applicable}) {
    if (cases::to_string(s) == word) return s;
  }
  return cases::RunStatus::error;
}

comparison::Comparison read_row(const Reader& r, const Json& row, const std::string& path) {
  comparison::Comparison c;
  c.metric = r.text(row, "metric", path);
  c.engine = r.text(row, "engine", path);
  c.reference = r.text(row, "reference", path);
  c.value = r.number(row, "value", path);
  c.reference_value = r.number(row, "reference_value", path);
  c.abs_diff = r.number(row, "abs_diff", path);
  c.rel_diff = r.number(row, "rel_diff", path);
  if (row.contains("tolerance")) c.tolerance = r.tolerance(row["tolerance"], path + ".tolerance");
  const std::string status = r.text(row, "status", path);
  const auto parsed = comparison::parse_status(status);
  if (!parsed) r.fail(path + ".status", fmt::format("'{}' is not a status (pass, fail, error, missing, n/a)", status));
  c.status = *parsed;
  c.note = r.text(row, "note", path, std::string());
  return c;
}

CaseResults read_case(const Reader& r, const Json& c, const std::string& path) {
  if (!c.is_object()) r.fail(path, "is not an object");
  CaseResults out;
  out.name = r.text(c, "case", path, r.text(c, "case_file", path, std::string("?")));
  if (!c.contains("comparisons")) {
    out.failure = fmt::format("{} — {}", r.text(c, "status", path, std::string("error")),
                              r.text(c, "reason", path, std::string("no results")));
    return out;
  }
  if (const auto tier = cases::parse_tier(r.text(c, "tier", path, std::string("fast")))) out.tier = *tier;
  if (!c["comparisons"].is_array()) r.fail(path + ".comparisons", "is not an array");
  for (std::size_t k = 0; k < c["comparisons"].size(); ++k) {
    out.comparisons.push_back(read_row(r, c["comparisons"][k], fmt::format("{}.comparisons[{}]", path, k)));
  }
  if (c.contains("engines")) {
    if (!c["engines"].is_object()) r.fail(path + ".engines", "is not an object");
    for (const auto& [name, e] : c["engines"].items()) {
      const std::string at = path + ".engines." + name;
      EngineResults engine;
      engine.name = name;
      engine.status = run_status(r.text(e, "status", at, std::string("error")));
      engine.source = r.text(e, "source", at, std::string("run"));
      if (e.contains("metrics")) {
        if (!e["metrics"].is_object()) r.fail(at + ".metrics", "is not an object");
        for (const auto& [metric, value] : e["metrics"].items()) {
          engine.metrics.emplace_back(metric, value.is_number() ? finite(value.get<double>()) : std::nullopt);
        }
      }
      out.engines.push_back(std::move(engine));
    }
  }
  if (c.contains("tolerances")) {
    if (!c["tolerances"].is_object()) r.fail(path + ".tolerances", "is not an object");
    for (const auto& [metric, t] : c["tolerances"].items()) {
      out.tolerances.emplace_back(metric, r.tolerance(t, path + ".tolerances." + metric));
    }
  }
  return out;
}

}  // namespace

CaseResults case_results(const comparison::CaseOutcome& outcome) {
  CaseResults out;
  out.name = outcome.scene.name;
  out.tier = outcome.scene.tier;
  out.comparisons = outcome.comparisons;
  for (auto& c : out.comparisons) {
    c.value = finite(c.value);
    c.reference_value = finite(c.reference_value);
  }
  for (const auto& run : outcome.runs) {
    EngineResults e;
    e.name = run.engine;
    e.status = run.status;
    e.source = run.source;
    if (const auto m = outcome.metrics.find(run.engine); m != outcome.metrics.end()) {
      for (const auto& [metric, value] : m->second) e.metrics.emplace_back(metric, finite(value.value));
    }
    out.engines.push_back(std::move(e));
  }
  for (const auto& metric : outcome.scene.compare.metrics) {
    out.tolerances.emplace_back(metric, comparison::tolerance_for(outcome.scene, metric));
  }
  return out;
}

CaseResults failed_case(std::string file, std::string reason) {
  CaseResults out;
  out.name = std::move(file);
  out.failure = "error — " + reason;
  return out;
}

SuiteResults read_suite_results(const nlohmann::ordered_json& document, const std::string& where) {
  const Reader r(where);
  if (!document.is_object()) r.fail("the document", "is not a JSON object");
  SuiteResults out;
  out.suite = r.text(document, "suite", "", std::string());
  const std::string tier = r.text(document, "tier", "", std::string("full"));
  out.tier = cases::parse_tier(tier).value_or(cases::Tier::full);
  if (document.contains("cases")) {
    if (!document["cases"].is_array()) r.fail("cases", "is not an array");
    for (std::size_t k = 0; k < document["cases"].size(); ++k) {
      out.cases.push_back(read_case(r, document["cases"][k], fmt::format("cases[{}]", k)));
    }
  } else {
    out.cases.push_back(read_case(r, document, "(case)"));
  }
  if (document.contains("ensembles")) {
    if (!document["ensembles"].is_array()) r.fail("ensembles", "is not an array");
    for (std::size_t k = 0; k < document["ensembles"].size(); ++k) {
      const Json& e = document["ensembles"][k];
      const std::string path = fmt::format("ensembles[{}]", k);
      if (!e.is_object()) r.fail(path, "is not an object");
      EnsembleResults ensemble;
      ensemble.sweep = r.text(e, "sweep", path, std::string("?"));
      ensemble.current = e.contains("current") && e["current"].is_boolean() && e["current"].get<bool>();
      ensemble.problem = r.text(e, "problem", path, std::string());
      out.ensembles.push_back(std::move(ensemble));
    }
  }
  return out;
}

}  // namespace results
