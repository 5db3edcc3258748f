// SPDX-License-Identifier: MIT
#include "reference/yade/run_plan.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "cases/core_wall.hpp"
#include "cases/trace.hpp"
#include "dem/contact/wall.hpp"
#include "reference/common/core_setup.hpp"
#include "reference/common/wall_state.hpp"
#include "cases/time_step.hpp"

namespace reference::yade {
namespace {

/// True when particle i overlaps another particle or a wall at t = 0 (δ > 0: the core's contact
/// rule, and YADE's for a new contact). All pairs, O(N²): fine for the small scenes YADE runs.
bool starts_in_contact(const cases::Scene& scene, std::size_t i) {
  const auto& p = scene.particles[i];
  for (std::size_t j = 0; j < scene.particles.size(); ++j) {
    if (j == i) continue;
    const auto& q = scene.particles[j];
    const double dx = p.position[0] - q.position[0];
    const double dy = p.position[1] - q.position[1];
    const double dz = p.position[2] - q.position[2];
    if (p.radius + q.radius - std::sqrt(dx * dx + dy * dy + dz * dz) > 0.0) return true;
  }
  const dem::Vec3 x(p.position[0], p.position[1], p.position[2]);
  for (const auto& w : scene.walls) {
    if (wall_in_run(w) && p.radius - dem::wall_frame(cases::core_wall(w), x, 0.0).distance > 0.0) return true;
  }
  return false;
}

/// True when the scene's velocities are already v(−Δt/2) (the matched set-up).
bool declares_half_step_velocities(const cases::Scene& scene) {
  return scene.integration.scheme == dem::SchemeId::leapfrog &&
         scene.integration.leapfrog_start == dem::LeapfrogStart::given_is_half_step;
}

}  // namespace

std::vector<std::string> trace_columns(const cases::Scene& scene) {
  return cases::trace_layout(scene).columns();
}

std::vector<std::uint64_t> snapshot_iterations(std::vector<double> times, double dt,
                                               std::uint64_t steps) {
  std::sort(times.begin(), times.end());
  std::vector<std::uint64_t> out;
  std::uint64_t n = 0;
  for (const double t : times) {
    const double first = std::floor((t - 0.5 * dt) / dt) - 1.0;  // a step or two early, then walk
    if (first > static_cast<double>(steps)) break;
    if (first > static_cast<double>(n)) n = static_cast<std::uint64_t>(first);
    while (n <= steps && !(static_cast<double>(n) * dt >= t - 0.5 * dt)) ++n;
    if (n > steps) break;
    out.push_back(n);
  }
  return out;
}

StartVelocities start_velocities(const cases::Scene& scene, double dt) {
  StartVelocities out;
  for (const auto& p : scene.particles) out.velocity.push_back(p.velocity);
  if (declares_half_step_velocities(scene)) {
    out.convention =
        "the scene's velocities are v(−Δt/2) (leapfrog_start = given_is_half_step) and are given "
        "to YADE unchanged";
    return out;
  }
  const cases::Vector3& g = scene.gravity;
  const bool gravity = g[0] != 0.0 || g[1] != 0.0 || g[2] != 0.0;
  std::vector<std::size_t> in_contact;
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    if (scene.particles[i].fixed) continue;
    if (starts_in_contact(scene, i)) {
      in_contact.push_back(i);
      continue;
    }
    if (!gravity) continue;
    for (std::size_t k = 0; k < 3; ++k) out.velocity[i][k] = scene.particles[i].velocity[k] - 0.5 * dt * g[k];
  }
  out.convention = gravity ? "v(−Δt/2) = v(0) − Δt/2·g for particles that start free of contacts "
                             "(a(0) = g exactly)"
                           : "v(−Δt/2) = v(0) for particles that start free of contacts (a(0) = 0)";
  if (!in_contact.empty()) {
    std::string ids;
    for (const auto i : in_contact) ids += (ids.empty() ? "" : ", ") + std::to_string(i);
    out.convention += "; particles starting in contact keep v(0) as v(−Δt/2)";
    out.warnings.push_back(fmt::format(
        "particles {} start in contact: their a(0) depends on the contact law, so YADE starts them "
        "with v(0) as its half-step velocity v(−Δt/2) — a start error of Δt/2·a(0) in velocity",
        ids));
  }
  return out;
}

YadeRunPlan make_run_plan(const PreparedScene& prepared) {
  const cases::Scene& scene = prepared.scene();
  YadeRunPlan plan;
  const CoreSetup setup = core_setup(prepared);
  plan.timestep = setup.simulation.timestep;
  plan.steps = cases::step_count(scene.integration.duration, plan.timestep);
  plan.snapshot_iterations = snapshot_iterations(scene.output.snapshot_times, plan.timestep, plan.steps);
  plan.trace_columns = trace_columns(scene);
  plan.model = map_contact_model(prepared);
  plan.calibration = plan_calibration(scene, plan.model, plan.steps);
  if (plan.model.viscous && plan.model.python_cohesion && scene.model.damping == "restitution") {
    // Without cohesion the driver calibrates betan on a two-body YADE run; the cohesion is a
    // Python force of the main script only, so the calibration run could not include it.
    plan.inexpressible_metrics["restitution"] =
        "YADE's FrictVisco dashpot acts on α·u_n, α = (r_p + r_q)/(r_p + r_q − δ) "
        "(ScGeom::getIncidentVel with noRatch), so the textbook betan rebounds below ε; the driver "
        "calibrates betan on a two-body YADE run, which cannot include the linear cohesion the "
        "script adds as a per-step Python force. A known convention gap: linear_cohesion_pair "
        "rebounds at 0.78695 against ε = 0.78815, and the matched run (the core with α) "
        "reproduces YADE's value bit for bit";
  }
  StartVelocities start = start_velocities(scene, plan.timestep);
  plan.start_velocities = std::move(start.velocity);

  plan.warnings = setup.warnings;
  for (auto& w : start.warnings) plan.warnings.push_back(std::move(w));
  for (const auto& w : plan.model.warnings) plan.warnings.push_back(w);

  auto& c = plan.conventions;
  c = plan.model.conventions;
  c["integrator"] =
      "YADE NewtonIntegrator: leapfrog with half-step velocities, v(n+½) = v(n−½) + Δt (F(x_n)/m + g), "
      "x(n+1) = x(n) + Δt v(n+½); velocity-dependent forces see v(n−½)";
  c["global damping"] = "NewtonIntegrator(damping=0) set explicitly (YADE's default is 0.2)";
  c["timestep"] = fmt::format("{:.6g} s, the in-house core's resolved step; {} steps", plan.timestep,
                              plan.steps);
  c["start velocity"] = start.convention;
  c["trace sampling"] =
      "a PyRunner between InteractionLoop and NewtonIntegrator (iterPeriod = trace_every, "
      "initRun = True) records iteration n: x(n), v(n−½), F(x(n)), i.e. the in-house row k at "
      "t = n Δt; the time column is O.iter·O.dt (O.time, a running sum of O.dt, differs by round-off)";
  c["trace velocity"] = "half-step velocity v(t − Δt/2) (State.vel)";
  c["trace force"] =
      "O.forces.f(id) (contact forces YADE summed) plus m·g for mobile particles (NewtonIntegrator "
      "adds gravity as an acceleration)";
  c["trace contact"] =
      "overlap = ScGeom.penetrationDepth and fn = FrictPhys.normalForce·ScGeom.normal (total normal "
      "force YADE applied) while the interaction is real; otherwise r_p + r_q − |x_p − x_q| from "
      "YADE's positions and fn = 0";
  c["contact onset"] = "a new contact needs δ > 0 (Ig2_Sphere_Sphere_ScGeom); an existing one acts "
                       "while δ ≥ 0 (the Law2 erases it at δ < 0)";
  c["pair parameters"] =
      "kn (and betan) per material pair from the workbench pair table, via MatchMaker(matches=…) "
      "for every pair; YADE's own mixing is not used";
  c["mass"] = "State.mass = 4/3 π ρ r³ and inertia 2/5 m r² set to the workbench's values "
              "(utils.sphere computes the same formula in another operation order)";
  c["fixed particles"] =
      "utils.sphere(fixed=True): non-dynamic, all DOFs blocked; infinite-mass partner (FrictViscoPhys "
      "uses the mobile body's mass as m̄)";
  c["rotation"] = scene.integration.rotation
                      ? "integrated by NewtonIntegrator (spherical leapfrog)"
                      : "blocked (State.blockedDOFs = 'XYZ'): angular velocities keep their initial values";
  c["restitution calibration"] =
      plan.calibration
          ? "FrictViscoMat.betan calibrated by secant on two-body YADE runs so that YADE's rebound "
            "is the case's ε (table in the run's calibrations); YADE's α-scaled dashpot and the "
            "leapfrog's O(Δt) error are absorbed in it"
          : "none: YADE's own damping convention (the registry's mapping) is used as is";
  c["invocation"] =
      "python3.11 imports yade as a module (no `yade` launcher, so no TCP prompt or XMLRPC server)";
  c["threads"] = "OMP_NUM_THREADS=1";
  return plan;
}

}  // namespace reference::yade
