// SPDX-License-Identifier: MIT
// The energy ledger balances to round-off on seeded random scenes that exercise every path of
// energy (springs, JKR and linear cohesion, dashpots, friction, rolling resistance, a moving
// wall, a sphere under prescribed motion, drag, buoyancy, virtual mass, a pull), for every scheme
// that states its weights; and its integration error shrinks with Δt, so that no path is
// hidden in it (docs/physics.md, "Energy ledger").
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "dem/contact/laws/jkr.hpp"
#include "dem/particles/particles.hpp"
#include "dem/simulation/simulation.hpp"

namespace energy_balance_test {

/// Largest |term| of a ledger (the scale its balance is judged against).
double scale_of(const dem::EnergyLedger& e) {
  return std::max({std::abs(e.kinetic), std::abs(e.elastic), std::abs(e.cohesive), std::abs(e.gravitational),
                   std::abs(e.dissipated_damping), std::abs(e.dissipated_friction), std::abs(e.dissipated_adhesion),
                   std::abs(e.dissipated_plastic), std::abs(e.stiffness_change), std::abs(e.fluid_work),
                   std::abs(e.boundary_work), std::abs(e.integration_error)});
}

/// A material with every property the models below read.
dem::MaterialProperties grain(const std::string& name, double surface_energy) {
  dem::MaterialProperties m;
  m.name = name;
  m.density = 2500.0;
  m.youngs_modulus = 1e7;
  m.poisson_ratio = 0.3;
  m.restitution = 0.7;
  m.friction = 0.4;
  m.tangential_stiffness = 2e3;
  m.tangential_damping_ratio = 0.5;
  m.rolling_friction = 0.05;
  m.rolling_stiffness = 5e2;
  m.rolling_damping = 1e-4;
  m.surface_energy = surface_energy;
  m.normal_stiffness = 2e3;
  m.cohesive_stiffness = 50.0;
  m.interaction_ratio = 1.2;
  return m;
}

/// Which pair law a random scene uses.
enum class Law { jkr, linear_cohesion };

/// A seeded scene of a dozen spheres in a box whose lid moves down, one of them driven along a
/// prescribed path, under gravity, a moving fluid (drag, buoyancy, virtual mass) and a pull.
dem::SimulationSetup random_scene(unsigned seed, Law law, dem::SchemeId scheme, double dt) {
  std::mt19937_64 rng(seed);
  // [0, 1) from the top 53 bits: the same numbers with every standard library.
  const auto unit = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  dem::SimulationSetup s;
  s.materials = {grain("grain", 0.05), grain("wall", 0.02)};
  if (law == Law::jkr) {
    s.model.normal = "hertz";
    s.model.damping = "tsuji";
    s.model.cohesion = "jkr";
  } else {
    s.model.normal = "linear";
    s.model.damping = "restitution";
    s.model.cohesion = "linear";
  }
  s.model.tangential = "spring_coulomb";
  s.model.rolling = "spring_dashpot_slider";
  const double box = 0.01;
  for (int k = 0; k < 12; ++k) {
    const double r = 0.0006 + 0.0002 * unit();
    const dem::Vec3 x(0.002 + 0.006 * unit(), 0.002 + 0.006 * unit(), 0.002 + 0.006 * unit());
    const dem::Vec3 u(unit() - 0.5, unit() - 0.5, unit() - 0.5);
    const dem::Vec3 w(50.0 * (unit() - 0.5), 50.0 * (unit() - 0.5), 50.0 * (unit() - 0.5));
    s.particles.push_back(dem::ParticleInit{r, r, 2500.0, 0, x, 0.4 * u, w, false});
  }
  // Pull them together so that contacts form within the run.
  for (auto& p : s.particles) p.velocity += 2.0 * (dem::Vec3(0.005, 0.005, 0.005) - p.position);
  s.particles[0].fixed = true;  // driven through the cluster
  s.motions = {dem::PrescribedMotion{0, s.particles[0].position,
                                     {dem::MotionSegment{0.004, dem::Vec3(0.3, 0.0, 0.1)},
                                      dem::MotionSegment{1.0, dem::Vec3(-0.2, 0.1, 0.0)}}}};
  s.walls = {dem::Wall{dem::Vec3::Zero(), dem::Vec3(0, 0, 1), dem::Vec3::Zero(), 1},
             dem::Wall{dem::Vec3(0, 0, box), dem::Vec3(0, 0, -1), dem::Vec3(0, 0, -0.3), 1},
             dem::Wall{dem::Vec3::Zero(), dem::Vec3(1, 0, 0), dem::Vec3(0.05, 0.0, 0.0), 1}};
  s.fields.gravity = dem::Vec3(0, 0, -9.81);
  dem::Fluid fluid;
  fluid.density = 800.0;  // dense enough that buoyancy and virtual mass weigh
  fluid.viscosity = 1e-3;
  fluid.velocity.uniform = dem::Vec3(0.2, 0.0, 0.05);
  fluid.buoyancy = true;
  fluid.virtual_mass = true;
  fluid.pressure_gradient = dem::Vec3(0.0, 50.0, 0.0);
  s.fields.fluid = fluid;
  s.scheme = scheme;
  s.scheme_settings.length_scale = 0.0008;
  s.timestep = dt;
  return s;
}

/// Runs `steps` steps and returns the largest |balance − balance(0)| over the run relative to
/// the largest ledger term.
double balance_drift(const dem::SimulationSetup& setup, int steps) {
  dem::Simulation sim(setup);
  const double start = sim.energy().balance();
  double drift = 0.0;
  double scale = scale_of(sim.energy());
  for (int n = 0; n < steps; ++n) {
    sim.step();
    const dem::EnergyLedger e = sim.energy();
    drift = std::max(drift, std::abs(e.balance() - start));
    scale = std::max(scale, scale_of(e));
  }
  EXPECT_GT(scale, 0.0);
  return drift / scale;
}

struct SchemeCase {
  dem::SchemeId scheme;
  dem::LeapfrogStart start;
};

class ExactSchemes : public ::testing::TestWithParam<SchemeCase> {};

TEST_P(ExactSchemes, BalanceHoldsToRoundOffOnSeededRandomScenes) {
  for (const Law law : {Law::jkr, Law::linear_cohesion}) {
    for (unsigned seed = 1; seed <= 3; ++seed) {
      dem::SimulationSetup s = random_scene(seed, law, GetParam().scheme, 2e-6);
      s.scheme_settings.leapfrog_start = GetParam().start;
      // The scene must really exercise the paths: check that each one booked work.
      dem::Simulation sim(s);
      for (int n = 0; n < 1500; ++n) sim.step();
      const dem::EnergyLedger e = sim.energy();
      EXPECT_GT(e.dissipated_damping, 0.0) << "seed " << seed;
      EXPECT_GT(e.dissipated_friction, 0.0) << "seed " << seed;
      EXPECT_NE(e.fluid_work, 0.0) << "seed " << seed;
      EXPECT_NE(e.boundary_work, 0.0) << "seed " << seed;
      if (law == Law::jkr) {
        EXPECT_NE(e.dissipated_adhesion, 0.0) << "seed " << seed;
      }
      EXPECT_LT(balance_drift(s, 1500), 1e-12) << "seed " << seed << (law == Law::jkr ? " jkr" : " linear");
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Schemes, ExactSchemes,
    ::testing::Values(SchemeCase{dem::SchemeId::velocity_verlet, dem::LeapfrogStart::half_kick},
                      SchemeCase{dem::SchemeId::leapfrog, dem::LeapfrogStart::half_kick},
                      SchemeCase{dem::SchemeId::leapfrog, dem::LeapfrogStart::given_is_half_step},
                      SchemeCase{dem::SchemeId::fe, dem::LeapfrogStart::half_kick},
                      SchemeCase{dem::SchemeId::se, dem::LeapfrogStart::half_kick},
                      SchemeCase{dem::SchemeId::rk2, dem::LeapfrogStart::half_kick},
                      SchemeCase{dem::SchemeId::rk4, dem::LeapfrogStart::half_kick}));

TEST(EnergyBalance, RungeKuttaStartUpOfAMultiStepSchemeBooksExactly) {
  // AB4 takes its first three steps with RK4 sub-steps, each stating its share of the step.
  for (const int substeps : {1, 4}) {
    dem::SimulationSetup s = random_scene(2, Law::jkr, dem::SchemeId::ab4, 2e-6);
    s.scheme_settings.startup_substeps = substeps;
    dem::Simulation sim(s);
    ASSERT_EQ(sim.past_states_needed(), 3U);
    const double start = sim.energy().balance();
    double scale = scale_of(sim.energy());
    for (int n = 0; n < 3; ++n) {
      sim.step();
      scale = std::max(scale, scale_of(sim.energy()));
    }
    EXPECT_LT(std::abs(sim.energy().balance() - start), 1e-12 * scale) << substeps << " sub-steps";
  }
}

TEST(EnergyBalance, TheCheckCanFail) {
  // The check can fail: under a multi-step scheme the ledger falls back to the trapezoid rule,
  // which does not match the scheme's velocity update, and the balance drifts far above
  // round-off on the same scene.
  dem::SimulationSetup s = random_scene(1, Law::linear_cohesion, dem::SchemeId::ab2, 2e-6);
  EXPECT_GT(balance_drift(s, 1500), 1e-9);
}

/// A JKR approach, rebound and rupture of two spheres (Δt = dt): the ledger at the end and the
/// largest |integration error| on the way.
struct PullOff {
  dem::EnergyLedger end;
  double worst_error = 0.0;
};
PullOff jkr_pulloff(double dt) {
  dem::SimulationSetup s;
  dem::MaterialProperties m = grain("grain", 0.05);
  s.materials = {m};
  s.model.normal = "hertz";
  s.model.cohesion = "jkr";
  // Sphere 1 approaches sphere 0 (fixed, drifting away under a prescribed motion), snaps in,
  // rebounds and breaks the neck: both jumps of the JKR potential happen within the run.
  s.particles = {dem::ParticleInit{0.001, 0.001, 2500.0, 0, dem::Vec3::Zero(), dem::Vec3::Zero(), dem::Vec3::Zero(), true},
                 dem::ParticleInit{0.001, 0.001, 2500.0, 0, dem::Vec3(0.00201, 0, 0), dem::Vec3(-0.05, 0, 0),
                                   dem::Vec3::Zero(), false}};
  s.motions = {dem::PrescribedMotion{0, dem::Vec3::Zero(), {dem::MotionSegment{1.0, dem::Vec3(-0.02, 0, 0)}}}};
  s.scheme = dem::SchemeId::velocity_verlet;
  s.scheme_settings.rotation = false;
  s.scheme_settings.length_scale = 0.001;
  s.timestep = dt;
  dem::Simulation sim(s);
  PullOff out;
  while (sim.time() < 4e-3) {
    sim.step();
    out.worst_error = std::max(out.worst_error, std::abs(sim.energy().integration_error));
  }
  out.end = sim.energy();
  return out;
}

TEST(EnergyBalance, JkrSnapInAndRuptureAreBookedAndTheIntegrationErrorConverges) {
  const PullOff coarse_run = jkr_pulloff(2e-7);
  const PullOff fine_run = jkr_pulloff(1e-7);
  const dem::EnergyLedger& fine = fine_run.end;
  // Snap-in releases 1.2πγa₀² (a₀³ = 4πγR*²/E*), the break at δ_c another 0.8πγa_c²; here
  // E* = E/(2(1 − ν²)) and R* = r/2.
  const dem::laws::JkrParameters p{1e7 / (2.0 * (1.0 - 0.09)), 0.0005, 0.05};
  const double snap_in = -dem::laws::jkr_energy_at_ratio(
      dem::laws::jkr_radius_ratio(0.0, p, dem::laws::jkr_critical_radius(p)), dem::laws::jkr_critical_radius(p), p);
  const double a_c = dem::laws::jkr_critical_radius(p);
  const double rupture = 0.8 * std::numbers::pi * p.surface_energy * a_c * a_c;
  EXPECT_NEAR(fine.dissipated_adhesion, snap_in + rupture, 1e-9 * (snap_in + rupture));
  EXPECT_NEAR(snap_in, 1.2 * std::numbers::pi * 0.05 *
                           std::pow(std::cbrt(4.0 * std::numbers::pi * 0.05 * 0.0005 * 0.0005 / p.effective_modulus), 2),
              1e-9 * snap_in);
  EXPECT_EQ(fine.elastic, 0.0);  // apart at the end
  // Without the two jumps booked, the integration error would tend to their sum, not to zero:
  // the scheme is first order across the force jumps, so halving Δt halves it.
  EXPECT_LT(coarse_run.worst_error, 0.05 * (snap_in + rupture));
  EXPECT_LT(fine_run.worst_error, 0.6 * coarse_run.worst_error);
  EXPECT_GT(fine_run.worst_error, 0.0);
}

TEST(EnergyBalance, IntegrationErrorOfAConservativeCollisionFallsAsDtSquared) {
  // Elastic Hertz head-on collision under velocity Verlet: a second-order scheme, so the energy
  // it creates within the contact shrinks fourfold when Δt halves.
  const auto run = [](double dt) {
    dem::SimulationSetup s;
    s.materials = {grain("grain", 0.0)};
    s.model.normal = "hertz";
    s.particles = {dem::ParticleInit{0.001, 0.001, 2500.0, 0, dem::Vec3::Zero(), dem::Vec3(0.1, 0, 0), dem::Vec3::Zero(), false},
                   dem::ParticleInit{0.001, 0.001, 2500.0, 0, dem::Vec3(0.00201, 0, 0), dem::Vec3(-0.1, 0, 0),
                                     dem::Vec3::Zero(), false}};
    s.scheme = dem::SchemeId::velocity_verlet;
    s.scheme_settings.rotation = false;
    s.scheme_settings.length_scale = 0.001;
    s.timestep = dt;
    dem::Simulation sim(s);
    double worst = 0.0;
    while (sim.time() < 2e-4) {
      sim.step();
      worst = std::max(worst, std::abs(sim.energy().integration_error));
    }
    return worst;
  };
  const double coarse = run(4e-8);
  const double fine = run(2e-8);
  EXPECT_GT(coarse / fine, 3.5);
  EXPECT_LT(coarse / fine, 4.5);
}

/// A sphere dropped on a floor at 2 m/s under velocity Verlet (no gravity): the ledger at the
/// end, the deepest overlap, and the largest |integration error| on the way.
struct FloorDrop {
  dem::EnergyLedger end;
  double deepest = 0.0;
  double worst_error = 0.0;
  double spring_at_parting = 0.0;  ///< tangential + rolling spring energy at the last commit in contact
};

/// Radius [m] and density [kg/m³] of the sphere of the floor scenes.
constexpr double kFloorSphereRadius = 0.01;
constexpr double kFloorSphereDensity = 1000.0;

/// One sphere of the floor scenes (`position`, `velocity`, `spin`) over the floor z = 0, the grain
/// stiffened for it (k_n = 1e5 N/m, k_t = 2/7 k_n, rolling 1e3 N·m/rad), under velocity Verlet at `dt`.
dem::SimulationSetup floor_scene(const dem::ModelChoice& model, const dem::Vec3& position, const dem::Vec3& velocity,
                                 const dem::Vec3& spin, double dt) {
  dem::SimulationSetup s;
  dem::MaterialProperties m = grain("grain", 0.0);
  m.normal_stiffness = 1e5;
  m.tangential_stiffness = 2.0 / 7.0 * 1e5;
  m.rolling_stiffness = 1e3;
  s.materials = {m};
  s.model = model;
  s.particles = {dem::ParticleInit{kFloorSphereRadius, kFloorSphereRadius, kFloorSphereDensity, 0, position, velocity,
                                   spin, false}};
  s.walls = {dem::Wall{dem::Vec3::Zero(), dem::Vec3(0, 0, 1), dem::Vec3::Zero(), 0}};
  s.scheme = dem::SchemeId::velocity_verlet;
  s.scheme_settings.length_scale = kFloorSphereRadius;
  s.timestep = dt;
  return s;
}

FloorDrop floor_drop(const dem::ModelChoice& model, const dem::Vec3& velocity, double dt, bool rotation = true) {
  dem::SimulationSetup s = floor_scene(model, dem::Vec3(0, 0, 0.0101), velocity, dem::Vec3(0, 40.0, 0), dt);
  s.scheme_settings.rotation = rotation;
  dem::Simulation sim(s);
  sim.watch({dem::ContactObservation{0, 0, true, 0.0, 0.0, false}});
  FloorDrop out;
  double stored_springs = 0.0;
  while (sim.time() < 2e-3) {
    sim.step();
    const dem::ContactObservation& o = sim.force_field().observations()[0];
    const dem::EnergyLedger e = sim.energy();
    out.deepest = std::max(out.deepest, o.overlap);
    out.worst_error = std::max(out.worst_error, std::abs(e.integration_error));
    if (o.interacting) {
      // The springs' share of the stored energy: all of it minus the normal spring's.
      const double normal = model.normal == "hysteretic" ? 0.0 : 0.5 * 1e5 * o.overlap * o.overlap;
      stored_springs = e.elastic - normal;
    } else if (stored_springs != 0.0 && out.spring_at_parting == 0.0) {
      out.spring_at_parting = stored_springs;
    }
  }
  out.end = sim.energy();
  return out;
}

TEST(EnergyBalance, HystereticPlasticWorkIsBookedInClosedForm) {
  dem::ModelChoice model;
  model.normal = "hysteretic";
  const FloorDrop run = floor_drop(model, dem::Vec3(0, 0, -2.0), 1e-7);
  const double k_l = 1e5;
  const double k_u = k_l / (0.7 * 0.7);
  const double loop = 0.5 * k_l * run.deepest * run.deepest * (1.0 - k_l / k_u);
  EXPECT_NEAR(run.end.dissipated_plastic, loop, 1e-12 * loop);
  // The plastic work is all the collision loses (no dashpot): ε² of the impact energy stays.
  const double m = dem::sphere_mass(1000.0, 0.01);
  EXPECT_NEAR(run.end.dissipated_plastic, 0.5 * m * 4.0 * (1.0 - 0.49), 1e-3 * 0.5 * m * 4.0);
  EXPECT_LT(run.worst_error, 1e-4 * loop);
}

TEST(EnergyBalance, SpringsThatLetGoAtPartingAreBookedAsFriction) {
  // Oblique impact with a spinning sphere: the tangential and rolling springs still hold energy
  // when the sphere leaves the floor. Booked as dissipated friction, the integration error falls
  // with Δt; dropped, it would stay at the springs' energy.
  dem::ModelChoice model;
  model.normal = "linear";
  model.damping = "restitution";
  model.tangential = "spring_coulomb";
  model.rolling = "spring_dashpot_slider";
  const dem::Vec3 v(0.8, 0.0, -1.0);
  const FloorDrop coarse = floor_drop(model, v, 2e-7);
  const FloorDrop fine = floor_drop(model, v, 1e-7);
  ASSERT_GT(fine.spring_at_parting, 0.0);
  EXPECT_LT(fine.worst_error, 0.05 * fine.spring_at_parting);
  EXPECT_LT(fine.worst_error, 0.6 * coarse.worst_error);
}

/// A sphere sliding on a floor for 2 ms: it starts pressed into the floor by 1.5 times its resting
/// overlap, so the overlap, and with it the friction cap μF_n, swings by half while it slides, and
/// it never leaves the floor (no contact starts or ends within the run).
dem::EnergyLedger sliding_on_a_bouncing_contact(double dt, double* worst_error) {
  dem::ModelChoice model;
  model.normal = "linear";
  model.tangential = "spring_coulomb";
  const double r = kFloorSphereRadius;
  const double resting = dem::sphere_mass(kFloorSphereDensity, r) * 9.81 / 1e5;  // m g / k_n
  dem::SimulationSetup s =
      floor_scene(model, dem::Vec3(0, 0, r - 1.5 * resting), dem::Vec3(0.5, 0, 0), dem::Vec3::Zero(), dt);
  s.materials[0].tangential_damping_ratio = 0.0;
  s.fields.gravity = dem::Vec3(0, 0, -9.81);
  dem::Simulation sim(s);
  *worst_error = 0.0;
  while (sim.time() < 2e-3) {
    sim.step();
    *worst_error = std::max(*worst_error, std::abs(sim.energy().integration_error));
  }
  return sim.energy();
}

TEST(EnergyBalance, SlidingWorkIsBookedByTheTrapezoidRuleAsTheSchemeTakesIt) {
  // While a contact slides, the slider books the work of the step with the forces at both of its
  // ends, as velocity Verlet takes every force's work: with no contact starting or ending, the
  // friction the ledger books is the friction's work to round-off. Booked with the capped force
  // alone (a rectangle rule, before 2026-12-05) the error was first order in Δt, and a dense
  // granular flow accumulated it (docs/hopper.md).
  for (const double dt : {2e-7, 1e-7}) {
    double worst = 0.0;
    const dem::EnergyLedger e = sliding_on_a_bouncing_contact(dt, &worst);
    ASSERT_GT(e.dissipated_friction, 1e-5);  // μ m g v t = 1.6e-5 J: sliding all along
    EXPECT_LT(worst, 1e-9 * e.kinetic) << "dt " << dt;  // round-off of the ledger's largest term
  }
}

/// What a Mindlin contact's ledger shows over a run: the largest |integration error|, the largest
/// |integration error + stiffness_change| (what the ledger showed before it booked the stiffness
/// change), and the largest |stiffness_change|.
struct MindlinRocking {
  double worst_error = 0.0;
  double worst_unbooked = 0.0;
  double largest_change = 0.0;
};

/// A sphere pressed into a floor by 1.5 times its resting Hertz overlap and pushed along it at
/// 4 mm/s, its spin held: for 10 ms the normal contact rocks between about half and one and a half
/// times the resting overlap while the Mindlin spring (8 G* a, a = √(R δ)) loads, sticks and
/// slips. k_t follows the overlap at a slip that is not zero: the stiffness change the ledger books.
MindlinRocking mindlin_rocking(dem::MindlinForm form, double dt) {
  dem::ModelChoice model;
  model.normal = "hertz";
  model.tangential = "mindlin_8g";
  model.mindlin_form = form;
  const double r = kFloorSphereRadius;
  const double m = dem::sphere_mass(kFloorSphereDensity, r);
  const dem::MaterialProperties g = grain("grain", 0.0);
  // Sphere on a wall of the same material: E* = E / (2 (1 − ν²)), R* = r; F = 4/3 E* √R δ^{3/2}.
  const double e_star = *g.youngs_modulus / (2.0 * (1.0 - *g.poisson_ratio * *g.poisson_ratio));
  const double resting = std::pow(m * 9.81 / (4.0 / 3.0 * e_star * std::sqrt(r)), 2.0 / 3.0);
  dem::SimulationSetup s =
      floor_scene(model, dem::Vec3(0, 0, r - 1.5 * resting), dem::Vec3(0.004, 0, 0), dem::Vec3::Zero(), dt);
  s.materials[0].tangential_damping_ratio = 0.0;
  s.fields.gravity = dem::Vec3(0, 0, -9.81);
  s.scheme_settings.rotation = false;
  dem::Simulation sim(s);
  MindlinRocking out;
  while (sim.time() < 1e-2) {
    sim.step();
    const dem::EnergyLedger e = sim.energy();
    out.worst_error = std::max(out.worst_error, std::abs(e.integration_error));
    out.worst_unbooked = std::max(out.worst_unbooked, std::abs(e.integration_error + e.stiffness_change));
    out.largest_change = std::max(out.largest_change, std::abs(e.stiffness_change));
  }
  return out;
}

TEST(EnergyBalance, MindlinStiffnessChangeIsBookedAndTheIntegrationErrorConverges) {
  for (const dem::MindlinForm form : {dem::MindlinForm::incremental, dem::MindlinForm::total}) {
    SCOPED_TRACE(form == dem::MindlinForm::incremental ? "incremental" : "total");
    const MindlinRocking coarse = mindlin_rocking(form, 2e-6);
    const MindlinRocking fine = mindlin_rocking(form, 1e-6);
    // The change is there (1.2e-8 J here, against 4e-4 J of weight), and without it the ledger's
    // error would keep its size as Δt halves: a model effect, no integration error.
    ASSERT_GT(fine.largest_change, 1e-9);
    EXPECT_GT(fine.worst_unbooked, 0.9 * coarse.worst_unbooked);
    // Booked, what is left converges and is a thousandth of the change: second order for the
    // incremental form; first for the total form, whose trapezoid work mixes both ends'
    // stiffnesses while the change is booked at the step's starting slip (½ Δk Δς a step).
    EXPECT_LT(fine.worst_error, 0.6 * coarse.worst_error);
    EXPECT_LT(fine.worst_error, 1e-3 * fine.largest_change);
  }
}

TEST(EnergyBalance, AHeldSpinIsADriverWhoseWorkIsBoundaryWork) {
  // rotation = false holds ω = 40 rad/s: friction works on the spin, which no kinetic term
  // follows; booked as boundary work, the integration error still falls with Δt.
  dem::ModelChoice model;
  model.normal = "linear";
  model.damping = "restitution";
  model.tangential = "spring_coulomb";
  const dem::Vec3 v(0.2, 0.0, -1.0);
  const FloorDrop coarse = floor_drop(model, v, 2e-7, false);
  const FloorDrop fine = floor_drop(model, v, 1e-7, false);
  EXPECT_NE(fine.end.boundary_work, 0.0);
  EXPECT_LT(fine.worst_error, 0.6 * coarse.worst_error);
  EXPECT_LT(fine.worst_error, 1e-2 * std::abs(fine.end.boundary_work));
}

TEST(EnergyBalance, AMovingWallPutsInItsClosedFormWorkAndTheDashpotTakesItsShare) {
  // A wall at v_w = 1 m/s strikes a sphere at rest (linear spring, restitution e = 0.7): the
  // sphere leaves at (1 + e) v_w, the wall has done m v_w² (1 + e) and the dashpot, acting on
  // the relative motion, has taken ½ m v_w² (1 − e²).
  dem::SimulationSetup s;
  dem::MaterialProperties m = grain("grain", 0.0);
  m.normal_stiffness = 1e5;
  s.materials = {m};
  s.model.normal = "linear";
  s.model.damping = "restitution";
  s.particles = {dem::ParticleInit{0.01, 0.01, 1000.0, 0, dem::Vec3(0, 0, 0.0101), dem::Vec3::Zero(), dem::Vec3::Zero(), false}};
  s.walls = {dem::Wall{dem::Vec3::Zero(), dem::Vec3(0, 0, 1), dem::Vec3(0, 0, 1.0), 0}};
  s.scheme = dem::SchemeId::velocity_verlet;
  s.scheme_settings.rotation = false;
  s.scheme_settings.length_scale = 0.01;
  s.timestep = 1e-7;
  dem::Simulation sim(s);
  while (sim.time() < 1.5e-3) sim.step();
  const dem::EnergyLedger e = sim.energy();
  const double mass = dem::sphere_mass(1000.0, 0.01);
  EXPECT_NEAR(sim.state().velocity(2, 0), 1.7, 2e-3);
  EXPECT_NEAR(e.boundary_work, mass * 1.7, 2e-3 * mass * 1.7);
  EXPECT_NEAR(e.dissipated_damping, 0.5 * mass * (1.0 - 0.49), 2e-3 * 0.5 * mass);
  EXPECT_NEAR(e.kinetic, 0.5 * mass * 1.7 * 1.7, 4e-3 * 0.5 * mass * 1.7 * 1.7);
}

TEST(EnergyBalance, DragWorkIsAllTheKineticEnergyASphereLosesInStillFluid) {
  // Only drag acts: its work is exactly the change of kinetic energy, and nothing is left for
  // the integration error.
  dem::SimulationSetup s;
  s.materials = {grain("grain", 0.0)};
  s.particles = {dem::ParticleInit{0.0005, 0.0005, 2500.0, 0, dem::Vec3::Zero(), dem::Vec3(2.0, 0.5, 0.0), dem::Vec3::Zero(), false}};
  dem::Fluid water;
  water.density = 1000.0;
  water.viscosity = 1e-3;
  water.virtual_mass = true;
  s.fields.fluid = water;
  s.scheme = dem::SchemeId::velocity_verlet;
  s.scheme_settings.length_scale = 0.0005;
  s.timestep = 1e-5;
  dem::Simulation sim(s);
  const double start = sim.energy().kinetic;
  for (int n = 0; n < 2000; ++n) sim.step();
  const dem::EnergyLedger e = sim.energy();
  EXPECT_LT(e.kinetic, 0.9 * start);
  EXPECT_NEAR(e.fluid_work, e.kinetic - start, 1e-12 * start);
  EXPECT_LT(std::abs(e.integration_error), 1e-12 * start);
}

}  // namespace energy_balance_test
