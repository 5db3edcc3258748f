# SPDX-License-Identifier: MIT
# Fails when tests/ctest_costs.cmake names a test that ctest does not list, so that a renamed test
# cannot silently lose its place at the front of the queue.
# Usage: cmake -DCTEST=<ctest> -DBUILD=<build tree> -DCOSTS=<costs file> -P CheckTestCosts.cmake
set(DEMWB_TEST_COSTS_LIST_ONLY ON)
include(${COSTS})
execute_process(COMMAND ${CTEST} -N --test-dir ${BUILD} OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "ctest -N failed in ${BUILD}")
endif()
set(missing "")
foreach(entry IN LISTS demwb_test_costs)
  string(REPLACE "=" ";" pair "${entry}")
  list(GET pair 0 name)
  string(FIND "${listing}" ": ${name}\n" at)
  if(at EQUAL -1)
    list(APPEND missing "${name}")
  endif()
endforeach()
list(LENGTH demwb_test_costs named)
if(missing)
  message(FATAL_ERROR "${COSTS} names tests that do not exist: ${missing}")
endif()
message(STATUS "every one of the ${named} tests in ${COSTS} exists")
