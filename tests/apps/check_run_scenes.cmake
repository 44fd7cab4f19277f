cmake_minimum_required(VERSION 3.25)
# `recode run NAME --write-scene` writes exactly data/scenes/NAME.json for every built-in, and
# running the file gives the same run as running the built-in (apart from names and times).
# Expects RECODE, DATA (data/scenes), OUT (a scratch directory) and NAMES (;-separated).
file(MAKE_DIRECTORY ${OUT})
foreach(name IN LISTS NAMES)
  execute_process(COMMAND ${RECODE} run ${name} --write-scene ${OUT}/${name}.json
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "recode run ${name} --write-scene failed (${rc}): ${err}")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/${name}.json
                          ${DATA}/${name}.json RESULT_VARIABLE same)
  if(NOT same EQUAL 0)
    message(FATAL_ERROR "${DATA}/${name}.json differs from the built-in ${name}; regenerate it "
                        "with: recode run ${name} --write-scene ${DATA}/${name}.json")
  endif()
endforeach()

function(run_json what out)
  execute_process(COMMAND ${RECODE} run ${what} --json OUTPUT_VARIABLE json RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "recode run ${what} --json failed with ${rc}")
  endif()
  string(REGEX REPLACE "\"(scene|source)\": \"[^\"]*\"" "" json "${json}")
  string(REGEX REPLACE "\"(frame_us|collision_us|TTF_s|ATF_ms|DTF_ms|TTC_s|ATC_ms|DTC_ms)\": [0-9.e+-]+" "" json "${json}")
  set(${out} "${json}" PARENT_SCOPE)
endfunction()
run_json(comb-translate-aligned builtin)
run_json(${DATA}/comb-translate-aligned.json file)
if(NOT builtin STREQUAL file)
  message(FATAL_ERROR "recode run of the built-in and of its file differ")
endif()
list(LENGTH NAMES n)
message(STATUS "run scenes OK: ${n} files match their built-ins; the comb runs the same from either")
