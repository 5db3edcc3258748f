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

std::filesystem::path ResultCache::path_of(const cases::Scene& scene, std::string_view engine,
                                           const std::string& version) const {
  const std::string name =
      scene_fingerprint(scene).substr(0, 32) + "-" + support::sha256_hex(version).substr(0, 12) + ".json";
  return dir_ / std::string(engine) / name;
}

std::optional<cases::RunResult> ResultCache::find(const cases::Scene& scene, std::string_view engine,
                                                  const std::string& version) const {
  const auto file = path_of(scene, engine, version);
  if (!std::filesystem::exists(file)) return std::nullopt;
  try {
    const auto j = nlohmann::ordered_json::parse(support::read_file(file));
    if (j.at("fingerprint") != scene_fingerprint(scene) || j.at("version") != version) return std::nullopt;
    cases::RunResult r = run_result_from_json(j.at("result"));
    r.source = "cache";
    r.conventions["result source"] = "reused from the result cache: " + file.string();
    return r;
  } catch (const std::exception&) {
    return std::nullopt;  // unreadable entry: run the engine again and overwrite it
  }
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
  support::write_file(path_of(scene, run.engine, version), j.dump() + "\n");
}

Baseline read_baseline(const std::filesystem::path& file) {
  try {
    const auto j = nlohmann::ordered_json::parse(support::read_file(file));
    Baseline b;
    b.case_name = j.at("case").get<std::string>();
    b.fingerprint = j.at("fingerprint").get<std::string>();
    for (const auto& [engine, r] : j.at("references").items()) {
      b.references[engine] = run_result_from_json(r);
    }
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
  for (const auto& [engine, r] : b.references) refs[engine] = run_result_json(r);
  j["references"] = refs;
  j["inhouse_metrics"] = b.inhouse_metrics;
  support::write_file(file, j.dump(1) + "\n");
}

}  // namespace store
