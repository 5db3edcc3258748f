// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "cases/scene.hpp"
#include "cases/trace.hpp"
#include "reference/liggghts/atom_types.hpp"

namespace reference::liggghts {

/// One trace column: its name in the trace and the LIGGGHTS formula of its value.
struct TraceColumn {
  std::string name;
  std::string formula;
};

/// The deck's trace: computes it needs, and one thermo variable per column. Every formula is
/// written out in full: a `v_name` inside another formula passes through 15 digits in this
/// LIGGGHTS, while a thermo column prints the variable itself with `%.17g`.
struct TracePlan {
  std::vector<std::string> commands;  ///< computes and fixes the formulas read
  std::vector<TraceColumn> columns;   ///< "time" and the trace's columns, in thermo order
  std::vector<std::string> sources;   ///< where each quantity comes from (reported as conventions)
};

/// Name of the thermo variable of column k.
std::string column_variable(std::size_t k);
/// ID of the `fix store/force` of the pair forces (before walls, gravity and freeze).
inline constexpr std::string_view kPairForceFix = "tr_pair_force";
/// ID of the fix wall/gran of wall w.
std::string wall_fix_id(std::size_t wall);

/// Name of the auxiliary column saying, per row, whether pair (p, q)'s fn is its own force (1) or
/// a partner's total (0): written for scenes of more than two bodies, not part of the trace.
std::string exact_column(std::size_t p, std::size_t q);

/// The trace plan of the scene (pure): the trace's columns in its order, then the auxiliary ones.
TracePlan trace_plan(const cases::Scene& scene, const AtomTypes& types);

/// The trace from the log's thermo table: the block headed "Step tr_c0 tr_c1 …"; rows at
/// multiples of `every` from 0 to `steps` (the last line LIGGGHTS adds at a step that is not one
/// is dropped). Throws std::runtime_error naming `file_name` when the table is missing, short
/// or malformed.
cases::Trace trace_from_thermo(const cases::Scene& scene, const TracePlan& plan, std::string_view log_text,
                               std::string_view file_name, std::uint64_t steps);

/// The trace in the column order every engine shares, and a warning per traced pair whose fn was
/// not its own force at some rows.
struct AssembledTrace {
  cases::Trace trace;
  std::vector<std::string> warnings;
};

/// The trace's columns picked from the printed table (trace_from_thermo), with the warnings.
AssembledTrace assemble_trace(const cases::Scene& scene, const cases::Trace& printed);

}  // namespace reference::liggghts
