// SPDX-License-Identifier: MIT
#pragma once

#include <string_view>

#include "cases/trace.hpp"

namespace reference {

/// Parses the file a LAMMPS-family (LAMMPS, LIGGGHTS) `fix print … title "# name …"` writes: a header line "# name …"
/// followed by one row of whitespace-separated numbers per print (nan and inf are accepted, so
/// the caller can report them). Returns one column per header name. Throws std::runtime_error
/// naming `file_name` and the 1-based line number on a missing header, a duplicate name, a
/// wrong number of values or a token that is not a number.
cases::Trace parse_fix_print(std::string_view text, std::string_view file_name);

}  // namespace reference
