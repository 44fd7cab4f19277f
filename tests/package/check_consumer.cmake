# Builds a consumer of the library and runs it; the libraries are compiled once for both modes.
# MODE subdirectory: build tests/package/subdirectory, which adds this source tree with
# add_subdirectory (the libraries alone, RECODE_LIBRARY_ONLY being the default there), into
# WORK_DIR/subdirectory, and run its consumer. MODE installed (after subdirectory): install that
# build tree's libraries with RECODE's own install rules into WORK_DIR/prefix, then build
# tests/package/installed against the prefix with find_package(recode) and run it.
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

set(library_build "${WORK_DIR}/subdirectory")
set(prefix "${WORK_DIR}/prefix")
if(MODE STREQUAL "subdirectory")
  file(REMOVE_RECURSE "${WORK_DIR}")
  set(consumer_build "${library_build}")
  run_step("configure the consumer and the libraries" ${CMAKE_COMMAND}
           -S "${RECODE_SOURCE_DIR}/tests/package/subdirectory" -B "${consumer_build}" ${common}
           "-DRECODE_SOURCE_DIR=${RECODE_SOURCE_DIR}" "-DCMAKE_INSTALL_PREFIX=${prefix}")
elseif(MODE STREQUAL "installed")
  if(NOT EXISTS "${library_build}/CMakeCache.txt")
    message(FATAL_ERROR "no library build in ${library_build}: run package/consumer-subdirectory "
                        "first (ctest does: it is this test's fixture)")
  endif()
  file(REMOVE_RECURSE "${prefix}" "${WORK_DIR}/installed")
  run_step("install the libraries" ${CMAKE_COMMAND} --install "${library_build}")
  foreach(file include/recode/pair/pair.hpp include/recode/raster/fragment_stage.hpp
               include/recode/api/collision.hpp
               lib/cmake/recode/recodeConfig.cmake)
    if(NOT EXISTS "${prefix}/${file}")
      message(FATAL_ERROR "the install has no ${file}")
    endif()
  endforeach()
  set(consumer_build "${WORK_DIR}/installed")
  run_step("configure the consumer" ${CMAKE_COMMAND} -S "${RECODE_SOURCE_DIR}/tests/package/installed"
           -B "${consumer_build}" ${common} "-DCMAKE_PREFIX_PATH=${prefix}")
else()
  message(FATAL_ERROR "check_consumer.cmake: MODE is installed or subdirectory, not ${MODE}")
endif()
run_step("build the consumer" ${CMAKE_COMMAND} --build "${consumer_build}" -j 2)
run_step("run the consumer" "${consumer_build}/consumer")
