# SPDX-License-Identifier: MIT
# demwb_set_warnings(target): the project's warning set, optionally fatal (DEMWB_WERROR).
function(demwb_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                         -Wno-sign-conversion)
  if(DEMWB_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
