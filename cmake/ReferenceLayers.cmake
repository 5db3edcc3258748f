# SPDX-License-Identifier: MIT
# demwb_reference_folder(NAME [USES folder...]): one folder of reference/ as its own static library
# demwb_reference_<NAME>, linking the libraries of the folders it USES and nothing else of
# reference/. Its build first runs cmake/CheckLayerIncludes.cmake over the folder, which fails when a
# file includes a header of reference/ outside the folder and the folders it uses: a forbidden
# include fails the build (docs/architecture.md, "Layers").
function(demwb_reference_folder name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "USES")
  set(dir ${CMAKE_CURRENT_SOURCE_DIR}/${name})
  file(GLOB sources CONFIGURE_DEPENDS ${dir}/*.cpp)
  file(GLOB files CONFIGURE_DEPENDS ${dir}/*.cpp ${dir}/*.hpp)
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/${name}.layers-checked)
  list(JOIN arg_USES "," allowed)
  set(shown ${name})
  if(allowed)
    string(APPEND shown ",${allowed}")
  endif()
  add_custom_command(
    OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} -DFOLDER=${dir} -DNAME=${name} "-DALLOWED=${allowed}" -DSTAMP=${stamp}
            -P ${PROJECT_SOURCE_DIR}/cmake/CheckLayerIncludes.cmake
    DEPENDS ${files} ${PROJECT_SOURCE_DIR}/cmake/CheckLayerIncludes.cmake
    COMMENT "Checking that reference/${name}/ includes only reference/{${shown}}/"
    VERBATIM)
  add_library(demwb_reference_${name} STATIC ${sources} ${stamp})
  target_include_directories(demwb_reference_${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>)
  set(deps)
  foreach(used IN LISTS arg_USES)
    list(APPEND deps demwb_reference_${used})
  endforeach()
  target_link_libraries(demwb_reference_${name}
    PUBLIC ${deps} demwb_cases
    PRIVATE demwb_dem demwb_support Boost::headers fmt::fmt)
  demwb_set_warnings(demwb_reference_${name})
endfunction()
