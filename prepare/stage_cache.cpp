// SPDX-License-Identifier: MIT
#include "prepare/stage_cache.hpp"

#include <fstream>
#include <stdexcept>
#include <system_error>
#include <thread>

#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "support/text_file.hpp"

namespace prepare {
namespace {

std::filesystem::path file_of(const std::filesystem::path& dir, const std::string& key) {
  return dir / (key + ".json");
}

}  // namespace

std::optional<StoredStage> find_stage(const std::filesystem::path& dir, const std::string& key,
                                      std::size_t particle_count) {
  const std::filesystem::path file = file_of(dir, key);
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(support::read_file(file));
    if (j.at("key").get<std::string>() != key) return std::nullopt;
    StoredStage out;
    for (const auto& row : j.at("particles")) {
      cases::ParticleSpec p;
      p.position = row.at("position").get<cases::Vector3>();
      p.velocity = row.at("velocity").get<cases::Vector3>();
      p.angular_velocity = row.at("angular_velocity").get<cases::Vector3>();
      out.particles.push_back(p);
    }
    for (const auto& f : j.at("figures")) {
      out.figures.emplace_back(f.at(0).get<std::string>(), f.at(1).get<double>());
    }
    if (out.particles.size() != particle_count) return std::nullopt;
    return out;
  } catch (const std::exception&) {
    return std::nullopt;  // unreadable or from another layout: form afresh
  }
}

void store_stage(const std::filesystem::path& dir, const std::string& key, const StoredStage& stage) {
  nlohmann::ordered_json j;
  j["key"] = key;
  nlohmann::ordered_json figures = nlohmann::ordered_json::array();
  for (const auto& [name, value] : stage.figures) figures.push_back({name, value});
  j["figures"] = figures;
  nlohmann::ordered_json particles = nlohmann::ordered_json::array();
  for (const cases::ParticleSpec& p : stage.particles) {
    particles.push_back(
        {{"position", p.position}, {"velocity", p.velocity}, {"angular_velocity", p.angular_velocity}});
  }
  j["particles"] = particles;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error(fmt::format("cannot create the stage cache {}: {}", dir.string(), ec.message()));
  const std::filesystem::path file = file_of(dir, key);
  // Unique per process and thread: concurrent sweeps may form the same agglomerate at once.
  const std::filesystem::path temporary =
      fmt::format("{}.{}.{}.tmp", file.string(), ::getpid(), std::hash<std::thread::id>{}(std::this_thread::get_id()));
  {
    std::ofstream out(temporary);
    out << j.dump(1) << '\n';
    if (!out) throw std::runtime_error(fmt::format("cannot write the stage cache file {}", temporary.string()));
  }
  std::filesystem::rename(temporary, file, ec);
  if (ec) throw std::runtime_error(fmt::format("cannot write the stage cache file {}: {}", file.string(), ec.message()));
}

}  // namespace prepare
