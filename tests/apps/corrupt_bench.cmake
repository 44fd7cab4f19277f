cmake_minimum_required(VERSION 3.25)
# Shows recode_check_bench can fail: copies the quick bench's output to OUT with one change,
# chosen by KIND:
# - miscounted: one bullet row's `missed` raised by one (found - extra + missed != truth);
# - no-gl: without the recode-gl rows;
# - view-axis: one recode-view-axis row's `pair_tests` raised by one (not recode-cpu's);
# - skip-apart: one recode-skip-apart row's `contacts` raised by one (not recode-cpu's);
# - batch: one recode-vulkan row's `submissions_per_frame` set to 3 (more than a batch takes);
# - device-wait: one recode-cpu row's `device_wait_ms_per_frame` set to 0.5 (it submits nothing);
# - layered-passes: one recode-layered-512 row's `passes_per_frame` set to 3 (the layered pair
#   draws at least 4 passes where the boxes meet).
# Expects IN, OUT and KIND.
file(REMOVE_RECURSE ${OUT})
file(COPY ${IN}/ DESTINATION ${OUT})
file(STRINGS ${IN}/bench.csv lines)
if(KIND STREQUAL "miscounted")
  set(target "^comb,comb-rotate-aligned,.*,bullet,")
  set(column 13)  # missed
elseif(KIND STREQUAL "view-axis")
  set(target "^comb,comb-rotate-aligned,.*,recode-view-axis,")
  set(column 16)  # pair_tests
elseif(KIND STREQUAL "skip-apart")
  set(target "^comb,comb-rotate-offset,.*,recode-skip-apart,")
  set(column 10)  # contacts
elseif(KIND STREQUAL "batch")
  set(target "^comb,comb-rotate-aligned,.*,recode-vulkan,")
  set(column 20)  # submissions_per_frame
  set(replacement 3.00)
elseif(KIND STREQUAL "device-wait")
  set(target "^comb,comb-rotate-aligned,.*,recode-cpu,")
  set(column 22)  # device_wait_ms_per_frame
  set(replacement 0.5000)
elseif(KIND STREQUAL "layered-passes")
  set(target "^closed,ball-through-torus,.*,recode-layered-512,")
  set(column 30)  # passes_per_frame
  set(replacement 3.00)
elseif(NOT KIND STREQUAL "no-gl")
  message(FATAL_ERROR "KIND must be miscounted, no-gl, view-axis, skip-apart, batch, device-wait "
                      "or layered-passes, not '${KIND}'")
endif()
set(out "")
set(done OFF)
foreach(line IN LISTS lines)
  if(KIND STREQUAL "no-gl" AND line MATCHES ",recode-gl,")
    continue()
  endif()
  if(DEFINED target AND NOT done AND line MATCHES "${target}")
    string(REPLACE "," ";" fields "${line}")
    list(GET fields ${column} value)
    if(DEFINED replacement)
      set(value ${replacement})
    else()
      math(EXPR value "${value} + 1")
    endif()
    list(REMOVE_AT fields ${column})
    list(INSERT fields ${column} ${value})
    list(JOIN fields "," line)
    set(done ON)
  endif()
  string(APPEND out "${line}\n")
endforeach()
if(DEFINED target AND NOT done)
  message(FATAL_ERROR "no row matching ${target} to corrupt in ${IN}/bench.csv")
endif()
file(WRITE ${OUT}/bench.csv "${out}")
