// SPDX-License-Identifier: MIT
#include "compare/metrics_motion.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "compare/trace_analysis.hpp"
#include "dem/particles/particles.hpp"
#include "support/line_fit.hpp"

namespace comparison::motion {
namespace {

using Vec = std::array<double, 3>;

/// Why a motion metric cannot be computed; caught at the public entry points.
struct Problem : std::runtime_error {
  using std::runtime_error::runtime_error;
};

Vec add(const Vec& a, const Vec& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec scale(const Vec& a, double f) { return {a[0] * f, a[1] * f, a[2] * f}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
/// Part of v perpendicular to the unit vector n.
Vec tangential(const Vec& v, const Vec& n) { return sub(v, scale(n, dot(v, n))); }

const std::vector<double>& column(const cases::Trace& trace, const std::string& name) {
  const auto* c = trace.column(name);
  if (c == nullptr) throw Problem(fmt::format("trace has no column '{}'", name));
  return *c;
}

/// Position, velocity and spin of one body at one row.
struct BodyState {
  Vec x{};
  Vec v{};
  Vec w{};
};

/// A particle's state at every row: traced columns, or the case values of a fixed sphere at rest.
class Body {
 public:
  Body(const cases::Scene& scene, const cases::Trace& trace, std::size_t index)
      : spec_(scene.particles.at(index)) {
    if (trace.column(cases::particle_column(index, "x")) == nullptr) {
      if (!spec_.fixed) throw Problem(fmt::format("particle {} is not traced (output.trace_particles)", index));
      if (!spec_.motion.empty()) {
        throw Problem(fmt::format("particle {} moves by prescription but is not traced", index));
      }
      return;
    }
    for (const char* q : {"x", "y", "z", "vx", "vy", "vz", "wx", "wy", "wz"}) {
      columns_.push_back(&column(trace, cases::particle_column(index, q)));
    }
  }
  [[nodiscard]] BodyState at(std::size_t row) const {
    if (columns_.empty()) return {spec_.position, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
    const auto c = [&](std::size_t k) { return (*columns_[k])[row]; };
    return {{c(0), c(1), c(2)}, {c(3), c(4), c(5)}, {c(6), c(7), c(8)}};
  }
  [[nodiscard]] double radius() const noexcept { return spec_.radius; }

 private:
  const cases::ParticleSpec& spec_;
  std::vector<const std::vector<double>*> columns_;
};

/// The subject (compare.subject, else the first mobile particle).
std::size_t subject_of(const cases::Scene& scene) {
  if (scene.compare.subject) return *scene.compare.subject;
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    if (!scene.particles[i].fixed) return i;
  }
  throw Problem("the scene has no mobile particle");
}

/// The compared contact seen from the subject: relative kinematics at any row.
class ContactKinematics {
 public:
  ContactKinematics(const cases::Scene& scene, const cases::Trace& trace) {
    const std::size_t s = subject_of(scene);
    std::size_t other = 0;
    if (scene.compare.wall_contact) {
      const auto [p, w] = *scene.compare.wall_contact;
      if (p != s) throw Problem(fmt::format("the subject {} is not in compare.wall_contact", s));
      wall_ = &scene.walls.at(w);
      overlap_name_ = cases::wall_column(p, w, "overlap");
    } else if (scene.compare.pair) {
      const auto [a, b] = *scene.compare.pair;
      if (a != s && b != s) throw Problem(fmt::format("the subject {} is not in compare.pair", s));
      other = a == s ? b : a;
      overlap_name_ = cases::pair_column(a, b, "overlap");
    } else {
      throw Problem("the case sets no compare.pair or compare.wall_contact");
    }
    subject_.emplace(scene, trace, s);
    if (wall_ == nullptr) partner_.emplace(scene, trace, other);
    overlap_ = &column(trace, overlap_name_);
    time_ = &column(trace, "time");
  }

  /// Unit normal from the partner to the subject at a row.
  [[nodiscard]] Vec normal(std::size_t row) const {
    if (wall_ != nullptr) return wall_->normal;
    const Vec d = sub(subject_->at(row).x, partner_->at(row).x);
    const double n = norm(d);
    if (!(n > 0.0)) throw Problem(fmt::format("coincident centres at row {}", row));
    return scale(d, 1.0 / n);
  }
  /// Centre velocity of the subject relative to the partner.
  [[nodiscard]] Vec relative_velocity(std::size_t row) const {
    const Vec partner = wall_ != nullptr ? wall_->velocity : partner_->at(row).v;
    return sub(subject_->at(row).v, partner);
  }
  /// Tangential contact-point velocity; branch vectors shortened by half the overlap `delta`.
  [[nodiscard]] Vec slip_velocity(std::size_t row, double delta) const {
    const Vec n = normal(row);
    const BodyState p = subject_->at(row);
    const Vec a_p = scale(n, -(subject_->radius() - 0.5 * delta));
    Vec u = add(p.v, cross(p.w, a_p));
    if (wall_ != nullptr) {
      u = sub(u, wall_->velocity);
    } else {
      const BodyState q = partner_->at(row);
      const Vec a_q = scale(n, partner_->radius() - 0.5 * delta);
      u = sub(u, add(q.v, cross(q.w, a_q)));
    }
    return tangential(u, n);
  }
  [[nodiscard]] BodyState subject(std::size_t row) const { return subject_->at(row); }
  [[nodiscard]] double subject_radius() const noexcept { return subject_->radius(); }
  [[nodiscard]] const std::vector<double>& overlap() const { return *overlap_; }
  [[nodiscard]] const std::vector<double>& time() const { return *time_; }

  /// The first contact, or a problem naming the contact.
  [[nodiscard]] ContactInterval first_contact_interval() const {
    const IntervalSearch found = first_contact(*time_, *overlap_);
    if (found.interval) return *found.interval;
    switch (found.problem) {
      case IntervalProblem::starts_in_contact:
        throw Problem(fmt::format("'{}' is positive at the first sample: no approach to compare", overlap_name_));
      case IntervalProblem::never_ends:
        throw Problem(fmt::format("the contact ('{}') does not end within the run", overlap_name_));
      case IntervalProblem::no_contact: break;
    }
    throw Problem(fmt::format("'{}' never becomes positive: no contact", overlap_name_));
  }

 private:
  const cases::WallSpec* wall_ = nullptr;
  std::optional<Body> subject_;
  std::optional<Body> partner_;
  std::string overlap_name_;
  const std::vector<double>* overlap_ = nullptr;
  const std::vector<double>* time_ = nullptr;
};

/// Direction of the contact-point slip before the contact, and its speed.
std::pair<Vec, double> slip_before(const ContactKinematics& k, const ContactInterval& c) {
  const Vec u = k.slip_velocity(c.last_before, 0.0);
  const double speed = norm(u);
  const BodyState p = k.subject(c.last_before);
  const double typical = norm(k.relative_velocity(c.last_before)) + norm(p.w) * k.subject_radius();
  if (!(speed > 1e-12 * typical) || !(speed > 0.0)) {
    throw Problem("the contact point has no tangential velocity before the contact (normal impact)");
  }
  return {scale(u, 1.0 / speed), speed};
}

/// Runs a metric body, turning a Problem into an empty value with its reason.
template <class F>
MotionMetric guarded(F&& body) {
  MotionMetric out;
  try {
    const double v = body();
    if (std::isfinite(v)) {
      out.value = v;
    } else {
      out.problem = fmt::format("non-finite value {}", v);
    }
  } catch (const Problem& e) {
    out.problem = e.what();
  } catch (const std::out_of_range& e) {
    out.problem = fmt::format("the case refers to a missing particle or wall ({})", e.what());
  }
  return out;
}

}  // namespace

MotionMetric tangential_restitution(const cases::Scene& scene, const cases::Trace& trace) {
  return guarded([&] {
    const ContactKinematics k(scene, trace);
    const ContactInterval c = k.first_contact_interval();
    const auto [t_hat, before] = slip_before(k, c);
    return -dot(k.slip_velocity(c.first_after, 0.0), t_hat) / before;
  });
}

MotionMetric rebound_angle(const cases::Scene& scene, const cases::Trace& trace) {
  return guarded([&] {
    const ContactKinematics k(scene, trace);
    const ContactInterval c = k.first_contact_interval();
    const Vec n = k.normal(c.first_after);
    const Vec v = k.relative_velocity(c.first_after);
    const double v_n = dot(v, n);
    if (!(v_n > 0.0)) throw Problem("the subject is not moving away from the partner after the contact");
    return std::atan2(norm(tangential(v, n)), v_n) * 180.0 / std::numbers::pi;
  });
}

MotionMetric spin_after(const cases::Scene& scene, const cases::Trace& trace) {
  return guarded([&] {
    const ContactKinematics k(scene, trace);
    const ContactInterval c = k.first_contact_interval();
    const Vec t_hat = slip_before(k, c).first;
    const Vec n_in = scale(k.normal(c.last_before), -1.0);
    return dot(k.subject(c.first_after).w, cross(t_hat, n_in));
  });
}

MotionMetric state_after(const cases::Scene& scene, const cases::Trace& trace, bool angular, int axis) {
  return guarded([&] {
    if (axis < 0 || axis > 2) throw Problem(fmt::format("no axis {}", axis));
    const ContactKinematics k(scene, trace);
    const BodyState after = k.subject(k.first_contact_interval().first_after);
    return (angular ? after.w : after.v)[static_cast<std::size_t>(axis)];
  });
}

std::optional<MotionMetric> end_state_metric(const std::string& name, const cases::Scene& scene,
                                             const cases::Trace& trace) {
  for (const bool angular : {false, true}) {
    const std::string prefix = angular ? "angular_velocity_after_" : "velocity_after_";
    if (name.size() != prefix.size() + 1 || !name.starts_with(prefix)) continue;
    const int axis = name.back() - 'x';
    if (axis < 0 || axis > 2) return std::nullopt;
    return state_after(scene, trace, angular, axis);
  }
  return std::nullopt;
}

MotionMetric tangential_force_max(const cases::Scene& scene, const cases::Trace& trace) {
  return guarded([&] {
    if (scene.particles.size() + scene.walls.size() != 2) {
      throw Problem(fmt::format("the scene has {} particles and {} walls; the traced force is the "
                                "compared contact's force only in a scene of the subject and its "
                                "partner alone",
                                scene.particles.size(), scene.walls.size()));
    }
    if (scene.fluid) throw Problem("a fluid acts on the subject: its traced force is not the contact force alone");
    const ContactKinematics k(scene, trace);
    const ContactInterval c = k.first_contact_interval();
    const std::size_t s = subject_of(scene);
    const cases::ParticleSpec& p = scene.particles.at(s);
    const double mass = dem::sphere_mass(scene.materials.at(p.material).density, p.radius);
    const Vec weight = scale(scene.gravity, mass);
    const auto& fx = column(trace, cases::particle_column(s, "fx"));
    const auto& fy = column(trace, cases::particle_column(s, "fy"));
    const auto& fz = column(trace, cases::particle_column(s, "fz"));
    double largest = 0.0;
    for (std::size_t row = c.last_before + 1; row < c.first_after; ++row) {
      const Vec contact = sub(Vec{fx[row], fy[row], fz[row]}, weight);
      largest = std::max(largest, norm(tangential(contact, k.normal(row))));
    }
    return largest;
  });
}

MotionMetric deceleration(const cases::Scene& scene, const cases::Trace& trace) {
  return guarded([&] {
    const ContactKinematics k(scene, trace);
    const auto& overlap = k.overlap();
    const auto& time = k.time();
    std::size_t first = 0;
    while (first < overlap.size() && !(overlap[first] > 0.0)) ++first;
    if (first == overlap.size()) throw Problem("the compared contact never forms");
    const double initial = norm(k.slip_velocity(first, overlap[first]));
    if (!(initial > 0.0)) throw Problem("the contact is not sliding at its first row");
    // Least squares over the sliding rows.
    std::vector<double> t, s;
    for (std::size_t row = first; row < overlap.size() && overlap[row] > 0.0; ++row) {
      if (!(norm(k.slip_velocity(row, overlap[row])) > kSlidingThreshold * initial)) break;
      const Vec n = k.normal(row);
      t.push_back(time[row]);
      s.push_back(norm(tangential(k.relative_velocity(row), n)));
    }
    if (t.size() < 3) {
      throw Problem(fmt::format("only {} sliding rows (need 3): sample more often", t.size()));
    }
    const std::optional<support::LineFit> line = support::least_squares_line(t, s);
    if (!line) throw Problem("the sliding rows share one time");
    return -line->slope;
  });
}

}  // namespace comparison::motion
