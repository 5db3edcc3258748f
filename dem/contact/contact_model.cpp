// SPDX-License-Identifier: MIT
#include "dem/contact/contact_model.hpp"

namespace dem {

ContactOutcome evaluate_contact(const PairLaw& law, const ContactGeometry& g, const ContactHistory& committed,
                                double elapsed) noexcept {
  return evaluate_contact_in(DynamicSlots{law}, g, committed, elapsed);
}

double interaction_range(const PairLaw& law, const PairExtent& e) noexcept {
  const double normal = std::visit([&](const auto& m) { return m.range(e); }, law.normal);
  const double cohesion = std::visit([&](const auto& m) { return m.range(e); }, law.cohesion);
  return std::max(normal, cohesion);
}

double collision_stiffness(const PairLaw& law, const CollisionScale& s) noexcept {
  return std::visit([&](const auto& m) { return m.collision_stiffness(s); }, law.normal);
}

double damping_coefficient(const PairLaw& law, double reduced_mass, double stiffness) noexcept {
  ContactGeometry g{};
  g.reduced_mass = reduced_mass;
  NormalResponse n;
  n.stiffness = stiffness;
  return std::visit([&](const auto& m) { return m.coefficient(g, n); }, law.damping);
}

}  // namespace dem
