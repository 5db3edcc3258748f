// SPDX-License-Identifier: MIT
// Uses the installed DEM core: a contact law, and a whole damped collision through the core.
#include <cmath>
#include <cstdio>

#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/simulation/simulation.hpp"

int main() {
  dem::SimulationSetup s;
  dem::MaterialProperties m;
  m.name = "glass";
  m.density = 2500.0;
  m.normal_stiffness = 1e5;
  m.restitution = 0.5;
  s.materials = {m};
  s.model.damping = "restitution";
  s.particles = {
      dem::ParticleInit{0.01, 0.01, 2500.0, 0, dem::Vec3(0, 0, 0), dem::Vec3(1, 0, 0), dem::Vec3::Zero(), false},
      dem::ParticleInit{0.01, 0.01, 2500.0, 0, dem::Vec3(0.0201, 0, 0), dem::Vec3::Zero(), dem::Vec3::Zero(), true}};
  s.scheme = dem::SchemeId::rk4;
  s.timestep = 1e-6;
  dem::Simulation sim(s);
  while (sim.time() < 3e-3) sim.step();
  const double e = -sim.state().velocity(0, 0);
  std::printf("restitution %.6f\n", e);
  return std::abs(e - 0.5) < 1e-3 ? 0 : 1;
}
