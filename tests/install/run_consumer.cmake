# The consumer matrix: installs snell into a scratch prefix, then
# builds and runs tests/install/consumer against it through find_package and
# pkg-config, and against the source tree through add_subdirectory and
# FetchContent; checks that the installed snell-flatten runs and that a
# consumer's own install does not install snell (SNELL_INSTALL is off there).
# -DSOURCE_DIR=<snell repo> -DWORK_DIR=<scratch dir> -DGENERATOR=<cmake generator> [-DCXX=<compiler>]
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/snell-build -G ${GENERATOR}
    -DSNELL_BUILD_TESTS=OFF -DSNELL_BUILD_EXAMPLES=OFF -DCMAKE_INSTALL_PREFIX=${prefix})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/snell-build)
run(${CMAKE_COMMAND} --install ${WORK_DIR}/snell-build)

foreach(mode find_package add_subdirectory FetchContent)
  set(b ${WORK_DIR}/consumer-${mode})
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer -B ${b} -G ${GENERATOR}
      -DSNELL_CONSUME=${mode} -DSNELL_SOURCE=${SOURCE_DIR} -DCMAKE_PREFIX_PATH=${prefix})
  run(${CMAKE_COMMAND} --build ${b})
  run(${b}/snell_consumer)
  message(STATUS "${mode}: ${last_output}")
  if(NOT mode STREQUAL "find_package")
    run(${CMAKE_COMMAND} --install ${b} --prefix ${WORK_DIR}/consumer-prefix-${mode})
    file(GLOB_RECURSE leaked ${WORK_DIR}/consumer-prefix-${mode}/*snell*)
    list(FILTER leaked EXCLUDE REGEX "/bin/snell_consumer$")
    if(leaked)
      message(FATAL_ERROR "${mode}: the consumer's install installed snell too:\n${leaked}")
    endif()
  endif()
endforeach()

# pkg-config, as a Makefile would use it.
find_program(PKG_CONFIG pkg-config REQUIRED)
set(ENV{PKG_CONFIG_PATH} ${prefix}/share/pkgconfig)
foreach(var cflags glsldir hlsldir singlefiledir)
  if(var STREQUAL "cflags")
    run(${PKG_CONFIG} --cflags --libs snell-gpu)
  else()
    run(${PKG_CONFIG} --variable=${var} snell)
  endif()
  string(STRIP "${last_output}" pc_${var})
endforeach()
separate_arguments(pc_flags UNIX_COMMAND "${pc_cflags}")
if(NOT CXX)
  set(CXX c++)
endif()
run(${CXX} -std=c++17 ${pc_flags} -DSNELL_GLSL_DIR="${pc_glsldir}" -DSNELL_HLSL_DIR="${pc_hlsldir}"
    -DSNELL_SINGLE_FILE_DIR="${pc_singlefiledir}" ${SOURCE_DIR}/tests/install/consumer/main.cpp
    -o ${WORK_DIR}/consumer-pkg-config ${pc_flags})
run(${WORK_DIR}/consumer-pkg-config)
message(STATUS "pkg-config (${pc_cflags}): ${last_output}")

# The installed snell-flatten finds the installed GLSL tree by itself.
file(WRITE ${WORK_DIR}/user.frag "#version 300 es\n#extension GL_GOOGLE_include_directive : require\nprecision highp float;\n#include \"snell/optics.glsl\"\nout vec4 c;\nvoid main() { c = vec4(snellIorToEta(1.0f, 1.5f)); }\n")
run(${prefix}/bin/snell-flatten --no-line ${WORK_DIR}/user.frag -o ${WORK_DIR}/user.flat.frag)
file(READ ${WORK_DIR}/user.flat.frag flat)
if(flat MATCHES "GL_GOOGLE_include_directive" OR NOT flat MATCHES "snellIorToEta\\(float")
  message(FATAL_ERROR "installed snell-flatten: unexpected output in ${WORK_DIR}/user.flat.frag")
endif()
message(STATUS "consumer built and ran in every mode: find_package, add_subdirectory, FetchContent, pkg-config")
