// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <string_view>

namespace reference {

/// `text` fit for a LAMMPS-family deck comment: every non-ASCII byte (LAMMPS 2021 warns about UTF-8
/// input) and every control byte (a newline would end the comment and start a command) becomes '?',
/// and '"' (LAMMPS' `"""` opens a multi-line string) becomes '\''. Case-file names are validated at
/// load time; this keeps every string a deck comment shows inert regardless.
std::string deck_comment_text(std::string_view text);

}  // namespace reference
