// SPDX-License-Identifier: MIT
#include "reference/common/atom_data.hpp"

#include <array>

#include <fmt/format.h>

namespace reference {
namespace {

/// A number written so that the code reads back the same double.
std::string num(double v) { return fmt::format("{:.17g}", v); }

}  // namespace

std::string atom_data_body(const cases::Scene& scene, const std::vector<std::size_t>& type_of, const cases::Vector3& lo,
                           const cases::Vector3& hi, std::string_view atoms_title) {
  std::string out;
  constexpr std::array<std::string_view, 3> kAxes{"x", "y", "z"};
  for (std::size_t k = 0; k < 3; ++k) out += fmt::format("{} {} {}lo {}hi\n", num(lo[k]), num(hi[k]), kAxes[k], kAxes[k]);
  out += fmt::format("\n{}\n\n", atoms_title);
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const cases::ParticleSpec& p = scene.particles[i];
    out += fmt::format("{} {} {} {} {} {} {}\n", i + 1, type_of.at(i) + 1, num(2.0 * p.radius),
                       num(scene.materials.at(p.material).density), num(p.position[0]), num(p.position[1]),
                       num(p.position[2]));
  }
  out += "\nVelocities\n\n";
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const cases::ParticleSpec& p = scene.particles[i];
    const cases::Vector3 zero{};
    const cases::Vector3& v = p.fixed ? zero : p.velocity;
    const cases::Vector3& w = p.fixed ? zero : p.angular_velocity;
    out += fmt::format("{} {} {} {} {} {} {}\n", i + 1, num(v[0]), num(v[1]), num(v[2]), num(w[0]), num(w[1]), num(w[2]));
  }
  return out;
}

}  // namespace reference
