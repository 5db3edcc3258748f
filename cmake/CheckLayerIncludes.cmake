# SPDX-License-Identifier: MIT
# cmake -DFOLDER=<dir> -DNAME=<folder name> -DALLOWED=<a,b> [-DSTAMP=<file>] -P CheckLayerIncludes.cmake
# Fails, naming the file and the header, when a .cpp or .hpp in FOLDER includes a header
# "reference/<x>/…" or "reference/<file>" whose <x> is neither NAME nor one of ALLOWED. Touches
# STAMP when every include is allowed (docs/architecture.md, "Layers").
cmake_minimum_required(VERSION 3.25)
if(NOT DEFINED FOLDER OR NOT DEFINED NAME)
  message(FATAL_ERROR "CheckLayerIncludes.cmake needs -DFOLDER=<dir> and -DNAME=<folder name>")
endif()
string(REPLACE "," ";" allowed "${ALLOWED}")
list(APPEND allowed ${NAME})
file(GLOB files ${FOLDER}/*.cpp ${FOLDER}/*.hpp)
set(violations "")
foreach(file IN LISTS files)
  file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]reference/")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[\"<](reference/[^\">]*)[\">].*$" "\\1" header "${line}")
    string(REGEX MATCH "^reference/([^/]+)/" in_folder "${header}")
    if(in_folder)
      set(folder ${CMAKE_MATCH_1})
    else()
      set(folder "")  # a header at the top of reference/ (the registry): above every folder
    endif()
    if(folder STREQUAL "" OR NOT folder IN_LIST allowed)
      cmake_path(GET file FILENAME short)
      string(APPEND violations "\n  reference/${NAME}/${short} includes ${header}")
    endif()
  endforeach()
endforeach()
if(violations)
  list(JOIN allowed ", " allowed_text)
  message(FATAL_ERROR "reference/${NAME}/ may include only reference/{${allowed_text}}/ "
                      "(docs/architecture.md, \"Layers\"):${violations}")
endif()
if(DEFINED STAMP)
  file(TOUCH ${STAMP})
endif()
