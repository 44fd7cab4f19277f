# Builds a consumer of the library and runs it. MODE installed: configure this source tree with
# RECODE_LIBRARY_ONLY=ON, build, install into a prefix under WORK_DIR, then build
# tests/package/installed against that prefix. MODE subdirectory: build
# tests/package/subdirectory, which adds the source tree itself.
# Arguments: -DMODE=installed|subdirectory -DRECODE_SOURCE_DIR=... -DWORK_DIR=... -DGENERATOR=...
# [-DLAUNCHER=...]
foreach(var MODE RECODE_SOURCE_DIR WORK_DIR GENERATOR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_consumer.cmake: ${var} is not set")
  endif()
endforeach()
set(common -G "${GENERATOR}" -DCMAKE_BUILD_TYPE=Release)
if(LAUNCHER)
  list(APPEND common -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${what}: ok")
endfunction()

file(REMOVE_RECURSE "${WORK_DIR}")
if(MODE STREQUAL "installed")
  set(prefix "${WORK_DIR}/prefix")
  run_step("configure the libraries" ${CMAKE_COMMAND} -S "${RECODE_SOURCE_DIR}"
           -B "${WORK_DIR}/library" ${common} -DRECODE_LIBRARY_ONLY=ON
           "-DCMAKE_INSTALL_PREFIX=${prefix}")
  run_step("build the libraries" ${CMAKE_COMMAND} --build "${WORK_DIR}/library" -j 2)
  run_step("install the libraries" ${CMAKE_COMMAND} --install "${WORK_DIR}/library")
  foreach(file include/recode/pair/pair.hpp include/recode/raster/fragment_stage.hpp
               include/recode/api/collision.hpp
               lib/cmake/recode/recodeConfig.cmake)
    if(NOT EXISTS "${prefix}/${file}")
      message(FATAL_ERROR "the install has no ${file}")
    endif()
  endforeach()
  set(consumer_args -S "${RECODE_SOURCE_DIR}/tests/package/installed" "-DCMAKE_PREFIX_PATH=${prefix}")
elseif(MODE STREQUAL "subdirectory")
  set(consumer_args -S "${RECODE_SOURCE_DIR}/tests/package/subdirectory"
                    "-DRECODE_SOURCE_DIR=${RECODE_SOURCE_DIR}")
else()
  message(FATAL_ERROR "check_consumer.cmake: MODE is installed or subdirectory, not ${MODE}")
endif()
run_step("configure the consumer" ${CMAKE_COMMAND} ${consumer_args} -B "${WORK_DIR}/consumer"
         ${common})
run_step("build the consumer" ${CMAKE_COMMAND} --build "${WORK_DIR}/consumer" -j 2)
run_step("run the consumer" "${WORK_DIR}/consumer/consumer")
