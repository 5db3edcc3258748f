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

constexpr double kInf = std::numeric_limits<double>::infinity();

/// What one material contributes: how many mobile and fixed spheres, the lightest and smallest.
struct MaterialCensus {
  std::size_t mobile = 0;
  std::size_t fixed = 0;
  double lightest_mobile = kInf;
  double smallest_radius = kInf;
};

/// Contact duration of a law for a collision of the given scale, with the law's damping.
double collision_duration(const PairLaw& law, const CollisionScale& scale) {
  const double k = collision_stiffness(law, scale);
  const double eta = damping_coefficient(law, scale.reduced_mass, k);
  return laws::linear_contact_duration(k, scale.reduced_mass, eta);
}

/// Largest normal approach speed to expect: twice the fastest particle, or a fall through the
/// largest diameter under gravity, whichever is larger.
double expected_impact_speed(const ParticleProperties& props, const KinematicState& state,
                             const Vec3& gravity) {
  double fastest = 0.0;
  double largest = 0.0;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(props.size()); ++i) {
    fastest = std::max(fastest, state.velocity.col(i).norm());
    largest = std::max(largest, 2.0 * props.radius[i]);
  }
  return std::max(2.0 * fastest, std::sqrt(2.0 * gravity.norm() * largest));
}

}  // namespace

TimestepLimits timestep_limits(const ParticleProperties& props, const KinematicState& state,
                               const PairTable& table, const Vec3& gravity, bool rotation,
                               double steps_per_collision,
                               const std::vector<std::uint32_t>& wall_materials) {
  std::vector<MaterialCensus> census(table.material_count());
  for (std::size_t i = 0; i < props.size(); ++i) {
    MaterialCensus& c = census[props.material[i]];
    const auto k = static_cast<Eigen::Index>(i);
    c.smallest_radius = std::min(c.smallest_radius, props.radius[k]);
    if (props.fixed[i] != 0) {
      ++c.fixed;
    } else {
      ++c.mobile;
      c.lightest_mobile = std::min(c.lightest_mobile, props.mass[k]);
    }
  }
  const double speed = expected_impact_speed(props, state, gravity);
  double sqrt_m_over_k = kInf;
  double t_c = kInf;
  for (std::size_t a = 0; a < census.size(); ++a) {
    if (census[a].mobile == 0) continue;
    for (std::size_t b = 0; b < census.size(); ++b) {
      const PairLaw& law = table.law(a, b);
      const double m_a = census[a].lightest_mobile;
      const double r_a = census[a].smallest_radius;
      const double r_b = census[b].smallest_radius;
      const bool mobile_partner = a == b ? census[a].mobile >= 2 : census[b].mobile >= 1;
      const bool fixed_partner = census[b].fixed >= 1;
      if (!mobile_partner && !fixed_partner) continue;
      const CollisionScale scale{m_a, r_a * r_b / (r_a + r_b), speed};
      sqrt_m_over_k = std::min(sqrt_m_over_k, std::sqrt(m_a / collision_stiffness(law, scale)));
      if (mobile_partner) {
        const double m_b = census[b].lightest_mobile;
        t_c = std::min(t_c, collision_duration(law, {m_a * m_b / (m_a + m_b), scale.reduced_radius, speed}));
      }
      if (fixed_partner) t_c = std::min(t_c, collision_duration(law, scale));
    }
    // A wall is a fixed partner of infinite radius: R* = r, m* = m.
    for (const std::uint32_t w : wall_materials) {
      const PairLaw& law = table.law(a, w);
      const CollisionScale scale{census[a].lightest_mobile, census[a].smallest_radius, speed};
      sqrt_m_over_k = std::min(sqrt_m_over_k, std::sqrt(scale.reduced_mass / collision_stiffness(law, scale)));
      t_c = std::min(t_c, collision_duration(law, scale));
    }
  }
  return TimestepLimits{sqrt_m_over_k, (rotation ? 0.22 : 0.34) * sqrt_m_over_k, t_c,
                        t_c / steps_per_collision, steps_per_collision, rotation};
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
