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

/// What one material contributes: how many mobile and fixed spheres, the lightest mobile one.
struct MaterialCensus {
  std::size_t mobile = 0;
  std::size_t fixed = 0;
  double lightest_mobile = kInf;
};

/// Stiffness that sets the collision time scale of a law.
double characteristic_stiffness(const PairLaw& law) {
  return std::visit([](const auto& m) { return m.characteristic_stiffness(); }, law.normal);
}

/// Contact duration of a law for reduced mass m*, with the law's damping at that mass.
double collision_duration(const PairLaw& law, double reduced_mass) {
  ContactGeometry g{};
  g.reduced_mass = reduced_mass;
  const double k = characteristic_stiffness(law);
  const double eta = damping_coefficient(law, g);
  return laws::linear_contact_duration(k, reduced_mass, eta);
}

}  // namespace

TimestepLimits timestep_limits(const ParticleProperties& props, const PairTable& table,
                               bool rotation, double steps_per_collision) {
  std::vector<MaterialCensus> census(table.material_count());
  for (std::size_t i = 0; i < props.size(); ++i) {
    MaterialCensus& c = census[props.material[i]];
    if (props.fixed[i] != 0) {
      ++c.fixed;
    } else {
      ++c.mobile;
      c.lightest_mobile = std::min(c.lightest_mobile, props.mass[static_cast<Eigen::Index>(i)]);
    }
  }
  double sqrt_m_over_k = kInf;
  double t_c = kInf;
  for (std::size_t a = 0; a < census.size(); ++a) {
    if (census[a].mobile == 0) continue;
    for (std::size_t b = 0; b < census.size(); ++b) {
      const PairLaw& law = table.law(a, b);
      const double m_a = census[a].lightest_mobile;
      const bool mobile_partner = a == b ? census[a].mobile >= 2 : census[b].mobile >= 1;
      const bool fixed_partner = census[b].fixed >= 1;
      if (!mobile_partner && !fixed_partner) continue;
      sqrt_m_over_k = std::min(sqrt_m_over_k, std::sqrt(m_a / characteristic_stiffness(law)));
      if (mobile_partner) {
        const double m_b = census[b].lightest_mobile;
        t_c = std::min(t_c, collision_duration(law, m_a * m_b / (m_a + m_b)));
      }
      if (fixed_partner) t_c = std::min(t_c, collision_duration(law, m_a));
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
