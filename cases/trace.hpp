// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace cases {

/// Time series of named quantities, one column per quantity, sampled at the same rows.
/// Column names: `time`; per particle i `p<i>.x|y|z|vx|vy|vz|wx|wy|wz|fx|fy|fz`; per contact
/// (i, j) `c<i>-<j>.overlap` and `c<i>-<j>.fn` (normal force, repulsive positive); per
/// particle–wall contact (i, w) `c<i>-w<w>.overlap` and `.fn`, after the pair columns.
class Trace {
 public:
  /// Adds an empty column and returns its index; names must be unique.
  std::size_t add_column(std::string name);
  /// Appends one row; `row` has one value per column in column order.
  void append_row(const std::vector<double>& row);
  /// Column named `name`, or nullptr.
  [[nodiscard]] const std::vector<double>* column(std::string_view name) const noexcept;
  /// Column names in order.
  [[nodiscard]] const std::vector<std::string>& columns() const noexcept { return names_; }
  /// Values of column `index`.
  [[nodiscard]] const std::vector<double>& values(std::size_t index) const {
    return values_.at(index);
  }
  /// Number of rows.
  [[nodiscard]] std::size_t rows() const noexcept {
    return values_.empty() ? 0 : values_.front().size();
  }
  /// True when there is no row.
  [[nodiscard]] bool empty() const noexcept { return rows() == 0; }

 private:
  std::vector<std::string> names_;
  std::vector<std::vector<double>> values_;
};

/// The first value of `trace` that is NaN or infinite, as "<column> = <value> at t = <time> s
/// (row <r>)" (the time column is the first), or empty when every value is finite.
[[nodiscard]] std::string first_non_finite(const Trace& trace);

/// Column name of a particle quantity, e.g. particle_column(0, "vx") = "p0.vx".
std::string particle_column(std::size_t particle, std::string_view quantity);
/// Column name of a contact quantity, e.g. pair_column(0, 1, "overlap") = "c0-1.overlap".
std::string pair_column(std::size_t p, std::size_t q, std::string_view quantity);
/// Column name of a particle–wall contact quantity, e.g. wall_column(0, 2, "fn") = "c0-w2.fn".
std::string wall_column(std::size_t p, std::size_t wall, std::string_view quantity);

struct Scene;

/// An empty trace with the columns every engine records for `scene`, in order: time; the 12
/// quantities of each output.trace_particles; overlap and fn of each output.trace_pairs; overlap
/// and fn of each output.trace_walls; each output.trace_aggregates.
Trace trace_layout(const Scene& scene);

/// The quantities traced per particle, in column order.
inline constexpr std::string_view kParticleQuantities[] = {"x",  "y",  "z",  "vx", "vy", "vz",
                                                           "wx", "wy", "wz", "fx", "fy", "fz"};
/// Whole-scene quantities a trace may carry (output.trace_aggregates): translational and
/// rotational kinetic energy of the mobile spheres [J], and the coordination number (mean
/// sphere–sphere contacts per sphere, 2 × pairs whose bodies touch / spheres) [-].
inline constexpr std::string_view kAggregateQuantities[] = {"kinetic_energy", "rotational_energy",
                                                            "coordination_number"};
/// Column name of an aggregate quantity, e.g. aggregate_column("kinetic_energy") = "all.kinetic_energy".
std::string aggregate_column(std::string_view quantity);

/// The quantities traced per contact, in column order.
inline constexpr std::string_view kPairQuantities[] = {"overlap", "fn"};
/// Columns of the energy trace (RunResult::energy), after "time".
inline constexpr std::string_view kEnergyQuantities[] = {
    "energy.kinetic", "energy.elastic", "energy.cohesive", "energy.gravitational",
    "energy.dissipated_damping", "energy.dissipated_friction",
    "energy.dissipated_adhesion", "energy.dissipated_plastic", "energy.stiffness_change", "energy.fluid_work", "energy.boundary_work",
    "energy.integration_error", "energy.balance"};

}  // namespace cases
