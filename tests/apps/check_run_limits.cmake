cmake_minimum_required(VERSION 3.25)
# The limits of a run (docs/scenes.md, "Limits of a run"), each refused with its message under a
# 2 GiB address-space cap and a 60 s timeout, and a run at a limit that passes. Expects RECODE
# and DIR (a scratch folder).
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})

# n cones at `spacing` apart along x (0: all at the origin, every pair overlapping).
function(write_cones file n spacing)
  set(objects "")
  math(EXPR last "${n} - 1")
  foreach(i RANGE ${last})
    math(EXPR x "${i} * ${spacing}")
    if(i GREATER 0)
      string(APPEND objects ",")
    endif()
    string(APPEND objects "{\"name\": \"c${i}\", \"shape\": {\"type\": \"cone\", \"radius\": 1, "
                          "\"height\": 2, \"segments\": 8}, \"position\": [${x}, 0, 0]}")
  endforeach()
  file(WRITE ${file} "{\"frames\": 2, \"objects\": [${objects}]}\n")
endfunction()
write_cones(${DIR}/coincident-3000.json 3000 0)
write_cones(${DIR}/row-5000.json 5000 3)
write_cones(${DIR}/coincident-4.json 4 0)

# arguments separated by ~|expected status|stderr pattern (empty: none expected)
set(cases
  "run~${DIR}/coincident-3000.json~--json|1|recode: error: .*coincident-[0-9]*.json: frame 0: at least 100001 block pairs have overlapping boxes, over the limit of 100000 pair tests per frame"
  "verify~${DIR}/row-5000.json|1|recode: error: .*row-5000.json: objects: verify checks every pair of blocks of two objects, and this scene has more than 100000 \\(the limit\\)"
  "run~${DIR}/coincident-4.json~--max-pair-tests~5|1|recode: error: .*coincident-[0-9]*.json: frame 0: at least 6 block pairs have overlapping boxes, over the limit of 5 pair tests per frame"
  "run~${DIR}/coincident-4.json~--max-pair-tests~6~--json|0|"
  "run~${DIR}/coincident-4.json~--max-pair-tests~0|105|--max-pair-tests: Value 0 not in range 1 to 10000000")
set(failed "")
foreach(case IN LISTS cases)
  string(REPLACE "|" ";" fields "${case}")
  list(GET fields 0 args)
  string(REPLACE "~" ";" args "${args}")
  list(GET fields 1 status)
  list(LENGTH fields n)
  set(expected "")
  if(n GREATER 2)
    list(GET fields 2 expected)
  endif()
  set(fields ${args})
  execute_process(COMMAND sh -c "ulimit -v 2097152; exec \"$0\" \"$@\"" ${RECODE} ${fields}
                  TIMEOUT 60 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc STREQUAL status)
    string(APPEND failed "recode ${fields}: status ${rc}, expected ${status}; stderr:\n${err}\n")
  elseif(expected AND NOT err MATCHES "${expected}")
    string(APPEND failed "recode ${fields}: stderr:\n${err}\n  expected: ${expected}\n")
  else()
    message(STATUS "ok: recode ${fields}")
  endif()
endforeach()
file(REMOVE_RECURSE ${DIR})
if(failed)
  message(FATAL_ERROR "${failed}")
endif()
