// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "dem/core/vector.hpp"

namespace bench {

/// One atom of a LAMMPS `atom_style sphere` data file.
struct DataAtom {
  std::uint64_t id = 0;
  int type = 0;
  double diameter = 0.0;
  double density = 0.0;
  dem::Vec3 position = dem::Vec3::Zero();
  dem::Vec3 velocity = dem::Vec3::Zero();
  dem::Vec3 angular_velocity = dem::Vec3::Zero();
};

/// The box and atoms of a LAMMPS data file (atom_style sphere: "id type diameter density x y z
/// [ix iy iz]" under Atoms, "id vx vy vz wx wy wz" under Velocities), atoms sorted by id. Image
/// flags are read past: positions are the wrapped ones the file gives.
struct LammpsData {
  dem::Vec3 lo = dem::Vec3::Zero();
  dem::Vec3 hi = dem::Vec3::Zero();
  int atom_types = 0;
  std::vector<DataAtom> atoms;
};

/// Reads a data file; throws std::runtime_error naming the file and line of the first problem.
LammpsData read_lammps_data(const std::filesystem::path& file);

}  // namespace bench
