// SPDX-License-Identifier: MIT
#include "reference/analytic/collinear_scene.hpp"

#include <stdexcept>
#include <variant>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/particles/particles.hpp"
#include "reference/analytic/scene_support.hpp"
#include "reference/analytic/vector3_math.hpp"

namespace reference::analytic {
namespace {

using cases::Vector3;


/// The axis partner for the contact of particles i and j with reduced mass m* (eq 3.10–3.11).
AxisPartner partner_for(const cases::Scene& scene, const dem::PairTable& table, std::size_t i,
                        std::size_t j, double reduced_mass, double position) {
  const cases::ParticleSpec& p = scene.particles[i];
  const cases::ParticleSpec& q = scene.particles[j];
  const dem::PairLaw& law = table.law(p.material, q.material);
  AxisPartner out;
  out.position = position;
  out.reach = p.radius + q.radius;
  out.stiffness = std::get<dem::LinearNormal>(law.normal).stiffness;
  if (const auto* d = std::get_if<dem::RestitutionDamping>(&law.damping)) {
    out.damping =
        dem::laws::restitution_damping_coefficient(d->restitution, reduced_mass, out.stiffness);
  }
  return out;
}

}  // namespace

ParticleRoles particle_roles(const cases::Scene& scene) {
  ParticleRoles r;
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    (scene.particles[i].fixed ? r.fixed : r.mobile).push_back(i);
  }
  return r;
}

std::optional<Vector3> line_of_motion(const cases::Scene& scene, std::size_t mobile,
                                      const std::vector<std::size_t>& fixed) {
  const cases::ParticleSpec& p = scene.particles[mobile];
  const double speed = norm(p.velocity);
  if (speed > 0.0) return scaled(p.velocity, 1.0 / speed);
  for (const std::size_t j : fixed) {
    const Vector3 from = minus(p.position, scene.particles[j].position);
    const double distance = norm(from);
    if (distance > 0.0 && p.radius + scene.particles[j].radius - distance >= 0.0) {
      return scaled(from, 1.0 / distance);
    }
  }
  return std::nullopt;
}

CollinearScene build_collinear_scene(const cases::Scene& scene, const dem::PairTable& table) {
  const ParticleRoles roles = particle_roles(scene);
  CollinearScene out;
  if (roles.mobile.size() == 1) {
    const std::size_t i = roles.mobile.front();
    const cases::ParticleSpec& p = scene.particles[i];
    out.axis = *line_of_motion(scene, i, roles.fixed);
    out.first = i;
    out.problem.mass = particle_mass(scene, i);
    out.problem.position = 0.0;
    out.problem.velocity = norm(p.velocity);
    for (const std::size_t j : roles.fixed) {
      const double position = dot(minus(scene.particles[j].position, p.position), out.axis);
      out.problem.partners.push_back(
          partner_for(scene, table, i, j, out.problem.mass, position));
      out.partner_particle.push_back(j);
    }
    return out;
  }
  const std::size_t a = roles.mobile[0];
  const std::size_t b = roles.mobile[1];
  const cases::ParticleSpec& pa = scene.particles[a];
  const cases::ParticleSpec& pb = scene.particles[b];
  const double m_a = particle_mass(scene, a);
  const double m_b = particle_mass(scene, b);
  const double total = m_a + m_b;
  const Vector3 x_ab = minus(pa.position, pb.position);
  const double distance = norm(x_ab);
  out.two_mobile = true;
  out.axis = scaled(x_ab, 1.0 / distance);
  out.first = a;
  out.second = b;
  out.first_share = m_b / total;
  out.second_share = m_a / total;
  for (int k = 0; k < 3; ++k) {
    const auto c = static_cast<std::size_t>(k);
    out.centre_of_mass_velocity[c] = (m_a * pa.velocity[c] + m_b * pb.velocity[c]) / total;
  }
  out.problem.mass = m_a * m_b / total;
  out.problem.position = distance;
  out.problem.velocity = dot(minus(pa.velocity, pb.velocity), out.axis);
  out.problem.partners.push_back(partner_for(scene, table, a, b, out.problem.mass, 0.0));
  out.partner_particle.push_back(b);
  return out;
}

CollinearScene reduce_scene(const PreparedScene& prepared) {
  const cases::Scene& scene = prepared.scene();
  const std::vector<std::string> reasons = unsupported_reasons(prepared);
  if (!reasons.empty()) {
    std::string text;
    for (const auto& r : reasons) text += (text.empty() ? "" : "; ") + r;
    throw std::invalid_argument(text);
  }
  const dem::PairTable& table = prepared.pair_table();
  return build_collinear_scene(scene, table);
}

std::optional<std::size_t> partner_of_pair(const CollinearScene& reduced, std::size_t p,
                                           std::size_t q) noexcept {
  for (std::size_t k = 0; k < reduced.partner_particle.size(); ++k) {
    const std::size_t other = reduced.partner_particle[k];
    if ((p == reduced.first && q == other) || (q == reduced.first && p == other)) return k;
  }
  return std::nullopt;
}

cases::Snapshot snapshot_at(const cases::Scene& scene, const CollinearScene& reduced,
                            const AxisSample& sample, double t) {
  cases::Snapshot snap;
  snap.time = t;
  for (const cases::ParticleSpec& p : scene.particles) {
    snap.position.push_back(p.position);
    snap.velocity.push_back(p.velocity);
    snap.angular_velocity.push_back(p.angular_velocity);
  }
  const double shift = sample.coordinate.position - reduced.problem.position;  // s(t) − s(0)
  const double rate = sample.coordinate.velocity;
  const Vector3& e = reduced.axis;
  const Vector3& v = reduced.centre_of_mass_velocity;
  const auto move = [&](std::size_t i, double share) {
    const cases::ParticleSpec& p = scene.particles[i];
    for (std::size_t c = 0; c < 3; ++c) {
      snap.position[i][c] = p.position[c] + v[c] * t + share * shift * e[c];
      snap.velocity[i][c] = v[c] + share * rate * e[c];
    }
  };
  move(reduced.first, reduced.first_share);
  if (reduced.two_mobile) move(reduced.second, -reduced.second_share);
  return snap;
}

std::vector<Vector3> forces_at(const cases::Scene& scene, const CollinearScene& reduced,
                               const AxisSample& sample) {
  std::vector<Vector3> force(scene.particles.size(), Vector3{0.0, 0.0, 0.0});
  for (std::size_t k = 0; k < reduced.partner_particle.size(); ++k) {
    // Force on the first sphere along the axis: n_k F_n,k (eq 3.10).
    const double along = static_cast<double>(sample.side[k]) * sample.normal_force[k];
    for (std::size_t c = 0; c < 3; ++c) {
      force[reduced.first][c] += along * reduced.axis[c];
      force[reduced.partner_particle[k]][c] -= along * reduced.axis[c];
    }
  }
  return force;
}

double particle_mass(const cases::Scene& scene, std::size_t i) {
  const cases::ParticleSpec& p = scene.particles.at(i);
  return dem::sphere_mass(scene.materials.at(p.material).density, p.radius);
}

}  // namespace reference::analytic
