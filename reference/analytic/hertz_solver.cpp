// SPDX-License-Identifier: MIT
#include "reference/analytic/hertz_solver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <map>
#include <optional>
#include <stdexcept>
#include <variant>

#include <fmt/format.h>

#include "cases/time_step.hpp"
#include "dem/contact/contact_model.hpp"
#include "dem/contact/laws/hertz.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/particles/particles.hpp"
#include "reference/analytic/collinear_scene.hpp"
#include "reference/analytic/collinear_solver.hpp"
#include "reference/analytic/hertz_elastic.hpp"
#include "reference/analytic/two_body_ode.hpp"
#include "reference/analytic/vector3_math.hpp"
#include "reference/common/core_setup.hpp"
#include "reference/analytic/model_support.hpp"

namespace reference::analytic {
namespace {

/// What the Hertz two-body solution solves: the Hertz spring with any dashpot (clamped or not),
/// frictionless, no cohesion, no rolling resistance.
const ModelSupport kHertzModel{"Hertz two-body", {"hertz"}, {}, {"none"}, {"none"}, {"none"}, true};

using cases::Vector3;

/// Relative tolerance of the head-on checks.
constexpr double kHeadOnTolerance = 1e-12;
/// Tolerance of the damped-contact integration (relative and absolute, scaled variables).
constexpr double kOdeTolerance = 1e-12;

/// A reason, prefixed so that reports say which analytic solver declined.
template <class... Args>
std::string reason(fmt::format_string<Args...> text, Args&&... args) {
  return "analytic (Hertz two-body): " + fmt::format(text, std::forward<Args>(args)...);
}

/// The two bodies of a supported scene, reduced to their overlap δ(t) along the fixed normal.
struct HertzPair {
  enum class Kind { fixed_sphere, wall, two_mobile };
  Kind kind = Kind::fixed_sphere;
  std::size_t first = 0;          ///< the (first) mobile sphere
  std::size_t second = 0;         ///< the partner particle, or the wall index
  Vector3 normal{};               ///< n from the partner towards `first` (a wall's own normal)
  double reduced_mass = 0.0;      ///< m* [kg] (the mobile mass against a fixed body)
  double reduced_radius = 0.0;    ///< R* [m] (r against a wall)
  double contact_distance = 0.0;  ///< r_p + r_q (r against a wall) [m]
  double effective_modulus = 0.0; ///< E* [Pa] of the pair
  double initial_overlap = 0.0;   ///< δ(0) [m], ≤ 0 for a supported scene
  double approach_speed = 0.0;    ///< δ'(0) = −(u_first − u_partner)·n [m/s]
  double first_share = 1.0;       ///< share of a separation change that moves `first`
  double second_share = 0.0;      ///< share that moves `second` (two mobile spheres)
  Vector3 centre_of_mass_velocity{};
  dem::PairLaw law;
};


/// Reasons against the fields and the particles' extras.
void check_environment(const cases::Scene& scene, std::vector<std::string>& reasons) {
  const Vector3& g = scene.gravity;
  if (g[0] != 0.0 || g[1] != 0.0 || g[2] != 0.0) {
    reasons.push_back(reason("gravity ({}, {}, {}) m/s² must be exactly zero", g[0], g[1], g[2]));
  }
  if (scene.fluid) reasons.push_back(reason("a fluid (drag, buoyancy) is not supported"));
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    if (!scene.particles[i].motion.empty()) {
      reasons.push_back(reason("particle {} has a prescribed motion", i));
    }
  }
}

/// Reasons against the layout: exactly two bodies, colliding head-on.
void check_hertz_layout(const cases::Scene& scene, std::vector<std::string>& reasons) {
  const std::size_t n = scene.particles.size();
  for (std::size_t i = 0; i < n; ++i) {
    const cases::ParticleSpec& p = scene.particles[i];
    if (p.material >= scene.materials.size()) {
      reasons.push_back(reason("particle {} names material {}, which does not exist", i, p.material));
    }
    if (!(p.radius > 0.0) || !std::isfinite(p.radius)) {
      reasons.push_back(reason("particle {} has radius {} m; need r > 0", i, p.radius));
    }
    if (p.fixed && norm(p.velocity) != 0.0) {
      reasons.push_back(reason("fixed particle {} moves; a fixed sphere must be at rest", i));
    }
  }
  for (std::size_t w = 0; w < scene.walls.size(); ++w) {
    if (norm(scene.walls[w].velocity) != 0.0) {
      reasons.push_back(reason("wall '{}' moves; only walls at rest are supported", scene.walls[w].name));
    }
  }
  const std::size_t mobile = static_cast<std::size_t>(
      std::count_if(scene.particles.begin(), scene.particles.end(), [](const auto& p) { return !p.fixed; }));
  const bool sphere_pair = n == 2 && scene.walls.empty() && mobile >= 1;
  const bool sphere_wall = n == 1 && scene.walls.size() == 1 && mobile == 1;
  if (!sphere_pair && !sphere_wall) {
    reasons.push_back(reason(
        "{} particles ({} mobile) and {} walls; solved are exactly two bodies: a mobile sphere "
        "with a fixed sphere, two mobile spheres, or one mobile sphere and one plane wall",
        n, mobile, scene.walls.size()));
    return;
  }
  if (!reasons.empty()) return;
  const cases::ParticleSpec& p = scene.particles[0];
  Vector3 normal{};
  Vector3 relative = p.velocity;
  double overlap = 0.0;
  if (sphere_wall) {
    const cases::WallSpec& w = scene.walls[0];
    normal = scaled(w.normal, 1.0 / norm(w.normal));
    overlap = p.radius - dot(minus(p.position, w.point), normal);
  } else {
    const cases::ParticleSpec& q = scene.particles[1];
    const Vector3 x = minus(p.position, q.position);
    const double distance = norm(x);
    if (!(distance > 0.0)) {
      reasons.push_back(reason("particles 0 and 1 have coincident centres"));
      return;
    }
    normal = scaled(x, 1.0 / distance);
    relative = minus(p.velocity, q.velocity);
    overlap = p.radius + q.radius - distance;
  }
  // Against a plane wall the normal is fixed, so a frictionless sphere's motion along the wall
  // is uniform and decouples from the contact: oblique impacts are solved. Between two spheres
  // an oblique approach turns the line of centres, so only head-on collisions are.
  const double off = off_line(relative, normal);
  if (!sphere_wall && off > kHeadOnTolerance * norm(relative)) {
    reasons.push_back(reason("the relative velocity has a {:.3g} m/s part across the contact "
                             "normal; only head-on collisions are solved",
                             off));
  }
  if (overlap > 0.0) {
    reasons.push_back(reason("the bodies overlap by {:.3g} m at t = 0; the contact must start "
                             "during the run",
                             overlap));
  }
}


/// The reduction of a scene whose model and layout passed the checks.
HertzPair reduce(const cases::Scene& scene, const dem::PairTable& table) {
  HertzPair h;
  const cases::ParticleSpec& p0 = scene.particles[0];
  if (scene.particles.size() == 1) {
    const cases::WallSpec& w = scene.walls[0];
    h.kind = HertzPair::Kind::wall;
    h.first = 0;
    h.second = 0;
    h.normal = scaled(w.normal, 1.0 / norm(w.normal));
    h.reduced_mass = particle_mass(scene, 0);
    h.reduced_radius = p0.radius;
    h.contact_distance = p0.radius;
    h.initial_overlap = p0.radius - dot(minus(p0.position, w.point), h.normal);
    h.approach_speed = -dot(p0.velocity, h.normal);
    // The velocity along the wall, untouched by a frictionless contact: the uniform part of the
    // motion (the role the centre-of-mass velocity plays for two mobile spheres).
    h.centre_of_mass_velocity = minus(p0.velocity, scaled(h.normal, dot(p0.velocity, h.normal)));
    h.law = table.law(p0.material, w.material);
  } else {
    // `first` is a mobile sphere; with two mobile spheres it is particle 0.
    const std::size_t a = p0.fixed ? 1 : 0;
    const std::size_t b = 1 - a;
    const cases::ParticleSpec& pa = scene.particles[a];
    const cases::ParticleSpec& pb = scene.particles[b];
    const Vector3 x = minus(pa.position, pb.position);
    const double distance = norm(x);
    h.first = a;
    h.second = b;
    h.normal = scaled(x, 1.0 / distance);
    h.reduced_radius = pa.radius * pb.radius / (pa.radius + pb.radius);
    h.contact_distance = pa.radius + pb.radius;
    h.initial_overlap = h.contact_distance - distance;
    h.approach_speed = -dot(minus(pa.velocity, pb.velocity), h.normal);
    h.law = table.law(pa.material, pb.material);
    const double m_a = particle_mass(scene, a);
    if (pb.fixed) {
      h.kind = HertzPair::Kind::fixed_sphere;
      h.reduced_mass = m_a;
    } else {
      const double m_b = particle_mass(scene, b);
      const double total = m_a + m_b;
      h.kind = HertzPair::Kind::two_mobile;
      h.reduced_mass = m_a * m_b / total;
      h.first_share = m_b / total;
      h.second_share = m_a / total;
      for (std::size_t c = 0; c < 3; ++c) {
        h.centre_of_mass_velocity[c] = (m_a * pa.velocity[c] + m_b * pb.velocity[c]) / total;
      }
    }
  }
  h.effective_modulus = std::get<dem::HertzNormal>(h.law.normal).effective_modulus;
  return h;
}

/// Builds the pair table and the reduction, adding reasons against the parameters.
std::optional<HertzPair> reduce_checked(const PreparedScene& prepared, std::vector<std::string>& reasons) {
  const cases::Scene& scene = prepared.scene();
  try {
    const dem::PairTable& table = prepared.pair_table();
    HertzPair h = reduce(scene, table);
    if (!(h.effective_modulus > 0.0) || !std::isfinite(h.effective_modulus)) {
      reasons.push_back(reason("the pair's effective modulus is {} Pa; need 0 < E* < ∞", h.effective_modulus));
    }
    if (!(h.reduced_mass > 0.0) || !std::isfinite(h.reduced_mass)) {
      reasons.push_back(reason("the moving mass is {} kg; need a positive density", h.reduced_mass));
    }
    if (!reasons.empty()) return std::nullopt;
    return h;
  } catch (const std::exception& e) {
    reasons.push_back(reason("{}", e.what()));
    return std::nullopt;
  }
}

/// Total normal force F(δ, δ') of the pair: Hertz plus the pair's damping sub-model, clipped at
/// ≥ 0 under clamp_tensile, as evaluate_contact composes them. η is evaluated for δ ≥ 0 (its
/// limit δ → 0⁺ at δ = 0, so the force is continuous at the end of a damped contact).
double total_force(const HertzPair& h, double overlap, double rate) {
  const double e = h.effective_modulus;
  const double r = h.reduced_radius;
  dem::NormalResponse normal{dem::laws::hertz_force(e, r, overlap),
                             dem::laws::hertz_stiffness(e, r, overlap),
                             dem::laws::hertz_energy(e, r, overlap), overlap > 0.0};
  dem::ContactGeometry g{};
  g.overlap = overlap;
  g.distance = h.contact_distance - overlap;
  g.normal_speed = -rate;
  g.reduced_mass = h.reduced_mass;
  g.reduced_radius = r;
  g.contact_distance = h.contact_distance;
  g.effect_distance = h.contact_distance;
  const double eta = std::visit([&](const auto& m) { return m.coefficient(g, normal); }, h.law.damping);
  double damping = eta * rate;
  if (h.law.policies.clamp_tensile && normal.force + damping < 0.0) damping = -normal.force;
  return normal.force + damping;
}

/// δ, δ' and F of the pair at one instant.
struct AxisState {
  double overlap = 0.0;
  double rate = 0.0;
  double force = 0.0;  ///< normal force, 0 while δ ≤ 0
};

/// Figures of the (only) contact.
struct ContactSummary {
  bool happens = false;
  bool closed_form = false;
  double start = 0.0;
  double duration = 0.0;
  double restitution = 0.0;
  double max_overlap = 0.0;
  double max_force = 0.0;
};

/// The pair's state at each of the increasing `times` [s]: free approach, the contact (closed
/// form when undamped, else the ODE), free separation.
std::vector<AxisState> axis_states(const HertzPair& h, const std::vector<double>& times,
                                   ContactSummary& summary) {
  const double v = h.approach_speed;
  const double d0 = h.initial_overlap;
  std::vector<AxisState> out(times.size());
  summary = ContactSummary{};
  if (!(v > 0.0)) {
    for (std::size_t k = 0; k < times.size(); ++k) out[k] = {d0 + v * times[k], v, 0.0};
    return out;
  }
  summary.happens = true;
  summary.start = -d0 / v;
  std::vector<double> relative;
  for (const double t : times) {
    if (t >= summary.start) relative.push_back(t - summary.start);
  }
  std::vector<AxisState> contact;  // states at the first relative times, while in contact
  double exit_rate = 0.0;
  if (std::holds_alternative<dem::NoDamping>(h.law.damping)) {
    const HertzElasticContact elastic(h.reduced_mass, h.effective_modulus, h.reduced_radius, v);
    summary.closed_form = true;
    summary.duration = elastic.duration();
    summary.max_overlap = elastic.max_overlap();
    summary.max_force = elastic.max_force();
    exit_rate = -v;
    for (const double t : relative) {
      if (t > summary.duration) break;
      const HertzElasticContact::State s = elastic.at(t);
      contact.push_back({s.overlap, s.overlap_rate, total_force(h, s.overlap, s.overlap_rate)});
    }
  } else {
    NormalContactProblem problem;
    problem.reduced_mass = h.reduced_mass;
    problem.approach_speed = v;
    problem.length_scale =
        dem::laws::hertz_max_overlap(h.reduced_mass, h.effective_modulus, h.reduced_radius, v);
    problem.force = [&h](double overlap, double rate) { return total_force(h, overlap, rate); };
    const NormalContactSolution solution = solve_normal_contact(problem, relative, kOdeTolerance);
    summary.duration = solution.duration;
    summary.max_overlap = solution.deepest.overlap;
    summary.max_force = solution.strongest.force;
    exit_rate = solution.exit_rate;
    for (const NormalContactState& s : solution.samples) contact.push_back({s.overlap, s.overlap_rate, s.force});
  }
  summary.restitution = -exit_rate / v;
  std::size_t j = 0;  // index into `relative` / `contact`
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double t = times[k];
    if (t < summary.start) {
      out[k] = {d0 + v * t, v, 0.0};
    } else if (j < contact.size()) {
      out[k] = contact[j++];
      if (!(out[k].overlap > 0.0)) out[k].force = 0.0;
    } else {
      out[k] = {exit_rate * (t - summary.start - summary.duration), exit_rate, 0.0};
    }
  }
  return out;
}

/// Every particle's state at time t, given the pair's state.
cases::Snapshot snapshot_at(const cases::Scene& scene, const HertzPair& h, double t, const AxisState& s) {
  cases::Snapshot snap;
  snap.time = t;
  for (const cases::ParticleSpec& p : scene.particles) {
    snap.position.push_back(p.position);
    snap.velocity.push_back(p.velocity);
    snap.angular_velocity.push_back(p.angular_velocity);
  }
  const double shift = h.initial_overlap - s.overlap;  // growth of the separation since t = 0
  const Vector3& n = h.normal;
  const Vector3& vcm = h.centre_of_mass_velocity;
  const auto move = [&](std::size_t i, double share) {
    const cases::ParticleSpec& p = scene.particles[i];
    for (std::size_t c = 0; c < 3; ++c) {
      snap.position[i][c] = p.position[c] + vcm[c] * t + share * shift * n[c];
      snap.velocity[i][c] = vcm[c] - share * s.rate * n[c];
    }
  };
  move(h.first, h.first_share);
  if (h.kind == HertzPair::Kind::two_mobile) move(h.second, -h.second_share);
  return snap;
}

/// Total contact force on every particle [N] (a fixed sphere receives minus what it exerts).
std::vector<Vector3> forces_at(const cases::Scene& scene, const HertzPair& h, const AxisState& s) {
  std::vector<Vector3> force(scene.particles.size(), Vector3{0.0, 0.0, 0.0});
  for (std::size_t c = 0; c < 3; ++c) {
    force[h.first][c] = s.force * h.normal[c];
    if (h.kind != HertzPair::Kind::wall) force[h.second][c] = -s.force * h.normal[c];
  }
  return force;
}

/// Appends one trace row in cases::trace_layout order.
void record(const cases::Scene& scene, const HertzPair& h, double t, const AxisState& s,
            cases::Trace& trace) {
  const cases::Snapshot snap = snapshot_at(scene, h, t, s);
  const std::vector<Vector3> force = forces_at(scene, h, s);
  std::vector<double> row;
  row.reserve(trace.columns().size());
  row.push_back(t);
  for (const std::size_t i : scene.output.trace_particles) {
    for (const auto* field : {&snap.position.at(i), &snap.velocity.at(i), &snap.angular_velocity.at(i), &force.at(i)}) {
      row.insert(row.end(), field->begin(), field->end());
    }
  }
  const bool pair = h.kind != HertzPair::Kind::wall;
  for (const auto& [p, q] : scene.output.trace_pairs) {
    if (pair && ((p == h.first && q == h.second) || (p == h.second && q == h.first))) {
      row.push_back(s.overlap);
      row.push_back(s.force);
    } else {
      const Vector3 x = minus(snap.position.at(p), snap.position.at(q));
      row.push_back(scene.particles.at(p).radius + scene.particles.at(q).radius - norm(x));
      row.push_back(0.0);
    }
  }
  for (const auto& [p, w] : scene.output.trace_walls) {
    if (!pair && p == h.first && w == h.second) {
      row.push_back(s.overlap);
      row.push_back(s.force);
    } else {
      const cases::WallSpec& wall = scene.walls.at(w);
      const Vector3 n = scaled(wall.normal, 1.0 / norm(wall.normal));
      row.push_back(scene.particles.at(p).radius - dot(minus(snap.position.at(p), wall.point), n));
      row.push_back(0.0);
    }
  }
  trace.append_row(row);
}

/// Whether the case's compared contact is the pair's contact.
bool compares_this_contact(const cases::Scene& scene, const HertzPair& h) {
  if (h.kind == HertzPair::Kind::wall) {
    return scene.compare.wall_contact && scene.compare.wall_contact->first == h.first &&
           scene.compare.wall_contact->second == h.second;
  }
  if (!scene.compare.pair || scene.compare.wall_contact) return false;
  const auto [p, q] = *scene.compare.pair;
  return (p == h.first && q == h.second) || (p == h.second && q == h.first);
}

/// The conventions of a Hertz analytic run, for reports.
std::map<std::string, std::string> conventions(const cases::Scene& scene, const HertzPair& h,
                                               double dt, std::uint64_t every) {
  std::map<std::string, std::string> c;
  const bool elastic = std::holds_alternative<dem::NoDamping>(h.law.damping);
  c["solution"] =
      elastic ? "closed form of the elastic Hertz contact: δ(t) = δ_max [I⁻¹(2/5, 1/2; 2t/t_c)]^{2/5} "
                "(Boost.Math ibetac_inv), t_c = (4/5) B(2/5, 1/2) δ_max/v, δ_max = (15 m* v²/(16 E* √R*))^{2/5}"
              : fmt::format("m* δ'' = −F(δ, δ') integrated with Boost.Odeint Dormand–Prince 5(4), "
                            "dense output, relative and absolute tolerance {:g} on δ/δ_max and δ'/v; "
                            "contact end and deepest point by TOMS 748, force peak by Brent",
                            kOdeTolerance);
  c["sampling"] = fmt::format(
      "same time points as the in-house core: t_k = k·{}·Δt with Δt = {:.6g} s", every, dt);
  switch (h.kind) {
    case HertzPair::Kind::fixed_sphere:
      c["geometry"] = fmt::format("mobile sphere {} against fixed sphere {}: m* = m = {:.6g} kg, "
                                  "R* = {:.6g} m", h.first, h.second, h.reduced_mass, h.reduced_radius);
      break;
    case HertzPair::Kind::wall:
      c["geometry"] = fmt::format("mobile sphere {} against plane wall {} at rest: m* = m = {:.6g} "
                                  "kg, R* = r = {:.6g} m; the velocity along the wall ({:.6g} m/s) is "
                                  "uniform (no friction)", h.first, h.second, h.reduced_mass,
                                  h.reduced_radius, norm(h.centre_of_mass_velocity));
      break;
    case HertzPair::Kind::two_mobile:
      c["geometry"] = fmt::format("two mobile spheres head-on: m* = {:.6g} kg, R* = {:.6g} m, "
                                  "uniform centre-of-mass motion", h.reduced_mass, h.reduced_radius);
      break;
  }
  c["contact onset"] = "a pair interacts while its overlap δ > 0 (strictly)";
  c["normal force"] = fmt::format(
      "Hertz 4/3 E* √R* δ^{{3/2}} (E* = {:.6g} Pa) plus the pair's damping sub-model '{}' "
      "(its η evaluated on the exact state){}",
      h.effective_modulus, scene.model.damping,
      h.law.policies.clamp_tensile ? ", total clipped at ≥ 0 (clamp_tensile)" : ", not clipped");
  c["trace velocity"] = "exact velocity at the sample time";
  c["fixed sphere force"] = "minus the contact force it exerts";
  return c;
}

}  // namespace

std::vector<std::string> HertzSolver::unsupported_reasons(const PreparedScene& prepared) const {
  const cases::Scene& scene = prepared.scene();
  std::vector<std::string> reasons;
  reasons = model_reasons(scene.model, kHertzModel);
  check_environment(scene, reasons);
  check_hertz_layout(scene, reasons);
  if (reasons.empty()) static_cast<void>(reduce_checked(prepared, reasons));
  return reasons;
}

cases::RunResult HertzSolver::run(const PreparedScene& prepared) const {
  const cases::Scene& scene = prepared.scene();
  std::vector<std::string> reasons;
  const std::optional<HertzPair> reduced = reduce_checked(prepared, reasons);
  if (!reduced) throw std::invalid_argument(reasons.empty() ? "unsupported scene" : reasons.front());
  const HertzPair& h = *reduced;
  const auto [dt, steps, every, t_end] = sample_grid(prepared);

  std::vector<double> times;
  for (std::uint64_t n = 0; n <= steps; n += every) times.push_back(static_cast<double>(n) * dt);
  ContactSummary summary;
  const std::vector<AxisState> states = axis_states(h, times, summary);

  cases::RunResult result;
  result.status = cases::RunStatus::ok;
  result.trace = cases::trace_layout(scene);
  for (std::size_t k = 0; k < times.size(); ++k) record(scene, h, times[k], states[k], result.trace);

  std::vector<double> snapshot_times;
  for (const std::uint64_t n : cases::snapshot_steps(scene.output.snapshot_times, dt, steps)) {
    snapshot_times.push_back(static_cast<double>(n) * dt);
  }
  ContactSummary ignored;
  const std::vector<AxisState> snapshot_states = axis_states(h, snapshot_times, ignored);
  for (std::size_t k = 0; k < snapshot_times.size(); ++k) {
    result.snapshots.push_back(snapshot_at(scene, h, snapshot_times[k], snapshot_states[k]));
  }

  result.conventions = conventions(scene, h, dt, every);
  if (compares_this_contact(scene, h)) {
    if (summary.happens && summary.start <= t_end) {
      result.exact_metrics["contact_duration"] = summary.duration;
      result.exact_metrics["restitution"] = summary.restitution;
      result.exact_metrics["max_overlap"] = summary.max_overlap;
      result.exact_metrics["max_force"] = summary.max_force;
      result.exact_metrics["tangential_force_max"] = 0.0;  // frictionless: no tangential force
      result.conventions["exact metrics"] = fmt::format(
          "contact from t = {:.9g} s: {}", summary.start,
          summary.closed_form ? "closed forms t_c = 2.868266 (m*²/(R* E*² v))^{1/5}, restitution 1, "
                                "δ_max, F(δ_max)"
                              : "located on the high-accuracy solution (duration to δ = 0, "
                                "restitution −δ'(t_c)/v, deepest point, force peak)");
    } else {
      result.warnings.push_back(fmt::format(
          "the compared contact does not start by the end of the run (t = {:.6g} s); no exact "
          "metrics", t_end));
    }
  } else if (scene.compare.pair || scene.compare.wall_contact) {
    result.warnings.push_back("the compared contact is not the two bodies' contact; no exact metrics");
  }
  return result;
}

}  // namespace reference::analytic
