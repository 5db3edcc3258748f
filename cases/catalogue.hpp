// SPDX-License-Identifier: MIT
#pragma once

#include <span>
#include <string_view>

namespace cases {

/// A metric a case file may ask for. compare/ implements each; a test keeps them in step.
struct MetricInfo {
  std::string_view name;
  std::string_view unit;
  std::string_view meaning;
  bool needs_pair;     ///< measured on the contact compare.pair
  bool needs_subject;  ///< measured on the motion of compare.subject
};

/// Every metric name a case file may list under compare.metrics.
std::span<const MetricInfo> metric_catalogue() noexcept;
/// True when `name` is in the metric catalogue.
bool is_known_metric(std::string_view name) noexcept;
/// Catalogue entry of `name`, or nullptr.
const MetricInfo* find_metric(std::string_view name) noexcept;

/// Every engine name a case file may list under compare.engines.
std::span<const std::string_view> engine_catalogue() noexcept;
/// True when `name` is in the engine catalogue.
bool is_known_engine(std::string_view name) noexcept;
/// The external reference codes (LAMMPS, YADE, LIGGGHTS), in the order reports list them.
std::span<const std::string_view> reference_codes() noexcept;
/// True for the external reference codes, whose results are cached and baselined.
bool is_reference_code(std::string_view name) noexcept;

/// Name of the in-house engine run with the numerics of reference code `code`: "inhouse@<code>".
std::string matched_engine_name(std::string_view code);
/// The reference code of a matched engine name ("inhouse@lammps" → "lammps"), or empty.
std::string_view matched_code(std::string_view engine) noexcept;

}  // namespace cases
