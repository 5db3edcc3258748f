// SPDX-License-Identifier: MIT
// Micro-benchmarks of the one per-pair evaluator, evaluate_contact, for the laws the many-body
// scenes use: the chute's linear spring with LAMMPS's dashpot and history friction, and Hertz
// with Mindlin friction. Each iteration evaluates one touching pair with a stored slip.
#include <benchmark/benchmark.h>

#include <memory>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/forces/contact_batch.hpp"

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
/// The same law through the batched kernel: one iteration evaluates a full batch of touching
/// pairs (items are pairs, so the rate compares with the rows above per pair).
void LinearMassVelocitySpringCoulombBatch(benchmark::State& state) {
  auto batch = std::make_unique<dem::ContactBatch>();
  dem::ContactBatch& b = *batch;
  for (std::uint32_t k = 0; k < dem::kContactBatch; ++k) {
    const double wobble = 1e-3 * k / dem::kContactBatch;  // not all lanes alike
    b.dx[k] = -0.99 + wobble;
    b.dy[k] = -0.01;
    b.dz[k] = 0.0;
    b.rp[k] = b.rq[k] = 0.5;
    b.mp[k] = b.mq[k] = 1.0 / 0.52;
    b.upx[k] = 0.1;
    b.upy[k] = 0.02;
    b.upz[k] = -0.03;
    b.uqx[k] = -0.1;
    b.uqy[k] = b.uqz[k] = 0.0;
    b.wpx[k] = 1.0;
    b.wpy[k] = 2.0;
    b.wpz[k] = 3.0;
    b.wqx[k] = -2.0;
    b.wqy[k] = 0.0;
    b.wqz[k] = 1.0;
    dem::set_law(b, k, {2e5, 50.0, 2e5 * 2.0 / 7.0, 0.5, 0.0});
  }
  dem::BatchPolicies policies;
  policies.lever_arm_radius = true;
  policies.increment_project = true;
  for (auto _ : state) {
    for (std::uint32_t k = 0; k < dem::kContactBatch; ++k) {  // the committed slip, as the pair loop loads it
      b.sx[k] = 0.0;
      b.sy[k] = 1e-4;
      b.sz[k] = 2e-5;
    }
    dem::evaluate_contact_batch(b, dem::kContactBatch, policies, 1e-4);
    benchmark::DoNotOptimize(b.fx[0]);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * dem::kContactBatch);
}
void HertzTsujiMindlin(benchmark::State& state) { evaluate(state, table("hertz", "tsuji", "mindlin_8g")); }
void PairGeometry(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(geometry());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

}  // namespace

BENCHMARK(LinearMassVelocitySpringCoulomb);
BENCHMARK(LinearMassVelocitySpringCoulombStatic);
BENCHMARK(LinearMassVelocitySpringCoulombBatch);
BENCHMARK(HertzTsujiMindlin);
BENCHMARK(PairGeometry);
