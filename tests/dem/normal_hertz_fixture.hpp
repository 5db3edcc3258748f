// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>

#include "dem/contact/laws/hertz.hpp"
#include "dem/simulation/simulation.hpp"

namespace hertz_test {

/// The Hertz impact measured with LAMMPS 29 Sep 2021: p (r = 0.01 m, ρ = 1000) onto a fixed
/// sphere q (r = 0.1 m) of the same material, E = 1e7 Pa, ν = 0.3 → E* = E/(2(1−ν²)) =
/// 5.4945e6 Pa, R* = 9.0909e-3 m.
constexpr double kRadius = 0.01;
constexpr double kPartnerRadius = 0.1;
constexpr double kDensity = 1000.0;
constexpr double kYoungs = 1e7;
constexpr double kPoisson = 0.3;

/// Mass of the moving sphere [kg].
inline double mover_mass() { return 4.0 / 3.0 * std::numbers::pi * kDensity * std::pow(kRadius, 3); }
/// E* of the pair [Pa].
inline double effective_modulus() { return kYoungs / (2.0 * (1.0 - kPoisson * kPoisson)); }
/// R* of the pair [m].
inline double reduced_radius() { return kRadius * kPartnerRadius / (kRadius + kPartnerRadius); }
/// Elastic Hertz contact duration of the impact at `speed` [s].
inline double elastic_duration(double speed) {
  return dem::laws::hertz_contact_duration(mover_mass(), effective_modulus(), reduced_radius(), speed);
}

/// Hertz impact of p at `speed` onto the fixed q (or, with `wall`, onto a plane wall), contact
/// starting 10.37 steps after t = 0 (not on a step boundary). `configure` adds the damping
/// model's properties and policies.
inline dem::SimulationSetup impact(dem::SchemeId scheme, double dt, const std::string& damping,
                                   const std::function<void(dem::SimulationSetup&)>& configure = {},
                                   double speed = 1.0, bool wall = false) {
  dem::SimulationSetup s;
  dem::MaterialProperties m;
  m.name = "sphere";
  m.density = kDensity;
  m.youngs_modulus = kYoungs;
  m.poisson_ratio = kPoisson;
  s.materials = {m};
  s.model.normal = "hertz";
  s.model.damping = damping;
  const double gap = 10.37 * speed * dt;
  s.particles = {dem::ParticleInit{kRadius, kRadius, kDensity, 0, dem::Vec3(0, 0, 0),
                                   dem::Vec3(speed, 0, 0), dem::Vec3::Zero(), false}};
  if (wall) {
    s.walls = {dem::Wall{dem::Vec3(kRadius + gap, 0, 0), dem::Vec3(-1, 0, 0), dem::Vec3::Zero(), 0}};
  } else {
    s.particles.push_back(dem::ParticleInit{kPartnerRadius, kPartnerRadius, kDensity, 0,
                                            dem::Vec3(kRadius + kPartnerRadius + gap, 0, 0),
                                            dem::Vec3::Zero(), dem::Vec3::Zero(), true});
  }
  s.scheme = scheme;
  s.scheme_settings.rotation = false;
  s.scheme_settings.length_scale = kRadius;
  s.timestep = dt;
  if (configure) configure(s);
  return s;
}

/// Figures of the first contact of the watched pair, measured on the per-step samples the way
/// compare/ does: crossings by linear interpolation, peaks by a parabola through three samples.
struct ImpactFigures {
  double duration = std::numeric_limits<double>::quiet_NaN();
  double max_overlap = 0.0;
  double max_force = 0.0;
  double restitution = std::numeric_limits<double>::quiet_NaN();
  bool energy_never_rose = true;  ///< kinetic + elastic energy never rose by > 1e-10 relative
};

/// Peak of a parabola through (−1, a), (0, b), (1, c), sample spacing 1.
inline double parabola_peak(double a, double b, double c) {
  const double curvature = a - 2.0 * b + c;
  if (curvature >= 0.0) return b;
  const double shift = 0.5 * (a - c) / curvature;
  return b - 0.25 * (a - c) * shift;
}

/// Steps `sim` (particle 0 against particle 1 or wall 0) until `t_end`, measuring the contact.
inline ImpactFigures measure_impact(dem::Simulation& sim, double speed, double t_end, bool wall = false) {
  sim.watch({dem::ContactObservation{0, wall ? 0U : 1U, wall, 0.0, 0.0, false}});
  ImpactFigures f;
  double start = std::numeric_limits<double>::quiet_NaN();
  double prev_t = sim.time();
  double prev_overlap = sim.force_field().observations()[0].overlap;
  double before2 = -1.0, before1 = -1.0;  // overlap at the two previous samples
  double fbefore2 = 0.0, fbefore1 = 0.0;
  double energy = sim.kinetic_energy();
  while (sim.time() < t_end) {
    sim.step();
    const auto& o = sim.force_field().observations()[0];
    const double t = sim.time();
    if (prev_overlap <= 0.0 && o.overlap > 0.0 && std::isnan(start)) {
      start = prev_t + (t - prev_t) * (-prev_overlap) / (o.overlap - prev_overlap);
    }
    if (!std::isnan(start) && std::isnan(f.duration) && prev_overlap > 0.0 && o.overlap <= 0.0) {
      const double end = prev_t + (t - prev_t) * prev_overlap / (prev_overlap - o.overlap);
      f.duration = end - start;
    }
    if (before1 > 0.0 && before1 >= before2 && before1 >= o.overlap) {
      f.max_overlap = std::max(f.max_overlap, parabola_peak(before2, before1, o.overlap));
    }
    if (fbefore1 > 0.0 && fbefore1 >= fbefore2 && fbefore1 >= o.normal_force) {
      f.max_force = std::max(f.max_force, parabola_peak(fbefore2, fbefore1, o.normal_force));
    }
    f.max_force = std::max(f.max_force, o.normal_force);
    before2 = before1;
    before1 = o.overlap;
    fbefore2 = fbefore1;
    fbefore1 = o.normal_force;
    prev_t = t;
    prev_overlap = o.overlap;
    const double now = sim.kinetic_energy() + sim.force_field().elastic_energy();
    if (now > energy * (1.0 + 1e-10)) f.energy_never_rose = false;
    energy = now;
  }
  f.restitution = -sim.state().velocity(0, 0) / speed;
  return f;
}

}  // namespace hertz_test
