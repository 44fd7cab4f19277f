cmake_minimum_required(VERSION 3.25)
# --no-timing: each command's --json, run twice, prints the same bytes, and none of the
# wall-clock keys (apps/no_timing.hpp). Expects RECODE and VERIFY (ON when verify's default
# oracles, Embree and CGAL, are built).
set(commands
  "pair|--json|--no-timing"
  "pair|--json|--no-timing|--mor|full|--resolution|96"
  "run|comb-translate-aligned|--frames|12|--json|--no-timing"
  "run|hierarchy-9|--frames|5|--json|--no-timing")
if(VERIFY)
  list(APPEND commands "verify|--suite|--count|8|--json|--no-timing")
endif()
set(timing_keys timing_us timing_steps_us frame_us collision_us TTF_s ATF_ms DTF_ms TTC_s ATC_ms
                DTC_ms seconds)
foreach(command IN LISTS commands)
  string(REPLACE "|" ";" args "${command}")
  execute_process(COMMAND ${RECODE} ${args} RESULT_VARIABLE rc1 OUTPUT_VARIABLE first)
  execute_process(COMMAND ${RECODE} ${args} RESULT_VARIABLE rc2 OUTPUT_VARIABLE second)
  if(NOT rc1 EQUAL 0 OR NOT rc2 EQUAL 0 OR first STREQUAL "")
    message(FATAL_ERROR "recode ${args}: status ${rc1} and ${rc2}")
  endif()
  if(NOT first STREQUAL second)
    message(FATAL_ERROR "recode ${args}: two runs printed different bytes")
  endif()
  foreach(key IN LISTS timing_keys)
    if(first MATCHES "\"${key}\"")
      message(FATAL_ERROR "recode ${args}: the output still has \"${key}\"")
    endif()
  endforeach()
  message(STATUS "same bytes twice: recode ${args}")
endforeach()
