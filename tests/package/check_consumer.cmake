# Builds a consumer of the library and runs it; the libraries are compiled once for both modes.
# MODE subdirectory: build tests/package/subdirectory, which adds this source tree with
# add_subdirectory (the libraries alone, RECODE_LIBRARY_ONLY being the default there), into
# WORK_DIR/subdirectory, and run its consumer. MODE installed (after subdirectory): install that
# build tree's libraries with RECODE's own install rules into WORK_DIR/prefix, then build
# tests/package/installed against the prefix with find_package(recode) and run it. In both
# modes the consumer also builds a back end's conformance tests (tests/package/conformance.cpp,
# Catch2 with recode/conformance/catch2.hpp): its device must pass every golden vector, and its
# deliberately broken one (the tests tagged [broken]) must fail with a report naming the stage
# and the wrong reading.
# Arguments: -DMODE=installed|subdirectory -DRECODE_SOURCE_DIR=... -DWORK_DIR=... -DGENERATOR=...
# [-DLAUNCHER=...] [-DWERROR=ON|OFF] (the main build's RECODE_WERROR, given to the libraries' build:
# the main build's command lines, so the compiler cache's objects)
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

set(werror "")
if(DEFINED WERROR)
  set(werror -DRECODE_WERROR=${WERROR})
endif()

set(library_build "${WORK_DIR}/subdirectory")
set(prefix "${WORK_DIR}/prefix")
if(MODE STREQUAL "subdirectory")
  file(REMOVE_RECURSE "${WORK_DIR}")
  set(consumer_build "${library_build}")
  run_step("configure the consumer and the libraries" ${CMAKE_COMMAND}
           -S "${RECODE_SOURCE_DIR}/tests/package/subdirectory" -B "${consumer_build}" ${common}
           "-DRECODE_SOURCE_DIR=${RECODE_SOURCE_DIR}" "-DCMAKE_INSTALL_PREFIX=${prefix}"
           ${werror})
elseif(MODE STREQUAL "installed")
  if(NOT EXISTS "${library_build}/CMakeCache.txt")
    message(FATAL_ERROR "no library build in ${library_build}: run package/consumer-subdirectory "
                        "first (ctest does: it is this test's fixture)")
  endif()
  file(REMOVE_RECURSE "${prefix}" "${WORK_DIR}/installed")
  run_step("install the libraries" ${CMAKE_COMMAND} --install "${library_build}")
  foreach(file include/recode/pair/pair.hpp include/recode/raster/fragment_stage.hpp
               include/recode/api/collision.hpp
               include/recode/conformance/catch2.hpp include/recode/conformance/suite.hpp
               include/recode/kit/variants.hpp
               lib/librecode_conformance.a lib/librecode_kit.a
               lib/cmake/recode/recodeConfig.cmake lib/cmake/recode/recodeConformanceTargets.cmake)
    if(NOT EXISTS "${prefix}/${file}")
      message(FATAL_ERROR "the install has no ${file}")
    endif()
  endforeach()
  # Every golden vector, in the same folders.
  file(GLOB_RECURSE source_vectors RELATIVE "${RECODE_SOURCE_DIR}/data/golden"
       "${RECODE_SOURCE_DIR}/data/golden/*.json")
  file(GLOB_RECURSE installed_vectors RELATIVE "${prefix}/share/recode/golden"
       "${prefix}/share/recode/golden/*.json")
  if(NOT source_vectors STREQUAL installed_vectors)
    list(LENGTH source_vectors n_source)
    list(LENGTH installed_vectors n_installed)
    message(FATAL_ERROR "the install has ${n_installed} golden vectors under share/recode/golden, "
                        "data/golden has ${n_source}")
  endif()
  set(consumer_build "${WORK_DIR}/installed")
  run_step("configure the consumer" ${CMAKE_COMMAND} -S "${RECODE_SOURCE_DIR}/tests/package/installed"
           -B "${consumer_build}" ${common} "-DCMAKE_PREFIX_PATH=${prefix}")
else()
  message(FATAL_ERROR "check_consumer.cmake: MODE is installed or subdirectory, not ${MODE}")
endif()
run_step("build the consumer" ${CMAKE_COMMAND} --build "${consumer_build}" -j 2)
run_step("run the consumer" "${consumer_build}/consumer")

# The conformance tests: one assertion per golden vector, all passing.
file(GLOB_RECURSE golden_vectors "${RECODE_SOURCE_DIR}/data/golden/*.json")
list(LENGTH golden_vectors n_vectors)
execute_process(COMMAND "${consumer_build}/conformance" RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "All tests passed \\(${n_vectors} assertions")
  message(FATAL_ERROR "the conformance tests failed (${rc}; expected ${n_vectors} passing "
                      "assertions):\n${out}")
endif()
message(STATUS "the conformance tests pass on the ${n_vectors} golden vectors: ok")
# The broken device must fail, and the report must say where and what (Catch wraps long lines).
execute_process(COMMAND "${consumer_build}/conformance" "[broken]" RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE out)
set(ws "[ \t\r\n]+")
foreach(expected "FAIL${ws}[^ ]+[.]json:" "stage:${ws}stencil,"
                 "behaves${ws}like:${ws}INCR${ws}wraps${ws}at${ws}255")
  if(rc EQUAL 0 OR NOT out MATCHES "${expected}")
    string(REPLACE "${ws}" " " shown "${expected}")
    message(FATAL_ERROR "the broken device's conformance tests should fail with a report "
                        "matching '${shown}' (exit status ${rc}):\n${out}")
  endif()
endforeach()
message(STATUS "the broken device fails, named at the stencil stage: ok")
