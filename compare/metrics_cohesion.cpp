// SPDX-License-Identifier: MIT
#include "compare/metrics_cohesion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "compare/trace_analysis.hpp"

namespace comparison {
namespace {

/// A cohesion metric that cannot be computed.
struct Problem : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Overlap and normal-force columns of the compared contact (either pair order).
struct ContactColumns {
  const std::vector<double>* time;
  const std::vector<double>* overlap;
  const std::vector<double>* force;
  std::string label;
};

ContactColumns contact_columns(const cases::Scene& scene, const cases::Trace& trace) {
  std::vector<std::string> prefixes;
  std::string label;
  if (scene.compare.wall_contact) {
    const auto [p, w] = *scene.compare.wall_contact;
    prefixes.push_back(cases::wall_column(p, w, ""));
    label = fmt::format("particle {} and wall {}", p, w);
  } else if (scene.compare.pair) {
    const auto [p, q] = *scene.compare.pair;
    prefixes.push_back(cases::pair_column(p, q, ""));
    prefixes.push_back(cases::pair_column(q, p, ""));
    label = fmt::format("pair {}-{}", p, q);
  } else {
    throw Problem("the case sets no compare.pair or compare.wall_contact");
  }
  const auto* time = trace.column("time");
  if (time == nullptr) throw Problem("trace has no column 'time'");
  for (const auto& prefix : prefixes) {
    const auto* overlap = trace.column(prefix + "overlap");
    const auto* force = trace.column(prefix + "fn");
    if (overlap != nullptr && force != nullptr) return {time, overlap, force, label};
  }
  throw Problem(fmt::format("trace has no columns '{}overlap' and '{}fn'", prefixes.front(),
                            prefixes.front()));
}

/// Largest tension (−F) over the trace, refined by the parabola through the peak sample and its
/// neighbours when all three interact.
double pulloff_force(const ContactColumns& c) {
  const auto& f = *c.force;
  if (f.empty()) throw Problem("the trace is empty");
  std::vector<double> tension(f.size());
  std::vector<bool> interacting(f.size());
  for (std::size_t k = 0; k < f.size(); ++k) {
    tension[k] = -f[k];
    interacting[k] = f[k] != 0.0;
  }
  const Peak p = peak(*c.time, tension, interacting, 0, f.size() - 1);
  if (!(p.sampled > 0.0)) throw Problem(fmt::format("the contact of {} is never in tension", c.label));
  return p.value;
}

Rupture rupture_of(const ContactColumns& c) {
  const auto r = find_rupture(*c.overlap, *c.force);
  if (!r) {
    throw Problem(fmt::format(
        "the contact of {} never breaks in tension (no tensile sample followed by a zero force)",
        c.label));
  }
  return *r;
}

/// Overlap of the compared contact at the last sample.
double equilibrium_overlap(const ContactColumns& c) {
  if (c.overlap->empty()) throw Problem("the trace is empty");
  return c.overlap->back();
}

}  // namespace

std::optional<Rupture> find_rupture(const std::vector<double>& overlap,
                                    const std::vector<double>& force) {
  const std::size_t n = std::min(overlap.size(), force.size());
  std::size_t k = n;
  for (std::size_t i = n; i-- > 1;) {
    if (force[i] == 0.0 && force[i - 1] < 0.0) {
      k = i - 1;
      break;
    }
  }
  if (k == n) return std::nullopt;
  Rupture r{k, 0.5 * (overlap[k] + overlap[k + 1]), force[k], false};
  if (k < 3) return r;
  // Cubic δ(F) through rows k−3..k (Newton form about x3 = F_k, powers of t = F − F_k) and its
  // minimum dδ/dF = 0 beyond row k: near a fold δ − δ_c ∝ (F − F_c)², so the vertex is the fold.
  const double x3 = force[k], x2 = force[k - 1], x1 = force[k - 2], x0 = force[k - 3];
  const double y3 = overlap[k], y2 = overlap[k - 1], y1 = overlap[k - 2], y0 = overlap[k - 3];
  if (x0 == 0.0 || x1 == 0.0 || x2 == 0.0 || !(y0 > y1 && y1 > y2 && y2 > y3)) return r;
  if (x0 == x1 || x1 == x2 || x2 == x3 || x0 == x2 || x1 == x3 || x0 == x3) return r;
  const double d32 = (y3 - y2) / (x3 - x2), d21 = (y2 - y1) / (x2 - x1), d10 = (y1 - y0) / (x1 - x0);
  const double d321 = (d32 - d21) / (x3 - x1), d210 = (d21 - d10) / (x2 - x0);
  const double a3 = (d321 - d210) / (x3 - x0);
  const double e2 = x3 - x2, e1 = x3 - x1;
  const double b1 = d32 + d321 * e2 + a3 * e1 * e2;  // p'(t) = b1 + 2 b2 t + 3 b3 t²
  const double b2 = d321 + a3 * (e1 + e2);
  const double b3 = a3;
  const double disc = 4.0 * b2 * b2 - 12.0 * b3 * b1;
  if (!(disc >= 0.0) || !(2.0 * b2 + std::sqrt(disc) > 0.0)) return r;
  const double t = -2.0 * b1 / (2.0 * b2 + std::sqrt(disc));  // the root with p'' > 0
  const double vertex_d = y3 + ((b3 * t + b2) * t + b1) * t;
  const bool ahead = t * (x3 - x2) >= 0.0 && std::abs(t) <= 3.0 * std::abs(x3 - x0);
  if (ahead && vertex_d <= y3 && vertex_d >= overlap[k + 1] && std::isfinite(vertex_d)) {
    r.overlap = vertex_d;
    r.force = x3 + t;
    r.fold_refined = true;
  }
  return r;
}

double separation_work(const std::vector<double>& overlap, const std::vector<double>& force,
                       const Rupture& r) {
  std::size_t start = r.last_attached;
  while (start > 0 && force[start - 1] != 0.0) --start;
  std::size_t deepest = start;
  for (std::size_t i = start; i <= r.last_attached; ++i) {
    if (overlap[i] > overlap[deepest]) deepest = i;
  }
  double work = 0.0;
  for (std::size_t i = deepest; i < r.last_attached; ++i) {
    work += 0.5 * (force[i] + force[i + 1]) * (overlap[i] - overlap[i + 1]);
  }
  return work + 0.5 * (force[r.last_attached] + r.force) * (overlap[r.last_attached] - r.overlap);
}

std::optional<CohesionMetric> cohesion_metric(const std::string& name, const cases::Scene& scene,
                                              const cases::Trace& trace) {
  if (name != "pulloff_force" && name != "rupture_separation" && name != "force_at_rupture" &&
      name != "separation_work" && name != "equilibrium_overlap") {
    return std::nullopt;
  }
  CohesionMetric out;
  try {
    const ContactColumns c = contact_columns(scene, trace);
    if (name == "pulloff_force") {
      out.value = pulloff_force(c);
    } else if (name == "equilibrium_overlap") {
      out.value = equilibrium_overlap(c);
    } else {
      const Rupture r = rupture_of(c);
      if (name == "rupture_separation") out.value = -r.overlap;
      if (name == "force_at_rupture") out.value = r.force;
      if (name == "separation_work") out.value = separation_work(*c.overlap, *c.force, r);
    }
  } catch (const Problem& e) {
    out.problem = e.what();
  }
  return out;
}

}  // namespace comparison
