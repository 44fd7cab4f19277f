# Configures and builds tests/link (raster + geometry + pair alone) in BINARY_DIR, then checks
# the probe's link command names no library of the other layers' packages and runs the probe.
# Arguments: -DRECODE_SOURCE_DIR=... -DBINARY_DIR=... -DGENERATOR=... [-DLAUNCHER=...]
# [-DWERROR=ON|OFF] (the main build's RECODE_WERROR: the same command lines, so the compiler
# cache's objects)
foreach(var RECODE_SOURCE_DIR BINARY_DIR GENERATOR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_backend_link.cmake: ${var} is not set")
  endif()
endforeach()

file(REMOVE_RECURSE "${BINARY_DIR}")
set(configure_args -S "${RECODE_SOURCE_DIR}/tests/link" -B "${BINARY_DIR}" -G "${GENERATOR}"
                   -DCMAKE_BUILD_TYPE=Release -DRECODE_SOURCE_DIR=${RECODE_SOURCE_DIR})
if(LAUNCHER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
if(DEFINED WERROR)
  list(APPEND configure_args -DRECODE_WERROR=${WERROR})
endif()
execute_process(COMMAND ${CMAKE_COMMAND} ${configure_args} RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "raster + geometry + pair did not configure on their own:\n${out}\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build "${BINARY_DIR}" -j 2 -- -v RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "raster + geometry + pair did not build on their own:\n${out}\n${err}")
endif()

# The probe's link command: the verbose build's line that writes the executable.
string(REPLACE "\n" ";" lines "${out}")
set(link_line "")
foreach(line IN LISTS lines)
  if(line MATCHES "-o recode_backend_probe( |$)")
    set(link_line "${line}")
  endif()
endforeach()
if(link_line STREQUAL "")
  message(FATAL_ERROR "no link command for recode_backend_probe in the build output:\n${out}")
endif()
foreach(forbidden tinyobjloader nlohmann json CLI11 embree CGAL gmp mpfr OSMesa fcl Bullet)
  string(TOLOWER "${link_line}" lower)
  string(TOLOWER "${forbidden}" needle)
  string(FIND "${lower}" "${needle}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "the probe's link line names ${forbidden}:\n${link_line}")
  endif()
endforeach()
message(STATUS "link line: ${link_line}")

execute_process(COMMAND "${BINARY_DIR}/recode_backend_probe" RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "probe: ${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the probe did not find the cones' contact (exit ${rc})")
endif()
