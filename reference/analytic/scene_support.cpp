// SPDX-License-Identifier: MIT
#include "reference/analytic/scene_support.hpp"

#include "reference/analytic/model_support.hpp"

#include <cmath>
#include <exception>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "dem/contact/pair_table.hpp"
#include "reference/analytic/collinear_scene.hpp"
#include "reference/analytic/vector3_math.hpp"

namespace reference::analytic {
namespace {

/// What the collinear closed forms solve: a linear spring with no or a restitution dashpot,
/// not clamped (eq 3.10–3.11), frictionless, no cohesion, no rolling resistance.
const ModelSupport kCollinearModel{"collinear collision", {"linear"}, {"none", "restitution"}, {"none"}, {"none"}, {"none"}};

using cases::Vector3;



/// Reasons against the particles' layout: one mobile sphere with collinear fixed partners, or
/// two mobile spheres alone colliding head-on.
void check_collinear_layout(const cases::Scene& scene, std::vector<std::string>& reasons) {
  const ParticleRoles roles = particle_roles(scene);
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const cases::ParticleSpec& p = scene.particles[i];
    if (p.material >= scene.materials.size()) {
      reasons.push_back(fmt::format("analytic: particle {} names material {}, which does not exist",
                                    i, p.material));
    }
    if (!(p.radius > 0.0) || !std::isfinite(p.radius)) {
      reasons.push_back(fmt::format("analytic: particle {} has radius {} m; need r > 0", i, p.radius));
    }
    if (p.fixed && norm(p.velocity) != 0.0) {
      reasons.push_back(fmt::format(
          "analytic: fixed particle {} has velocity ({}, {}, {}) m/s; a fixed sphere must be at rest",
          i, p.velocity[0], p.velocity[1], p.velocity[2]));
    }
  }
  const std::size_t mobile = roles.mobile.size();
  if (mobile == 0) {
    reasons.push_back("analytic: no mobile sphere, so there is no motion to solve");
  } else if (mobile == 1) {
    const std::size_t i = roles.mobile.front();
    const auto axis = line_of_motion(scene, i, roles.fixed);
    if (!axis) {
      reasons.push_back(fmt::format(
          "analytic: mobile particle {} is at rest and touches no fixed sphere, so no line of "
          "motion is defined",
          i));
      return;
    }
    for (const std::size_t j : roles.fixed) {
      const Vector3 d = minus(scene.particles[j].position, scene.particles[i].position);
      const double off = off_line(d, *axis);
      if (off > kCollinearTolerance * norm(d)) {
        reasons.push_back(fmt::format(
            "analytic: fixed particle {} lies {:.3g} m off the line of motion of mobile particle "
            "{} (its centre must be collinear within 1e-12 relative: only head-on contacts have a "
            "closed form here)",
            j, off, i));
      }
    }
  } else if (mobile == 2 && roles.fixed.empty()) {
    const std::size_t a = roles.mobile[0];
    const std::size_t b = roles.mobile[1];
    const Vector3 x_ab = minus(scene.particles[a].position, scene.particles[b].position);
    const double distance = norm(x_ab);
    if (!(distance > 0.0)) {
      reasons.push_back(fmt::format(
          "analytic: mobile particles {} and {} have coincident centres, so their line of centres "
          "is undefined",
          a, b));
      return;
    }
    const Vector3 relative = minus(scene.particles[a].velocity, scene.particles[b].velocity);
    const double off = off_line(relative, scaled(x_ab, 1.0 / distance));
    if (off > kCollinearTolerance * norm(relative)) {
      reasons.push_back(fmt::format(
          "analytic: the relative velocity of mobile particles {} and {} has a {:.3g} m/s part "
          "across their line of centres; only head-on collisions have a closed form here",
          a, b, off));
    }
  } else if (mobile == 2) {
    reasons.push_back(fmt::format(
        "analytic: 2 mobile spheres together with {} fixed ones; closed forms exist for one "
        "mobile sphere among fixed ones, or for two mobile spheres alone",
        roles.fixed.size()));
  } else {
    reasons.push_back(fmt::format(
        "analytic: {} mobile spheres; closed forms exist for one mobile sphere among fixed "
        "ones, or for two mobile spheres alone",
        mobile));
  }
}

/// Reasons against the mixed pair parameters of the contacts the solution would use.
void check_parameters(const CollinearScene& reduced, const cases::Scene& scene,
                      std::vector<std::string>& reasons) {
  if (!(reduced.problem.mass > 0.0) || !std::isfinite(reduced.problem.mass)) {
    reasons.push_back(fmt::format("analytic: the moving mass is {} kg; need a positive density",
                                  reduced.problem.mass));
  }
  for (std::size_t k = 0; k < reduced.problem.partners.size(); ++k) {
    const AxisPartner& p = reduced.problem.partners[k];
    const std::string& a = scene.materials.at(scene.particles[reduced.first].material).name;
    const std::string& b =
        scene.materials.at(scene.particles[reduced.partner_particle[k]].material).name;
    if (!(p.stiffness > 0.0) || !std::isfinite(p.stiffness)) {
      reasons.push_back(fmt::format(
          "analytic: materials '{}' and '{}' have normal stiffness {} N/m; need 0 < k < ∞", a, b,
          p.stiffness));
    }
    if (!(p.damping >= 0.0) || !std::isfinite(p.damping)) {
      reasons.push_back(fmt::format(
          "analytic: materials '{}' and '{}' give dashpot coefficient {} kg/s (eq 3.11); need a "
          "restitution in (0, 1]",
          a, b, p.damping));
    }
  }
}

}  // namespace

std::vector<std::string> unsupported_reasons(const PreparedScene& prepared) {
  const cases::Scene& scene = prepared.scene();
  std::vector<std::string> reasons;
  for (std::string& r : model_reasons(scene.model, kCollinearModel)) reasons.push_back(std::move(r));
  const Vector3& g = scene.gravity;
  if (g[0] != 0.0 || g[1] != 0.0 || g[2] != 0.0) {
    reasons.push_back(fmt::format(
        "analytic: gravity ({}, {}, {}) m/s² must be exactly zero (the closed forms have no body "
        "force)",
        g[0], g[1], g[2]));
  }
  if (!scene.walls.empty()) {
    reasons.push_back("analytic: walls are not part of the collinear closed forms");
  }
  if (scene.fluid) reasons.push_back("analytic: a fluid (drag, buoyancy) has no closed form here");
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    if (!scene.particles[i].motion.empty()) {
      reasons.push_back(fmt::format("analytic: particle {} has a prescribed motion", i));
    }
    if (scene.particles[i].charge != 0.0) {
      reasons.push_back(fmt::format("analytic: particle {} is charged", i));
    }
  }
  check_collinear_layout(scene, reasons);
  if (!reasons.empty()) return reasons;
  try {
    const dem::PairTable& table = prepared.pair_table();
    check_parameters(build_collinear_scene(scene, table), scene, reasons);
  } catch (const std::exception& e) {
    reasons.push_back(std::string("analytic: ") + e.what());
  }
  return reasons;
}

}  // namespace reference::analytic
