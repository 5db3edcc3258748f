// SPDX-License-Identifier: MIT
#include "dem/timestep/timestep_control.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/laws/linear_dashpot.hpp"

namespace dem {
namespace {

constexpr double kNoLimit = std::numeric_limits<double>::infinity();

/// Contact duration of a law for a collision of the given scale, with the law's damping.
double collision_duration(const PairLaw& law, const CollisionScale& scale) {
  const double k = collision_stiffness(law, scale);
  const double eta = damping_coefficient(law, scale.reduced_mass, k);
  return laws::linear_contact_duration(k, scale.reduced_mass, eta);
}

}  // namespace

void add_to_census(MaterialCensus& census, double mass, double radius, bool fixed) noexcept {
  census.smallest_radius = std::min(census.smallest_radius, radius);
  if (fixed) {
    ++census.fixed;
  } else {
    ++census.mobile;
    census.lightest_mobile = std::min(census.lightest_mobile, mass);
  }
}

double expected_impact_speed(double fastest_speed, double largest_diameter, double g) noexcept {
  return std::max(2.0 * fastest_speed, std::sqrt(2.0 * g * largest_diameter));
}

void for_each_weighed_collision(const std::vector<MaterialCensus>& census, double speed,
                                const std::vector<std::uint32_t>& wall_materials,
                                const std::function<void(const WeighedCollision&)>& visit) {
  for (std::size_t a = 0; a < census.size(); ++a) {
    if (census[a].mobile == 0) continue;
    const double m_a = census[a].lightest_mobile;
    const double r_a = census[a].smallest_radius;
    for (std::size_t b = 0; b < census.size(); ++b) {
      const double r_b = census[b].smallest_radius;
      const bool mobile_partner = a == b ? census[a].mobile >= 2 : census[b].mobile >= 1;
      const bool fixed_partner = census[b].fixed >= 1;
      if (!mobile_partner && !fixed_partner) continue;
      WeighedCollision c{a, b, std::nullopt, {m_a, r_a * r_b / (r_a + r_b), speed}, fixed_partner, std::nullopt};
      if (mobile_partner) {
        const double m_b = census[b].lightest_mobile;
        c.mobile = CollisionScale{m_a * m_b / (m_a + m_b), c.scale.reduced_radius, speed};
      }
      visit(c);
    }
    // A wall is a fixed partner of infinite radius: R* = r, m* = m.
    for (std::size_t w = 0; w < wall_materials.size(); ++w) {
      visit(WeighedCollision{a, wall_materials[w], w, {m_a, r_a, speed}, true, std::nullopt});
    }
  }
}

TimestepLimits timestep_limits(const std::vector<MaterialCensus>& census, double speed, const PairTable& table,
                               bool rotation, double steps_per_collision,
                               const std::vector<std::uint32_t>& wall_materials) {
  double sqrt_m_over_k = kNoLimit;
  double t_c = kNoLimit;
  for_each_weighed_collision(census, speed, wall_materials, [&](const WeighedCollision& c) {
    const PairLaw& law = table.law(c.a, c.b);
    sqrt_m_over_k = std::min(sqrt_m_over_k, std::sqrt(c.scale.reduced_mass / collision_stiffness(law, c.scale)));
    if (c.mobile) t_c = std::min(t_c, collision_duration(law, *c.mobile));
    if (c.fixed_partner) t_c = std::min(t_c, collision_duration(law, c.scale));
  });
  return TimestepLimits{sqrt_m_over_k, (rotation ? 0.22 : 0.34) * sqrt_m_over_k, t_c,
                        t_c / steps_per_collision, steps_per_collision, rotation};
}

TimestepLimits timestep_limits(const ParticleProperties& props, const KinematicState& state,
                               const PairTable& table, const Vec3& gravity, bool rotation,
                               double steps_per_collision,
                               const std::vector<std::uint32_t>& wall_materials) {
  std::vector<MaterialCensus> census(table.material_count());
  double fastest = 0.0;
  double largest = 0.0;
  for (std::size_t i = 0; i < props.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    add_to_census(census[props.material[i]], props.mass[k], props.radius[k], props.fixed[i] != 0);
    fastest = std::max(fastest, state.velocity.col(k).norm());
    largest = std::max(largest, 2.0 * props.radius[k]);
  }
  return timestep_limits(census, expected_impact_speed(fastest, largest, gravity.norm()), table, rotation,
                         steps_per_collision, wall_materials);
}

double automatic_timestep(const TimestepLimits& limits) noexcept {
  return std::min(limits.osullivan_bray, limits.collision_resolution);
}

std::vector<std::string> timestep_warnings(double dt, const TimestepLimits& limits) {
  std::vector<std::string> warnings;
  if (dt > limits.osullivan_bray) {
    warnings.push_back(fmt::format(
        "time step {:.6g} s exceeds the O'Sullivan–Bray stability limit {}√(m/k) = {:.6g} s "
        "(thesis eq 4.7, {})",
        dt, limits.rotation ? "0.22" : "0.34", limits.osullivan_bray,
        limits.rotation ? "with rotation" : "no rotation"));
  }
  if (dt > limits.collision_resolution) {
    warnings.push_back(fmt::format(
        "time step {:.6g} s resolves the shortest collision (t_c = {:.6g} s) with {:.3g} steps, "
        "fewer than the {} asked for (t_c/a = {:.6g} s, thesis eq 4.9)",
        dt, limits.collision_duration, limits.collision_duration / dt,
        limits.steps_per_collision, limits.collision_resolution));
  }
  return warnings;
}

}  // namespace dem
