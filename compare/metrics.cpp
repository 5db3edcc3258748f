// SPDX-License-Identifier: MIT
#include "compare/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "compare/metrics_breakup_run.hpp"
#include "compare/metrics_discharge.hpp"
#include "compare/metrics_packing.hpp"
#include "compare/metrics_cohesion.hpp"
#include "compare/metrics_motion.hpp"
#include "compare/trace_analysis.hpp"

namespace comparison {
namespace {

using Vec = std::array<double, 3>;

/// A metric that cannot be computed; carries the reason to the table.
struct MetricProblem : std::runtime_error {
  using std::runtime_error::runtime_error;
};

double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }

/// Column `name` of the trace, or a problem naming it.
const std::vector<double>& column(const cases::Trace& trace, const std::string& name) {
  const auto* c = trace.column(name);
  if (c == nullptr) throw MetricProblem(fmt::format("trace has no column '{}'", name));
  return *c;
}

/// Position of a prescribed motion at time t (piecewise-constant velocity from the start).
Vec motion_position(const cases::ParticleSpec& p, double t) {
  Vec x = p.position;
  double begin = 0.0;
  for (std::size_t k = 0; k < p.motion.size(); ++k) {
    const bool last = k + 1 == p.motion.size();
    const double span = last ? t - begin : std::min(p.motion[k].duration, std::max(0.0, t - begin));
    for (std::size_t c = 0; c < 3; ++c) x[c] += span * p.motion[k].velocity[c];
    if (last || t < begin + p.motion[k].duration) break;
    begin += p.motion[k].duration;
  }
  return x;
}

/// Velocity of a prescribed motion at time t.
Vec motion_velocity(const cases::ParticleSpec& p, double t) {
  double end = 0.0;
  for (std::size_t k = 0; k + 1 < p.motion.size(); ++k) {
    end += p.motion[k].duration;
    if (t < end) return p.motion[k].velocity;
  }
  return p.motion.back().velocity;
}

/// Position and velocity of one particle at every trace row. A fixed particle that is not
/// traced is taken from the case (at rest, or on its prescribed motion); any other untraced
/// particle is a problem.
class ParticleSeries {
 public:
  ParticleSeries(const cases::Scene& scene, const cases::Trace& trace, std::size_t index)
      : spec_(scene.particles.at(index)), time_(&column(trace, "time")) {
    if (trace.column(cases::particle_column(index, "x")) == nullptr) {
      if (!spec_.fixed) {
        throw MetricProblem(fmt::format("particle {} is not traced (output.trace_particles)", index));
      }
      return;
    }
    for (const char* q : {"x", "y", "z", "vx", "vy", "vz"}) {
      columns_.push_back(&column(trace, cases::particle_column(index, q)));
    }
  }
  [[nodiscard]] Vec position(std::size_t row) const {
    if (columns_.empty()) return spec_.motion.empty() ? spec_.position : motion_position(spec_, (*time_)[row]);
    return {(*columns_[0])[row], (*columns_[1])[row], (*columns_[2])[row]};
  }
  [[nodiscard]] Vec velocity(std::size_t row) const {
    if (columns_.empty()) return spec_.motion.empty() ? Vec{0.0, 0.0, 0.0} : motion_velocity(spec_, (*time_)[row]);
    return {(*columns_[3])[row], (*columns_[4])[row], (*columns_[5])[row]};
  }

 private:
  const cases::ParticleSpec& spec_;
  const std::vector<double>* time_;
  std::vector<const std::vector<double>*> columns_;
};

/// The subject particle (compare.subject, else the first mobile particle).
std::size_t subject_of(const cases::Scene& scene) {
  if (scene.compare.subject) return *scene.compare.subject;
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    if (!scene.particles[i].fixed) return i;
  }
  throw MetricProblem("the scene has no mobile particle");
}

/// The contact the metrics read: compare.pair (subject first when it belongs to it) or the
/// particle–wall contact compare.wall_contact.
struct ComparedContact {
  std::size_t p;
  std::size_t q;  ///< partner particle, or wall index when `wall`
  bool wall;

  /// Trace column of a contact quantity ("overlap", "fn").
  [[nodiscard]] std::string column_name(std::string_view quantity) const {
    return wall ? cases::wall_column(p, q, quantity) : cases::pair_column(p, q, quantity);
  }
  /// "pair 0-1" or "particle 0 and wall 2", for messages.
  [[nodiscard]] std::string label() const {
    return wall ? fmt::format("particle {} and wall {}", p, q) : fmt::format("pair {}-{}", p, q);
  }
};

ComparedContact compared_contact(const cases::Scene& scene) {
  if (scene.compare.wall_contact) {
    return {scene.compare.wall_contact->first, scene.compare.wall_contact->second, true};
  }
  if (!scene.compare.pair) throw MetricProblem("the case sets no compare.pair or compare.wall_contact");
  auto [p, q] = *scene.compare.pair;
  if (scene.compare.subject && *scene.compare.subject == q) std::swap(p, q);
  return {p, q, false};
}

/// Unit vector of the collision axis: from the subject towards its partner (or into the wall)
/// at t = 0, or along the subject's initial velocity when it is not in the compared contact.
Vec collision_axis(const cases::Scene& scene) {
  const std::size_t s = subject_of(scene);
  Vec axis = scene.particles[s].velocity;
  if (scene.compare.pair || scene.compare.wall_contact) {
    const ComparedContact c = compared_contact(scene);
    if (c.p == s) {
      if (c.wall) {
        const auto& n = scene.walls.at(c.q).normal;
        axis = {-n[0], -n[1], -n[2]};
      } else {
        axis = sub(scene.particles[c.q].position, scene.particles[c.p].position);
      }
    }
  }
  const double n = norm(axis);
  if (!(n > 0.0)) throw MetricProblem("no collision axis: the subject has no partner or velocity");
  return {axis[0] / n, axis[1] / n, axis[2] / n};
}

/// The first contact of the compared contact in a trace.
ContactInterval contact_of(const cases::Scene& scene, const cases::Trace& trace) {
  const ComparedContact cc = compared_contact(scene);
  const auto& t = column(trace, "time");
  const auto& overlap = column(trace, cc.column_name("overlap"));
  const IntervalSearch found = first_contact(t, overlap);
  if (found.interval) return *found.interval;
  switch (found.problem) {
    case IntervalProblem::starts_in_contact:
      throw MetricProblem(fmt::format("{} are already in contact at the first sample", cc.label()));
    case IntervalProblem::never_ends:
      throw MetricProblem(fmt::format("the contact of {} does not end within the run", cc.label()));
    case IntervalProblem::no_contact: break;
  }
  throw MetricProblem(fmt::format("{} never come into contact", cc.label()));
}

/// Overlap column of the compared contact and a per-row "in contact" mask.
std::pair<const std::vector<double>*, std::vector<bool>> overlap_mask(const cases::Scene& scene,
                                                                      const cases::Trace& trace) {
  const auto& overlap = column(trace, compared_contact(scene).column_name("overlap"));
  std::vector<bool> mask(overlap.size());
  for (std::size_t k = 0; k < overlap.size(); ++k) mask[k] = overlap[k] > 0.0;
  return {&overlap, std::move(mask)};
}

double contact_duration(const cases::Scene& scene, const cases::Trace& trace) {
  const ContactInterval c = contact_of(scene, trace);
  return c.end - c.start;
}

/// Normal relative speed (u_p − u_q)·n of the compared contact at a row, n from q to p (the
/// wall normal for a wall).
class NormalSpeed {
 public:
  NormalSpeed(const cases::Scene& scene, const cases::Trace& trace, const ComparedContact& c)
      : p_(scene, trace, c.p) {
    if (c.wall) {
      wall_ = &scene.walls.at(c.q);
    } else {
      q_.emplace(scene, trace, c.q);
    }
  }
  [[nodiscard]] double at(std::size_t row) const {
    if (wall_ != nullptr) return dot(sub(p_.velocity(row), wall_->velocity), wall_->normal);
    const Vec x = sub(p_.position(row), q_->position(row));
    const double d = norm(x);
    const Vec n{x[0] / d, x[1] / d, x[2] / d};
    return dot(sub(p_.velocity(row), q_->velocity(row)), n);
  }

 private:
  ParticleSeries p_;
  std::optional<ParticleSeries> q_;
  const cases::WallSpec* wall_ = nullptr;
};

double restitution(const cases::Scene& scene, const cases::Trace& trace) {
  const ContactInterval c = contact_of(scene, trace);
  const NormalSpeed speed(scene, trace, compared_contact(scene));
  const double before = speed.at(c.last_before);
  const double after = speed.at(c.first_after);
  if (!(before < 0.0)) throw MetricProblem("the contact partners are not approaching before the contact");
  return -after / before;
}

double max_of_pair_column(const cases::Scene& scene, const cases::Trace& trace,
                          const char* quantity) {
  const ContactInterval c = contact_of(scene, trace);
  const auto& t = column(trace, "time");
  const auto& y = column(trace, compared_contact(scene).column_name(quantity));
  const auto mask = overlap_mask(scene, trace).second;
  return peak(t, y, mask, c.last_before + 1, c.first_after - 1).value;
}

/// Displacement of the subject along the collision axis, row by row.
std::vector<double> displacement_along_axis(const cases::Scene& scene, const cases::Trace& trace) {
  const std::size_t s = subject_of(scene);
  const ParticleSeries series(scene, trace, s);
  const Vec axis = collision_axis(scene);
  const Vec origin = scene.particles[s].position;
  std::vector<double> out(trace.rows());
  for (std::size_t k = 0; k < trace.rows(); ++k) out[k] = dot(sub(series.position(k), origin), axis);
  return out;
}

/// Largest displacement of the subject along the collision axis over the samples.
double max_position(const cases::Scene& scene, const cases::Trace& trace) {
  const std::vector<double> d = displacement_along_axis(scene, trace);
  if (d.empty()) throw MetricProblem("the trace is empty");
  return *std::max_element(d.begin(), d.end());
}

/// Largest overlap of the compared pair over the samples (no refinement: thesis eq 4.8).
double sampled_max_overlap(const cases::Scene& scene, const cases::Trace& trace) {
  const auto& overlap = *overlap_mask(scene, trace).first;
  double best = -std::numeric_limits<double>::infinity();
  for (const double v : overlap) best = std::max(best, v);
  return best;
}

/// εx_amp, thesis eq 4.8, with both maxima over the same time points (§4.3.3).
double amplitude_error(const cases::Scene& scene, const cases::Trace& trace,
                       const cases::RunResult* analytic) {
  if (analytic == nullptr || analytic->status != cases::RunStatus::ok) {
    throw MetricProblem("amplitude_error needs an analytic solution, which did not run");
  }
  const auto& t = column(trace, "time");
  const auto& ta = column(analytic->trace, "time");
  if (t.size() != ta.size()) {
    throw MetricProblem(fmt::format("analytic trace has {} samples, this one {}", ta.size(), t.size()));
  }
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (std::abs(t[k] - ta[k]) > 1e-9 * std::max(std::abs(t[k]), 1e-300) + 1e-300) {
      throw MetricProblem(fmt::format("analytic trace is sampled at other times (row {})", k));
    }
  }
  const double overlap = sampled_max_overlap(scene, analytic->trace);
  if (!(overlap > 0.0)) throw MetricProblem("the analytic solution has no overlap");
  return std::abs(max_position(scene, trace) - max_position(scene, analytic->trace)) / overlap;
}

/// Computes one metric from the trace; throws MetricProblem when it cannot.
double from_trace(const std::string& name, const cases::Scene& scene, const cases::RunResult& run,
                  const cases::RunResult* analytic) {
  const cases::Trace& trace = run.trace;
  if (name == "contact_duration") return contact_duration(scene, trace);
  if (name == "restitution") return restitution(scene, trace);
  if (name == "max_overlap") return max_of_pair_column(scene, trace, "overlap");
  if (name == "max_force") return max_of_pair_column(scene, trace, "fn");
  if (name == "max_position") return max_position(scene, trace);
  if (name == "amplitude_error") return amplitude_error(scene, trace, analytic);
  if (name == "tangential_restitution") return motion::tangential_restitution(scene, trace).value_or_throw<MetricProblem>();
  if (name == "rebound_angle") return motion::rebound_angle(scene, trace).value_or_throw<MetricProblem>();
  if (name == "spin_after") return motion::spin_after(scene, trace).value_or_throw<MetricProblem>();
  if (name == "deceleration") return motion::deceleration(scene, trace).value_or_throw<MetricProblem>();
  if (name == "tangential_force_max") return motion::tangential_force_max(scene, trace).value_or_throw<MetricProblem>();
  if (const auto e = motion::end_state_metric(name, scene, trace)) return e->value_or_throw<MetricProblem>();
  if (const auto c = cohesion_metric(name, scene, trace)) return c->value ? *c->value : throw MetricProblem(c->problem);
  if (const auto b = breakup_metric(name, scene, run)) return b->value ? *b->value : throw MetricProblem(b->problem);
  if (const auto p = packing_metric(name, scene, run)) return p->value ? *p->value : throw MetricProblem(p->problem);
  if (const auto d = discharge_metric(name, scene, run)) return d->value ? *d->value : throw MetricProblem(d->problem);
  throw MetricProblem(fmt::format("no implementation of metric '{}'", name));
}

}  // namespace

namespace {

/// Row by row, the largest |x_a − x_b| over every traced particle and coordinate; empty when the
/// traces have no traced position in common. The traces must have the same number of rows.
std::optional<std::vector<double>> position_gaps(const cases::Scene& scene, const cases::Trace& a,
                                                 const cases::Trace& b) {
  std::vector<double> gaps(a.rows(), 0.0);
  bool any = false;
  for (const std::size_t i : scene.output.trace_particles) {
    for (const char* q : {"x", "y", "z"}) {
      const auto* ca = a.column(cases::particle_column(i, q));
      const auto* cb = b.column(cases::particle_column(i, q));
      if (ca == nullptr || cb == nullptr) continue;
      any = true;
      for (std::size_t k = 0; k < gaps.size(); ++k) gaps[k] = std::max(gaps[k], std::abs((*ca)[k] - (*cb)[k]));
    }
  }
  if (!any) return std::nullopt;
  return gaps;
}

}  // namespace

std::optional<TraceDeviation> trace_deviation(const cases::Scene& scene, const cases::RunResult& run,
                                              const cases::RunResult& reference, std::string& problem) {
  const auto* t = run.trace.column("time");
  const auto* tr = reference.trace.column("time");
  if (t == nullptr || tr == nullptr || t->size() != tr->size() || t->empty()) {
    problem = "the two traces do not have the same number of samples";
    return std::nullopt;
  }
  for (std::size_t k = 0; k < t->size(); ++k) {
    if (std::abs((*t)[k] - (*tr)[k]) > 1e-12 * std::max(std::abs((*tr)[k]), 1e-300)) {
      problem = fmt::format("the traces are sampled at other times (row {})", k);
      return std::nullopt;
    }
  }
  const auto gaps = position_gaps(scene, run.trace, reference.trace);
  if (!gaps) {
    problem = "no traced particle positions in both traces";
    return std::nullopt;
  }
  double scale = 0.0;
  try {
    const auto& overlap = *overlap_mask(scene, reference.trace).first;
    for (const double v : overlap) scale = std::max(scale, v);
  } catch (const MetricProblem& e) {
    problem = e.what();
    return std::nullopt;
  }
  if (!(scale > 0.0)) {
    problem = "the reference trace never overlaps: no scale for the deviation";
    return std::nullopt;
  }
  TraceDeviation d;
  d.rows = gaps->size();
  d.horizon = d.rows;
  // The run's own sensitivity to round-off: the first row at which its twin, started one ulp
  // away, has drifted past kRoundoffDrift. Rows from there on are not compared.
  if (run.roundoff_twin) {
    const cases::Trace& twin = *run.roundoff_twin;
    const auto* tt = twin.column("time");
    if (tt == nullptr || tt->size() != t->size()) {
      problem = "the round-off twin's trace does not have the run's samples";
      return std::nullopt;
    }
    const auto drift = position_gaps(scene, run.trace, twin);
    if (!drift) {
      problem = "the round-off twin's trace has no traced positions";
      return std::nullopt;
    }
    for (std::size_t k = 0; k < drift->size(); ++k) {
      if ((*drift)[k] / scale > kRoundoffDrift) {
        d.horizon = k;
        d.horizon_time = (*t)[k];
        break;
      }
    }
  }
  for (std::size_t k = 0; k < d.rows; ++k) {
    const double relative = (*gaps)[k] / scale;
    d.whole = std::max(d.whole, relative);
    if (k < d.horizon) d.value = std::max(d.value, relative);
  }
  return d;
}

std::optional<std::vector<double>> axis_displacement(const cases::Scene& scene,
                                                     const cases::Trace& trace) {
  try {
    return displacement_along_axis(scene, trace);
  } catch (const MetricProblem&) {
    return std::nullopt;
  }
}

MetricSet compute_metrics(const cases::Scene& scene, const cases::RunResult& run,
                          const cases::RunResult* analytic) {
  MetricSet out;
  for (const std::string& name : scene.compare.metrics) {
    MetricValue v;
    if (run.status != cases::RunStatus::ok) {
      v.problem = fmt::format("engine status {}", cases::to_string(run.status));
    } else if (const auto na = run.inexpressible_metrics.find(name); na != run.inexpressible_metrics.end()) {
      v.problem = na->second;
      v.not_applicable = true;
    } else if (const auto exact = run.exact_metrics.find(name); exact != run.exact_metrics.end()) {
      v.value = exact->second;
      v.source = "closed form";
    } else if (run.refinement && run.refinement->metrics.contains(name)) {
      v.value = run.refinement->metrics.at(name);
      v.source = fmt::format("trace at Δt = {:.6g} s", run.refinement->timestep);
    } else {
      try {
        v.value = from_trace(name, scene, run, analytic);
        v.source = "trace";
      } catch (const MetricProblem& e) {
        v.problem = e.what();
      }
    }
    if (v.value && !std::isfinite(*v.value)) {
      v.problem = fmt::format("non-finite value {}", *v.value);
      v.value.reset();
    }
    out[name] = v;
  }
  return out;
}

}  // namespace comparison
