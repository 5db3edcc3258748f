// SPDX-License-Identifier: MIT
#pragma once
// The body of a LAMMPS-family data file (LAMMPS atom style sphere, LIGGGHTS granular: the same
// columns), shared by both drivers.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "cases/scene.hpp"

namespace reference {

/// The data file after its header lines: the box (`lo hi xlo xhi` …), the `atoms_title` section
/// ("Atoms # sphere", "Atoms") with one row "id type diameter density x y z" per particle, type
/// `type_of[i] + 1`, and `Velocities` ("id vx vy vz ωx ωy ωz", zero for a fixed particle); every
/// number in 17 significant digits.
std::string atom_data_body(const cases::Scene& scene, const std::vector<std::size_t>& type_of, const cases::Vector3& lo,
                           const cases::Vector3& hi, std::string_view atoms_title);

}  // namespace reference
