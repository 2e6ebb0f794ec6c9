# examples/parity (docs/api.md, "Test your own function"), as a user would
# build it: a project of its own on this checkout (add_subdirectory), run; then
# run with a deliberate mismatch, which must fail and name the case.
# -DSOURCE_DIR=<snell repo> -DWORK_DIR=<scratch dir> -DGENERATOR=<cmake generator>
file(REMOVE_RECURSE ${WORK_DIR})
function(run expect)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL expect)
    message(FATAL_ERROR "exit ${rc}, expected ${expect}: ${ARGN}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()
run(0 ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/parity -B ${WORK_DIR} -G ${GENERATOR} -DSNELL_SOURCE=${SOURCE_DIR}
    -DCMAKE_BUILD_TYPE=Release)
run(0 ${CMAKE_COMMAND} --build ${WORK_DIR})
run(0 ${WORK_DIR}/my_parity)
if(NOT last_output MATCHES "10000 cases, 0 mismatches")
  message(FATAL_ERROR "my_parity: unexpected report:\n${last_output}")
endif()
message(STATUS "${last_output}")
run(1 ${WORK_DIR}/my_parity --deliberate-mismatch)
if(NOT last_output MATCHES "1 mismatches" OR NOT last_output MATCHES "first mismatch: case 42, output 0 'transmittance'")
  message(FATAL_ERROR "my_parity --deliberate-mismatch did not report case 42:\n${last_output}")
endif()
message(STATUS "${last_output}")
