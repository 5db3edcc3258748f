// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>

#include "cases/scene.hpp"

namespace bench {

/// The `box` benchmark scene: `n` glass-like spheres (r = 1 mm, E = 10 MPa, ν = 0.3, ρ = 2500)
/// with Hertz normal force (thesis eq 3.12), Tsuji's dashpot for ε = 0.5 and Mindlin friction
/// k_t = 8 G* a on the whole slip (the total form; μ = 0.5, no tangential dashpot, Coulomb cap on
/// |F_el + F_damp|) — the law the core, LAMMPS and LIGGGHTS all express — on a simple cubic
/// lattice 0.4 % tighter than touching, so every neighbour is in contact from the first step, in
/// an open-topped box of five plane walls, settling under gravity; velocity Verlet with Δt = 5 µs
/// for `steps` steps. The lattice is square in plan and about as tall as wide, so the share of
/// spheres at the walls shrinks as n grows. Every engine reads the same explicit scene through
/// its driver (atoms from a data file).
cases::Scene box_scene(std::size_t n, std::uint64_t steps, std::uint64_t seed = 1);

}  // namespace bench
