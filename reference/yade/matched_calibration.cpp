// SPDX-License-Identifier: MIT
#include "reference/yade/matched_calibration.hpp"

#include <cmath>
#include <numbers>

#include "cases/time_step.hpp"
#include "dem/simulation/simulation.hpp"
#include "reference/common/core_setup.hpp"

namespace reference::yade {
namespace {

/// The compared contact alone, as the YADE calibration block builds it: the particle and its
/// partner (sphere or wall), no gravity, no friction, no rotation, its velocity traced.
cases::Scene two_body_scene(const cases::Scene& matched, const YadeCalibrationPlan& plan) {
  cases::Scene s = matched;
  s.particles = {matched.particles[plan.particle]};
  s.walls.clear();
  if (plan.partner_particle) s.particles.push_back(matched.particles[*plan.partner_particle]);
  if (plan.partner_wall) s.walls = {matched.walls[*plan.partner_wall]};
  s.gravity = {0.0, 0.0, 0.0};
  s.fluid.reset();
  s.integration.rotation = false;
  s.model.tangential = "none";
  s.output = {};
  s.output.trace_every = 1;
  s.output.trace_particles = {0};
  if (s.particles.size() > 1) s.output.trace_particles.push_back(1);
  s.compare = {};
  return s;
}

/// Rebound restitution of the two-body core run with material restitution ε', or NaN. The core
/// is driven directly (the neutral layer's set-up), not through the in-house engine: a driver
/// depends on no other engine (docs/architecture.md, "Layers").
double rebound(cases::Scene s, const YadeCalibrationPlan& plan, double restitution) {
  s.materials[plan.material].restitution = restitution;
  dem::Simulation sim(core_setup(PreparedScene(s)).simulation);
  const bool pair = s.particles.size() > 1;
  // Velocity of sphere `id` along the plan's normal, summed component by component.
  const auto along_normal = [&](std::uint32_t id) {
    const auto c = static_cast<Eigen::Index>(sim.slot(id));
    double v = 0.0;
    for (Eigen::Index k = 0; k < 3; ++k) v += sim.state().velocity(k, c) * plan.normal[static_cast<std::size_t>(k)];
    return v;
  };
  const auto relative = [&] { return along_normal(0) - (pair ? along_normal(1) : 0.0); };
  const double before = relative();
  const std::uint64_t steps = cases::step_count(s.integration.duration, sim.timestep());
  for (std::uint64_t n = 0; n < steps; ++n) sim.step();
  return -relative() / before;
}

}  // namespace

double restitution_for_betan(double betan) noexcept {
  return std::exp(-std::numbers::pi * betan / std::sqrt(1.0 - betan * betan));
}

std::optional<double> matched_calibrated_restitution(const cases::Scene& matched,
                                                     const YadeCalibrationPlan& plan) {
  const cases::Scene s = two_body_scene(matched, plan);
  const auto e_of = [&](double betan) { return rebound(s, plan, restitution_for_betan(betan)); };
  // The same secant as the YADE block (restitution_calibration.cpp).
  double b0 = plan.start;
  double e0 = e_of(b0);
  if (!std::isfinite(e0)) return std::nullopt;
  double best_b = b0;
  double best_e = e0;
  double b1 = b0 * (1.0 + 2.0 * (e0 - plan.target));
  for (int k = 0; k < 20; ++k) {
    const double e1 = e_of(b1);
    if (!std::isfinite(e1)) return std::nullopt;
    if (std::abs(e1 - plan.target) < std::abs(best_e - plan.target)) {
      best_b = b1;
      best_e = e1;
    }
    if (std::abs(e1 - plan.target) <= 1e-12 || e1 == e0) break;
    const double next = b1 - (e1 - plan.target) * (b1 - b0) / (e1 - e0);
    b0 = b1;
    e0 = e1;
    b1 = next;
  }
  return restitution_for_betan(best_b);
}

}  // namespace reference::yade
