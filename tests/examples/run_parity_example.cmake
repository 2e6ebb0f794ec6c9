# examples/parity (docs/api.md, "Test your own function"), as a user would
# build it: a project of its own on this checkout (add_subdirectory), run on
# every runtime it lists; then run with a deliberate mismatch, which must fail
# and name the case.
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
# Every runtime the example lists, chosen by name; then a deliberate mismatch, which must fail naming the case.
run(0 ${WORK_DIR}/my_parity --runtimes)
string(REGEX MATCHALL "[a-z0-9]+" runtimes "${last_output}")
list(LENGTH runtimes n)
if(n LESS 6)
  message(FATAL_ERROR "my_parity --runtimes lists ${n} runtimes (a source build has six): ${last_output}")
endif()
foreach(runtime IN LISTS runtimes)
  run(0 ${WORK_DIR}/my_parity --runtime=${runtime})
  if(NOT last_output MATCHES "my_parity: ${runtime}: 10000 cases, 0 mismatches")
    message(FATAL_ERROR "my_parity --runtime=${runtime}: unexpected report:\n${last_output}")
  endif()
  message(STATUS "${last_output}")
endforeach()
run(1 ${WORK_DIR}/my_parity --deliberate-mismatch)
if(NOT last_output MATCHES "1 mismatches" OR NOT last_output MATCHES "first mismatch: case 42, output 0 'transmittance'")
  message(FATAL_ERROR "my_parity --deliberate-mismatch did not report case 42:\n${last_output}")
endif()
message(STATUS "${last_output}")
run(2 ${WORK_DIR}/my_parity --runtime-typo)
