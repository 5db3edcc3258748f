// SPDX-License-Identifier: MIT
#include "cases/trace.hpp"

#include "cases/scene.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace cases {

std::string first_non_finite(const Trace& trace) {
  for (std::size_t c = 0; c < trace.columns().size(); ++c) {
    const auto& v = trace.values(c);
    for (std::size_t r = 0; r < v.size(); ++r) {
      if (!std::isfinite(v[r])) {
        return fmt::format("{} = {} at t = {:.6g} s (row {})", trace.columns()[c], v[r], trace.values(0)[r], r);
      }
    }
  }
  return "";
}

std::size_t Trace::add_column(std::string name) {
  if (column(name) != nullptr) throw std::invalid_argument("duplicate trace column " + name);
  names_.push_back(std::move(name));
  values_.emplace_back();
  if (values_.size() > 1) values_.back().reserve(values_.front().capacity());
  return names_.size() - 1;
}

void Trace::append_row(const std::vector<double>& row) {
  if (row.size() != values_.size()) {
    throw std::invalid_argument(fmt::format("trace row has {} values for {} columns", row.size(),
                                            values_.size()));
  }
  for (std::size_t c = 0; c < row.size(); ++c) values_[c].push_back(row[c]);
}

const std::vector<double>* Trace::column(std::string_view name) const noexcept {
  for (std::size_t c = 0; c < names_.size(); ++c) {
    if (names_[c] == name) return &values_[c];
  }
  return nullptr;
}

std::string particle_column(std::size_t particle, std::string_view quantity) {
  return fmt::format("p{}.{}", particle, quantity);
}

std::string pair_column(std::size_t p, std::size_t q, std::string_view quantity) {
  return fmt::format("c{}-{}.{}", p, q, quantity);
}

Trace trace_layout(const Scene& scene) {
  Trace trace;
  trace.add_column("time");
  for (const std::size_t i : scene.output.trace_particles) {
    for (const auto q : kParticleQuantities) trace.add_column(particle_column(i, q));
  }
  for (const auto& [p, q] : scene.output.trace_pairs) {
    for (const auto name : kPairQuantities) trace.add_column(pair_column(p, q, name));
  }
  for (const auto& [p, w] : scene.output.trace_walls) {
    for (const auto name : kPairQuantities) trace.add_column(wall_column(p, w, name));
  }
  for (const std::string& a : scene.output.trace_aggregates) trace.add_column(aggregate_column(a));
  return trace;
}

std::string aggregate_column(std::string_view quantity) { return fmt::format("all.{}", quantity); }

std::string wall_column(std::size_t p, std::size_t wall, std::string_view quantity) {
  return fmt::format("c{}-w{}.{}", p, wall, quantity);
}

}  // namespace cases
