# Writes OUT, the header holding the checkout's commit (SOURCE: the source tree). Run at every
# build, so that a binary's label names the commit it was built from rather than the one its build
# was configured at; OUT is rewritten only when the commit changed, so a build of an unchanged
# checkout recompiles nothing.
execute_process(COMMAND git rev-parse --short=12 HEAD
                WORKING_DIRECTORY "${SOURCE}"
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE
                ERROR_QUIET RESULT_VARIABLE result)
if(NOT result EQUAL 0 OR NOT commit)
  set(commit "unknown")
endif()
set(text "// SPDX-License-Identifier: MIT
// Generated at every build by cmake/GitCommit.cmake; do not edit.
#pragma once

namespace support {

/// Git commit the build was made from (\"unknown\" outside a checkout), read at every build.
inline constexpr const char* kGitCommit = \"${commit}\";

}  // namespace support
")
set(old "")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUT}" "${text}")
endif()
