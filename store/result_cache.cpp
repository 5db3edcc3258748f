// SPDX-License-Identifier: MIT
#include "store/result_cache.hpp"

#include <cstdlib>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "store/run_result_json.hpp"
#include "store/scene_json.hpp"
#include "support/sha256.hpp"
#include "support/text_file.hpp"

namespace store {

std::filesystem::path ResultCache::default_dir() {
  if (const char* d = std::getenv("DEMWB_CACHE_DIR"); d != nullptr && *d != '\0') return d;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x != nullptr && *x != '\0') {
    return std::filesystem::path(x) / "demwb";
  }
  if (const char* h = std::getenv("HOME"); h != nullptr && *h != '\0') {
    return std::filesystem::path(h) / ".cache" / "demwb";
  }
  return ".demwb-cache";
}

namespace {

/// Generation of the cache keys, part of every entry's file name: raised whenever the scene
/// fingerprint learns a field that older entries were keyed without (2: the Mindlin form, the
/// unloaded-slider and adhesive-dashpot rules), so that no entry made before can answer for a
/// scene it does not describe.
constexpr std::string_view kKeyGeneration = "2";

}  // namespace

std::filesystem::path ResultCache::path_of(const cases::Scene& scene, std::string_view engine,
                                           const std::string& version) const {
  const std::string name = scene_fingerprint(scene).substr(0, 32) + "-" +
                           support::sha256_hex(version + "\n" + std::string(kKeyGeneration)).substr(0, 12) + ".json";
  return dir_ / std::string(engine) / name;
}

namespace {

/// SHA-256 of `document`'s compact JSON text without its "sha256" member.
std::string content_checksum(nlohmann::ordered_json document) {
  document.erase("sha256");
  return support::sha256_hex(document.dump());
}

}  // namespace

nlohmann::ordered_json with_checksum(nlohmann::ordered_json document) {
  document["sha256"] = content_checksum(document);
  return document;
}

std::string checksum_problem(const nlohmann::ordered_json& document) {
  if (!document.is_object() || !document.contains("sha256") || !document["sha256"].is_string()) {
    return "it has no sha256 member";
  }
  if (document["sha256"].get<std::string>() != content_checksum(document)) {
    return "its content does not match its sha256 (edited or damaged)";
  }
  return "";
}

ResultCache::Lookup ResultCache::find(const cases::Scene& scene, std::string_view engine,
                                      const std::string& version) const {
  const auto file = path_of(scene, engine, version);
  Lookup out;
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return out;
  try {
    const auto j = nlohmann::ordered_json::parse(support::read_file(file));
    if (const std::string problem = checksum_problem(j); !problem.empty()) {
      out.problem = file.string() + ": " + problem;
      return out;
    }
    if (j.at("fingerprint") != scene_fingerprint(scene) || j.at("version") != version || j.at("engine") != engine) {
      out.problem = file.string() + ": stored for another scene, engine or version";
      return out;
    }
    cases::RunResult r = run_result_from_json(j.at("result"));
    if (r.status != cases::RunStatus::ok || r.engine != engine) {
      out.problem = file.string() + ": holds a result that is not a successful run of " + std::string(engine) +
                    " (only those are ever stored)";
      return out;
    }
    r.source = "cache";
    r.conventions["result source"] = "reused from the result cache: " + file.string();
    out.hit = std::move(r);
  } catch (const std::exception& e) {
    out.problem = file.string() + ": unreadable (" + e.what() + ")";
  }
  return out;
}

void ResultCache::store(const cases::Scene& scene, const cases::RunResult& run, const std::string& version) const {
  if (run.status != cases::RunStatus::ok) return;
  nlohmann::ordered_json j;
  j["fingerprint"] = scene_fingerprint(scene);
  j["engine"] = run.engine;
  j["version"] = version;
  j["scene"] = scene_json(scene);
  cases::RunResult stored = run;
  stored.source = "run";
  j["result"] = run_result_json(stored);
  support::write_file(path_of(scene, run.engine, version), with_checksum(std::move(j)).dump() + "\n");
}

Baseline read_baseline(const std::filesystem::path& file) {
  try {
    const auto j = nlohmann::ordered_json::parse(support::read_file(file));
    if (const std::string problem = checksum_problem(j); !problem.empty()) {
      throw std::runtime_error(problem + "; rewrite it with `demwb refresh --write-baselines`");
    }
    Baseline b;
    b.case_name = j.at("case").get<std::string>();
    b.fingerprint = j.at("fingerprint").get<std::string>();
    for (const auto& [engine, r] : j.at("references").items()) {
      b.references[engine] = run_result_from_json(r);
    }
    if (j.contains("inputs")) b.inputs = j.at("inputs").get<std::map<std::string, std::string>>();
    b.inhouse_metrics = j.at("inhouse_metrics").get<std::map<std::string, double>>();
    return b;
  } catch (const std::exception& e) {
    throw std::runtime_error(file.string() + ": not a readable baseline: " + e.what());
  }
}

void write_baseline(const std::filesystem::path& file, const Baseline& b) {
  nlohmann::ordered_json j;
  j["case"] = b.case_name;
  j["fingerprint"] = b.fingerprint;
  nlohmann::ordered_json refs = nlohmann::ordered_json::object();
  for (const auto& [engine, r] : b.references) {
    cases::RunResult kept = r;
    kept.scratch_dir.clear();  // a path on the machine that made it
    refs[engine] = run_result_json(kept);
  }
  j["references"] = refs;
  j["inputs"] = b.inputs;
  j["inhouse_metrics"] = b.inhouse_metrics;
  support::write_file(file, with_checksum(std::move(j)).dump(1) + "\n");
}

}  // namespace store
