# SPDX-License-Identifier: MIT
# ctest script: compiles the batched contact kernel with the flags it is built with and fails
# unless GCC reports at least MIN_LOOPS vectorised loops. A kernel loop that stops vectorising
# still gives the right bits, so only this catches it (docs/performance.md, "What was tried").
# Arguments: -DCXX=… -DSOURCE=… -DINCLUDE=… -DMIN_LOOPS=…
execute_process(
  COMMAND ${CXX} -I${INCLUDE} -std=c++20 -O3 -DNDEBUG -fno-math-errno -fno-trapping-math -ffp-contract=off
          -fopt-info-vec-optimized -c ${SOURCE} -o ${CMAKE_CURRENT_BINARY_DIR}/contact_batch_vectorised.o
  RESULT_VARIABLE status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE report)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "compiling ${SOURCE} failed:\n${report}")
endif()
string(REGEX MATCHALL "loop vectorized" loops "${report}")
list(LENGTH loops count)
if(count LESS MIN_LOOPS)
  message(FATAL_ERROR "${SOURCE}: ${count} vectorised loops, expected at least ${MIN_LOOPS} "
                      "(a short-circuit && or a call in the lane loop stops GCC vectorising it)")
endif()
message(STATUS "${SOURCE}: ${count} vectorised loops")
