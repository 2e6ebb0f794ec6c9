# The `bench` target's driver (cmake -P; see CMakeLists.txt for the variables):
# runs snell_bench and snell_bench_functions with JSON output, the lab at each
# size, records the machine's load and each step's wall time, then has
# snell_bench_report write the Markdown report to DOC.
foreach(v BENCH BENCH_FUNCTIONS LAB REPORT OUT DOC MIN_TIME REPETITIONS LAB_SIZES)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_bench.cmake: -D${v}=... is required")
  endif()
endforeach()
file(MAKE_DIRECTORY ${OUT})
set(META ${OUT}/run.txt)

function(load_average out)
  file(READ /proc/loadavg avg)
  string(REGEX MATCH "^[^ ]+ [^ ]+ [^ ]+" avg "${avg}")
  set(${out} "${avg}" PARENT_SCOPE)
endfunction()

# Runs a command, fails the target with its name when it fails, and appends
# "step <name> <seconds>" to the run record.
function(timed_step name)
  string(TIMESTAMP t0 "%s")
  message(STATUS "bench: ${name}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "bench: ${name} failed (${rc}): ${ARGN}")
  endif()
  string(TIMESTAMP t1 "%s")
  math(EXPR dt "${t1} - ${t0}")
  load_average(avg)
  file(APPEND ${META} "step ${name} ${dt}\nload_after ${name} ${avg}\n")
endfunction()

string(TIMESTAMP date "%Y-%m-%d %H:%M UTC" UTC)
load_average(avg)
file(WRITE ${META} "date ${date}\nmin_time ${MIN_TIME}\nrepetitions ${REPETITIONS}\nload_start ${avg}\n")

# Repetitions in random order (Google Benchmark's random interleaving): a burst
# of load from other processes hits one repetition of several benchmarks rather
# than every repetition of one; the report uses the median repetition.
set(gb_flags --benchmark_min_time=${MIN_TIME} --benchmark_repetitions=${REPETITIONS}
    --benchmark_enable_random_interleaving=true --benchmark_out_format=json)
timed_step(snell_bench ${BENCH} ${gb_flags} --benchmark_out=${OUT}/snell_bench.json)
timed_step(snell_bench_functions ${BENCH_FUNCTIONS} ${gb_flags} --benchmark_out=${OUT}/functions.json)

string(REPLACE "," ";" sizes "${LAB_SIZES}")
set(lab_args)
foreach(entry ${sizes})
  string(REPLACE ":" ";" parts "${entry}")
  list(GET parts 0 size)
  list(GET parts 1 frames)
  timed_step(lab_${size} ${LAB} --size ${size}x${size} --frames ${frames} --out ${OUT}/lab-${size} --quiet)
  list(APPEND lab_args --lab ${OUT}/lab-${size}/table.json)
endforeach()

load_average(avg)
file(APPEND ${META} "load_end ${avg}\n")
execute_process(COMMAND ${REPORT} --bench ${OUT}/snell_bench.json --functions ${OUT}/functions.json ${lab_args}
                        --run ${META} --out ${DOC}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "bench: snell_bench_report failed (${rc})")
endif()
message(STATUS "bench: wrote ${DOC} (results in ${OUT})")
