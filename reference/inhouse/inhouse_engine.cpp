// SPDX-License-Identifier: MIT
#include "reference/inhouse/inhouse_engine.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "dem/integrators/scheme.hpp"
#include "reference/common/core_setup.hpp"
#include "support/build_info.hpp"
#include "cases/time_step.hpp"

namespace reference {
namespace {

/// Energy trace columns: time, then the ledger.
cases::Trace make_energy_trace() {
  cases::Trace trace;
  trace.add_column("time");
  for (const auto name : cases::kEnergyQuantities) trace.add_column(std::string(name));
  return trace;
}

/// Appends the energy ledger at the simulation's current time.
void record_energy(const dem::Simulation& sim, cases::Trace& trace) {
  const dem::EnergyLedger& e = sim.energy();
  trace.append_row({sim.time(), e.kinetic, e.elastic, e.cohesive, e.gravitational,
                    e.dissipated_damping, e.dissipated_friction, e.dissipated_adhesion,
                    e.dissipated_plastic, e.stiffness_change, e.fluid_work, e.boundary_work,
                    e.integration_error, e.balance()});
}

/// The contacts the trace reports, pairs first, then particle–wall contacts.
std::vector<dem::ContactObservation> watched_contacts(const cases::Scene& scene) {
  std::vector<dem::ContactObservation> out;
  for (const auto& [p, q] : scene.output.trace_pairs) {
    out.push_back({static_cast<std::uint32_t>(p), static_cast<std::uint32_t>(q), false, 0.0, 0.0, false});
  }
  for (const auto& [p, w] : scene.output.trace_walls) {
    out.push_back({static_cast<std::uint32_t>(p), static_cast<std::uint32_t>(w), true, 0.0, 0.0, false});
  }
  return out;
}

/// A whole-scene quantity of cases::kAggregateQuantities at the simulation's current state.
double aggregate(const dem::Simulation& sim, std::string_view quantity) {
  const dem::ParticleProperties& props = sim.particles();
  const dem::KinematicState& s = sim.state();
  if (quantity == "coordination_number") {
    const auto n = static_cast<double>(props.size());
    return n > 0.0 ? 2.0 * static_cast<double>(sim.force_field().touching_pairs()) / n : 0.0;
  }
  const bool rotational = quantity == "rotational_energy";
  double sum = 0.0;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(props.size()); ++i) {
    if (props.fixed[static_cast<std::size_t>(i)] != 0) continue;
    sum += rotational ? 0.5 * props.inertia[i] * s.angular_velocity.col(i).squaredNorm()
                      : 0.5 * props.mass[i] * s.velocity.col(i).squaredNorm();
  }
  return sum;
}

/// Appends the simulation's current state as one trace row.
void record(const cases::Scene& scene, const dem::Simulation& sim, cases::Trace& trace) {
  std::vector<double> row;
  row.reserve(trace.columns().size());
  row.push_back(sim.time());
  const dem::KinematicState& s = sim.state();
  const dem::Vec3Array& force = sim.force_field().forces();
  for (const std::size_t i : scene.output.trace_particles) {
    const auto c = static_cast<Eigen::Index>(sim.slot(static_cast<std::uint32_t>(i)));
    for (const dem::Vec3Array* field : {&s.position, &s.velocity, &s.angular_velocity, &force}) {
      for (Eigen::Index k = 0; k < 3; ++k) row.push_back((*field)(k, c));
    }
  }
  for (const auto& o : sim.force_field().observations()) {  // pairs, then walls
    row.push_back(o.overlap);
    row.push_back(o.normal_force);
  }
  for (const std::string& a : scene.output.trace_aggregates) row.push_back(aggregate(sim, a));
  trace.append_row(row);
}

/// Full particle state at the simulation's current time.
cases::Snapshot snapshot(const dem::Simulation& sim) {
  cases::Snapshot snap;
  snap.time = sim.time();
  const dem::KinematicState& s = sim.state();
  for (Eigen::Index id = 0; id < s.position.cols(); ++id) {
    const auto i = static_cast<Eigen::Index>(sim.slot(static_cast<std::uint32_t>(id)));
    snap.position.push_back({s.position(0, i), s.position(1, i), s.position(2, i)});
    snap.velocity.push_back({s.velocity(0, i), s.velocity(1, i), s.velocity(2, i)});
    snap.angular_velocity.push_back(
        {s.angular_velocity(0, i), s.angular_velocity(1, i), s.angular_velocity(2, i)});
  }
  return snap;
}

/// Gives a multi-step scheme exact states at t = −Δt, −2Δt, … from `exact` (the closed forms).
void supply_exact_past(const PreparedScene& prepared, const ExactStates& exact, dem::Simulation& sim) {
  const std::size_t needed = sim.past_states_needed();
  if (needed == 0) return;
  if (!exact) {
    throw std::runtime_error(
        "integration.startup = \"exact\" needs the analytic solution of the scene, which this "
        "engine was not given (make it with reference::make_engine(\"inhouse\"))");
  }
  std::vector<double> times;
  for (std::size_t k = 1; k <= needed; ++k) times.push_back(-static_cast<double>(k) * sim.timestep());
  std::vector<dem::KinematicState> past;
  try {
    for (const auto& snap : exact(prepared, times)) past.push_back(to_state(snap));
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(
        std::string("integration.startup = \"exact\" needs the analytic solution of the scene, "
                    "which is not available: ") + e.what());
  }
  sim.set_exact_past(past);
}

/// The conventions this run used, for reports.
std::map<std::string, std::string> conventions(const cases::Scene& scene, const CoreSetup& setup) {
  const dem::SchemeInfo& info = dem::scheme_info(scene.integration.scheme);
  std::map<std::string, std::string> c;
  c["integrator"] = fmt::format("{} ({})", info.name, info.source);
  c["timestep"] = fmt::format("{:.6g} s ({})", setup.simulation.timestep,
                              scene.integration.timestep ? "fixed" : "automatic");
  c["contact onset"] = "a pair interacts while its overlap δ > 0 (strictly)";
  c["trace velocity"] = scene.integration.scheme == dem::SchemeId::leapfrog
                            ? "half-step velocity v(t − Δt/2), as YADE reports it"
                            : "velocity at the sample time";
  c["multistep start-up"] = scene.integration.startup == dem::StartupPolicy::exact
                                ? "exact past states from the analytic solution"
                                : fmt::format("RK4, {} sub-steps per step",
                                              scene.integration.startup_substeps);
  c["rotation"] = scene.integration.rotation ? "integrated" : "held at initial values";
  return c;
}

}  // namespace

std::optional<std::string> InhouseEngine::version() const {
  return fmt::format("dem-workbench {} ({})", support::kVersion, support::kGitCommit);
}

Support InhouseEngine::supports(const PreparedScene&) const { return {}; }

cases::RunResult InhouseEngine::run(const PreparedScene& prepared, const RunOptions& options) const {
  const cases::Scene& scene = prepared.scene();
  const CoreSetup setup = core_setup(prepared, options.threads);
  dem::Simulation sim(setup.simulation);
  if (scene.integration.startup == dem::StartupPolicy::exact) supply_exact_past(prepared, exact_, sim);
  sim.watch(watched_contacts(scene));

  cases::RunResult result;
  result.status = cases::RunStatus::ok;
  result.trace = cases::trace_layout(scene);
  const double dt = sim.timestep();
  const std::uint64_t steps = cases::step_count(scene.integration.duration, dt);
  // The same steps every engine snapshots at (cases::snapshot_steps).
  const std::vector<std::uint64_t> snapshot_at = cases::snapshot_steps(scene.output.snapshot_times, dt, steps);
  std::size_t next_snapshot = 0;
  const auto take_snapshots = [&](std::uint64_t n) {
    while (next_snapshot < snapshot_at.size() && snapshot_at[next_snapshot] == n) {
      result.snapshots.push_back(snapshot(sim));
      ++next_snapshot;
    }
  };

  const bool energy = scene.output.trace_energy;
  if (energy) result.energy = make_energy_trace();
  const auto record_all = [&] {
    record(scene, sim, result.trace);
    if (energy) record_energy(sim, result.energy);
  };
  record_all();
  take_snapshots(0);
  // Whole stretches between outputs (Simulation::advance: the same states as step by step).
  std::uint64_t n = 0;
  while (n < steps) {
    const std::uint64_t every = scene.output.trace_every;
    std::uint64_t to = std::min(steps, (n / every + 1) * every);
    if (next_snapshot < snapshot_at.size()) to = std::min(to, std::max(snapshot_at[next_snapshot], n + 1));
    sim.advance(to - n);
    n = to;
    if (n % every == 0) record_all();
    take_snapshots(n);
  }

  result.warnings = setup.warnings;
  if (energy && !sim.books_work_exactly()) {
    result.warnings.push_back(fmt::format(
        "output.trace_energy: scheme '{}' states no weights for its force evaluations, so the energy "
        "ledger books work with the trapezoid rule and its balance moves at the order of the scheme's "
        "error (docs/physics.md, \"Energy ledger\")",
        dem::scheme_info(scene.integration.scheme).keyword));
  }
  if (const auto bad = sim.diagnostics().unconverged_steps; bad > 0) {
    result.warnings.push_back(fmt::format(
        "integration.implicit_tolerance: {} implicit steps did not converge within {} iterations",
        bad, scene.integration.implicit_max_iterations));
  }
  result.conventions = conventions(scene, setup);
  return result;
}

}  // namespace reference
