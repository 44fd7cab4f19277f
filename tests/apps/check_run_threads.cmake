cmake_minimum_required(VERSION 3.25)
# `recode run SCENE --json --csv` on 1 and on THREADS threads: the same bytes once the wall-clock
# times are taken out (JSON keys ending _us, _ms or _s; the CSV's frame_us and collision_us
# columns). Expects RECODE, SCENE, THREADS and OUT (a directory).

# Runs the scene on `threads` threads; sets <var>_json and <var>_csv to its outputs, times out.
function(run_untimed threads var)
  set(csv ${OUT}/threads-${threads}.csv)
  execute_process(COMMAND ${RECODE} run ${SCENE} --json --csv ${csv} --threads ${threads}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "recode run ${SCENE} --threads ${threads} exited ${rc}: ${err}")
  endif()
  string(REGEX REPLACE "\"([A-Za-z_]+_(us|ms|s))\": [-+0-9.eE]+" "\"\\1\": TIME" json "${json}")
  file(STRINGS ${csv} rows)
  set(untimed "")
  foreach(row IN LISTS rows)
    # frame,frame_us,collision_us,...: drop the second and third fields.
    string(REGEX REPLACE "^([^,]*),[^,]*,[^,]*," "\\1,TIME,TIME," row "${row}")
    string(APPEND untimed "${row}\n")
  endforeach()
  file(WRITE ${OUT}/threads-${threads}.untimed.json "${json}")
  set(${var}_json "${json}" PARENT_SCOPE)
  set(${var}_csv "${untimed}" PARENT_SCOPE)
endfunction()

file(MAKE_DIRECTORY ${OUT})
run_untimed(1 one)
run_untimed(${THREADS} many)
if(NOT one_json MATCHES "\"pair_tests\": [1-9]")
  message(FATAL_ERROR "recode run ${SCENE} ran no pair test: nothing was compared")
endif()
if(NOT one_json STREQUAL many_json)
  message(FATAL_ERROR "recode run ${SCENE} --json: 1 and ${THREADS} threads differ beyond their "
                      "times (diff ${OUT}/threads-1.untimed.json ${OUT}/threads-${THREADS}.untimed.json)")
endif()
if(NOT one_csv STREQUAL many_csv)
  message(FATAL_ERROR "recode run ${SCENE} --csv: 1 and ${THREADS} threads differ beyond their times")
endif()
string(LENGTH "${one_json}" bytes)
message(STATUS "recode run ${SCENE}: ${bytes} bytes of JSON and the CSV the same on 1 and ${THREADS} threads")
