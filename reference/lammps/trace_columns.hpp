// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "cases/scene.hpp"
#include "cases/trace.hpp"
#include "reference/lammps/atom_types.hpp"

namespace reference::lammps {

/// ID of the `fix store/force` that keeps each atom's pair (contact) forces before `fix gravity`
/// adds weight and `fix freeze` zeroes frozen atoms. The deck must define it before both.
inline constexpr std::string_view kPairForceFix = "tr_pairforce";
/// ID of the `fix store/force` defined after the walls: pair + wall forces. A wall's force on an
/// atom is the difference of the two stores.
inline constexpr std::string_view kContactForceFix = "tr_contactforce";
/// Name of the step column of the fix-print file (checked, then dropped).
inline constexpr std::string_view kStepColumn = "step";
/// Name of a pair's auxiliary column, e.g. "c0-1.fn_exact": 1 on rows where its `fn` is
/// exactly that pair's force, 0 where the per-atom forces cannot isolate it.
std::string exact_column(std::size_t p, std::size_t q);

/// One column of the `fix print` file: its header name and the LAMMPS expression printed.
struct PrintColumn {
  std::string name;        ///< "step", a trace column ("p0.x", "c0-1.fn") or an auxiliary column
  std::string expression;  ///< equal-style formula, e.g. "x[1]", inlined in `$(…:%.17g)`
};

/// Everything the deck needs to write the trace file: computes and columns.
struct TracePrintPlan {
  std::vector<std::string> computes;  ///< `compute …` lines
  std::vector<PrintColumn> columns;   ///< in file order: step, trace columns, auxiliaries
  /// Which LAMMPS quantity each trace column comes from (for reports).
  std::vector<std::string> sources;
};

/// The trace columns of the scene — exactly cases::trace_layout's: time; per traced particle
/// x y z vx vy vz wx wy wz fx fy fz; per traced pair overlap and fn — as LAMMPS quantities:
/// - time = LAMMPS `time` (= step·Δt); positions and velocities x[i], vx[i] …;
/// - angular velocity from `compute property/atom omegax omegay omegaz`;
/// - force: fx[i] of a mobile atom (contacts + gravity, what LAMMPS integrates); for a fixed
///   atom its contact force from the `fix store/force` (before `fix freeze` zeroes it), as the
///   core reports it;
/// - overlap r_p + r_q − |x_p − x_q| from LAMMPS' radii and positions;
/// - fn: the pair forces LAMMPS applied (`fix store/force`) on a partner whose only contact
///   (`compute contact/atom`) is this pair, projected on n = (x_p − x_q)/|x_p − x_q|; 0 while
///   δ ≤ 0. `compute pair/local` is not used: it re-evaluates the pair at output time with the
///   full-step velocities, not the half-step ones the dashpot saw. When both partners have other
///   contacts the value is not exact and the auxiliary column exact_column(p, q) says so. In a
///   scene of exactly two spheres and no walls the force is not gated by δ > 0 (a JKR neck
///   pulls at δ < 0) and is always exact;
/// - wall overlap r − (distance of the centre from the plane); wall fn: the stored contact
///   force minus the stored pair force (the walls' forces) along the wall normal, exact while
///   the sphere touches only that wall.
/// Every formula is written out in full inside `$(…:%.17g)`: LAMMPS 2021 passes the value of a
/// `v_name` reference to another equal-style variable through "%.15g", so a column printed as
/// `$(v_name:%.17g)` or built from helper variables would lose two digits.
TracePrintPlan trace_print_plan(const cases::Scene& scene, const AtomTypes& types);

/// The `fix print` command for `plan`, every `every` steps, writing `file` (header "# names").
std::string fix_print_command(const TracePrintPlan& plan, std::size_t every,
                              std::string_view file);

/// A scene trace and the notes made while building it.
struct AssembledTrace {
  cases::Trace trace;
  std::vector<std::string> warnings;
};

/// Turns the parsed fix-print table into the scene's trace: checks that row k is step
/// k·trace_every for k = 0 … steps/trace_every, orders the columns as cases::trace_layout does,
/// drops the step and auxiliary columns, and warns about inexact pair forces. Throws
/// std::runtime_error naming the row or column when the table does not fit the scene.
AssembledTrace assemble_trace(const cases::Scene& scene, const cases::Trace& printed,
                              std::uint64_t steps);

}  // namespace reference::lammps
