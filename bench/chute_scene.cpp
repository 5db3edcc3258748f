// SPDX-License-Identifier: MIT
#include "bench/chute_scene.hpp"

#include <cmath>
#include <cstdlib>
#include <numbers>

#include <fmt/format.h>

namespace bench {

dem::SimulationSetup chute_setup(const LammpsData& data, int threads) {
  constexpr double kNormalStiffness = 200000.0;
  dem::SimulationSetup s;
  dem::MaterialProperties grain;
  grain.name = "chute";
  grain.density = 1.0;
  grain.normal_stiffness = kNormalStiffness;
  grain.damping_rate = 50.0;                                   // γ_n [1/τ]: η = γ_n m*
  grain.tangential_stiffness = kNormalStiffness * 2.0 / 7.0;   // kt = NULL → 2/7 kn
  grain.tangential_damping_ratio = 0.0;                        // dampflag 0 → γ_t = 0
  grain.friction = 0.5;
  s.materials = {grain};
  s.model.normal = "linear";
  s.model.damping = "lammps_mass_velocity";
  s.model.tangential = "spring_coulomb";
  s.model.friction_limit = dem::FrictionLimit::elastic_damping;
  s.model.pair_lever_arm = dem::PairLeverArm::radius;
  s.model.tangential_history = dem::TangentialHistory::increment_project;
  s.model.unloaded_slider = dem::UnloadedSlider::zero;  // gran/hooke/history's `shrmag != 0` rule
  for (const DataAtom& a : data.atoms) {
    const double r = 0.5 * a.diameter;
    s.particles.push_back({r, r, a.density, 0, a.position, a.velocity, a.angular_velocity, a.type == 2});
  }
  // fix gravity 1.0 chute 26.0: θ = 180° − 26° from +z in the x–z plane.
  const double theta = (180.0 - 26.0) * (std::numbers::pi / 180.0);
  s.fields.gravity = dem::Vec3(std::sin(theta), 0.0, std::cos(theta));
  s.box.lo = data.lo;
  s.box.hi = data.hi;
  s.box.periodic = {true, true, false};  // boundary p p fs
  s.neighbors.skin = 0.1;
  s.scheme = dem::SchemeId::velocity_verlet;
  s.scheme_settings.rotation = true;
  s.scheme_settings.orientation = false;  // atom_style sphere keeps no orientation
  s.timestep = 1e-4;
  s.threads = threads;
  s.track_energy = false;  // thermo needs only kinetic energies, taken from the state
  return s;
}

std::optional<std::filesystem::path> find_chute_dir(const std::string& given) {
  std::vector<std::filesystem::path> candidates;
  if (!given.empty()) {
    candidates.emplace_back(given);
  } else {
    if (const char* env = std::getenv("DEMWB_CHUTE_DIR")) candidates.emplace_back(env);
#ifdef DEMWB_SOURCE_DIR
    candidates.emplace_back(std::filesystem::path(DEMWB_SOURCE_DIR) / ".." / "shared" / "bench" / "lammps-chute");
#endif
    candidates.emplace_back(std::filesystem::current_path() / ".." / "shared" / "bench" / "lammps-chute");
  }
  for (const auto& c : candidates) {
    std::error_code ec;
    if (std::filesystem::exists(c / "in.chute", ec) && std::filesystem::exists(c / "data.chute", ec)) {
      return std::filesystem::weakly_canonical(c, ec);
    }
  }
  return std::nullopt;
}

AllKinetic all_kinetic_energy(const dem::Simulation& sim) {
  AllKinetic e;
  const auto& props = sim.particles();
  const auto& state = sim.state();
  for (std::uint32_t id = 0; id < props.size(); ++id) {
    const auto i = static_cast<Eigen::Index>(sim.slot(id));
    e.translational += 0.5 * props.mass[i] * state.velocity.col(i).squaredNorm();
    e.rotational += 0.5 * props.inertia[i] * state.angular_velocity.col(i).squaredNorm();
  }
  return e;
}

std::string lammps_digits(double value, int digits) { return fmt::format("{:.{}g}", value, digits); }

}  // namespace bench
