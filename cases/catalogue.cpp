// SPDX-License-Identifier: MIT
#include "cases/catalogue.hpp"

#include <algorithm>
#include <array>

namespace cases {
namespace {

constexpr std::array kMetrics{
    MetricInfo{"contact_duration", "s",
               "time between the overlap's sign changes, each located by linear interpolation", true, false},
    MetricInfo{"restitution", "-",
               "normal relative speed after / before the first contact of the compared pair", true, false},
    MetricInfo{"max_overlap", "m", "largest overlap of the compared pair (parabolic refinement)", true, false},
    MetricInfo{"max_force", "N",
               "largest normal force of the compared pair (parabolic refinement)", true, false},
    MetricInfo{"max_position", "m",
               "largest displacement of the subject along the collision axis, over the samples", false, true},
    MetricInfo{"amplitude_error", "-",
               "εx_amp, thesis eq 4.8: |max x_num − max x_analytic| over the same samples, "
               "divided by the analytic maximum overlap", true, true},
};

constexpr std::array<std::string_view, 4> kEngines{"inhouse", "analytic", "lammps", "yade"};

}  // namespace

std::span<const MetricInfo> metric_catalogue() noexcept { return kMetrics; }

bool is_known_metric(std::string_view name) noexcept {
  return std::any_of(kMetrics.begin(), kMetrics.end(),
                     [&](const MetricInfo& m) { return m.name == name; });
}

const MetricInfo* find_metric(std::string_view name) noexcept {
  for (const auto& m : kMetrics) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

std::span<const std::string_view> engine_catalogue() noexcept { return kEngines; }

bool is_known_engine(std::string_view name) noexcept {
  return std::find(kEngines.begin(), kEngines.end(), name) != kEngines.end();
}

}  // namespace cases
