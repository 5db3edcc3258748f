// SPDX-License-Identifier: MIT
// Micro-benchmarks of the one per-pair evaluator, evaluate_contact, for the laws the many-body
// scenes use: the chute's linear spring with LAMMPS's dashpot and history friction, and Hertz
// with Mindlin friction. Each iteration evaluates one touching pair with a stored slip.
#include <benchmark/benchmark.h>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/pair_table.hpp"

namespace {

dem::MaterialProperties material() {
  dem::MaterialProperties m;
  m.name = "grain";
  m.density = 2500.0;
  m.normal_stiffness = 2e5;
  m.damping_rate = 50.0;
  m.tangential_stiffness = 2e5 * 2.0 / 7.0;
  m.tangential_damping_ratio = 0.0;
  m.friction = 0.5;
  m.youngs_modulus = 1e7;
  m.poisson_ratio = 0.3;
  m.restitution = 0.5;
  return m;
}

dem::PairTable table(const char* normal, const char* damping, const char* tangential) {
  dem::ModelChoice c;
  c.normal = normal;
  c.damping = damping;
  c.tangential = tangential;
  c.friction_limit = dem::FrictionLimit::elastic_damping;
  return dem::PairTable({material()}, {}, {}, c);
}

/// A touching pair with relative sliding and spin.
dem::ContactGeometry geometry() {
  const dem::SphereState p{dem::Vec3(0, 0, 0), dem::Vec3(0.1, 0.02, -0.03), dem::Vec3(1, 2, 3), 0.5, 0.5, 1.0 / 0.52};
  const dem::SphereState q{dem::Vec3(0.99, 0.01, 0.0), dem::Vec3(-0.1, 0, 0), dem::Vec3(-2, 0, 1), 0.5, 0.5, 1.0 / 0.52};
  return dem::pair_geometry(p, q, dem::PairLeverArm::radius);
}

void evaluate(benchmark::State& state, const dem::PairTable& t) {
  const dem::PairLaw& law = t.law(0, 0);
  dem::ContactGeometry g = geometry();
  dem::ContactHistory h;
  h.tangential_slip = dem::Vec3(0, 1e-4, 2e-5);
  for (auto _ : state) {
    benchmark::DoNotOptimize(g);
    const dem::ContactOutcome c = dem::evaluate_contact(law, g, h, 1e-4);
    benchmark::DoNotOptimize(c);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

void LinearMassVelocitySpringCoulomb(benchmark::State& state) {
  evaluate(state, table("linear", "lammps_mass_velocity", "spring_coulomb"));
}

/// The same law through the compile-time slots of the pair loop's fast path.
void LinearMassVelocitySpringCoulombStatic(benchmark::State& state) {
  const dem::PairTable t = table("linear", "lammps_mass_velocity", "spring_coulomb");
  using Slots = dem::StaticSlots<dem::LinearNormal, dem::LammpsMassVelocityDamping, dem::SpringCoulombTangential,
                                 dem::NoCohesion, dem::NoRolling>;
  const dem::PairLaw& law = t.law(0, 0);
  dem::ContactGeometry g = geometry();
  dem::ContactHistory h;
  h.tangential_slip = dem::Vec3(0, 1e-4, 2e-5);
  for (auto _ : state) {
    benchmark::DoNotOptimize(g);
    const dem::ContactOutcome c = dem::evaluate_contact_in(Slots{law}, g, h, 1e-4);
    benchmark::DoNotOptimize(c.force_on_p);
    benchmark::DoNotOptimize(c.torque_on_p);
    benchmark::DoNotOptimize(c.torque_on_q);
    benchmark::DoNotOptimize(c.history.tangential_slip);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
void HertzTsujiMindlin(benchmark::State& state) { evaluate(state, table("hertz", "tsuji", "mindlin_8g")); }
void PairGeometry(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(geometry());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

}  // namespace

BENCHMARK(LinearMassVelocitySpringCoulomb);
BENCHMARK(LinearMassVelocitySpringCoulombStatic);
BENCHMARK(HertzTsujiMindlin);
BENCHMARK(PairGeometry);
