cmake_minimum_required(VERSION 3.25)
# The limits of a run (docs/scenes.md, "Limits of a run"), each refused with its message under a
# 2 GiB address-space cap and a 60 s timeout, and a run at a limit that passes. trees-6 (36
# pairs of 374,004 interfering pixels each) runs under 400 MB: a run keeps no contact points
# (they took 9 MB per pair, all held to the end of the frame). Expects RECODE
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
# Two objects of n coincident child cones each: n * n leaf pairs from one object pair's descent.
function(write_trees file n)
  set(children "")
math(EXPR last "${n} - 1")
foreach(i RANGE ${last})
  if(i GREATER 0)
    string(APPEND children ",")
  endif()
  string(APPEND children "{\"name\": \"c${i}\", \"shape\": {\"type\": \"cone\", \"radius\": 1, "
                         "\"height\": 2, \"segments\": 8}}")
endforeach()
file(WRITE ${file} "{\"objects\": [{\"name\": \"a\", \"children\": [${children}]}, "
                   "{\"name\": \"b\", \"children\": [${children}]}]}\n")
endfunction()
write_trees(${DIR}/trees-30.json 30)
write_trees(${DIR}/trees-6.json 6)

# arguments separated by ~|expected status|stderr pattern (empty: none expected)
set(cases
  "run~${DIR}/coincident-3000.json~--json|1|recode: error: .*coincident-[0-9]*.json: frame 0: at least 100001 block pairs have overlapping boxes, over the limit of 100000 pair tests per frame"
  "verify~${DIR}/row-5000.json|1|recode: error: .*row-5000.json: objects: verify checks every pair of blocks of two objects, and this scene has more than 100000 \\(the limit\\)"
  "run~${DIR}/coincident-4.json~--max-pair-tests~5|1|recode: error: .*coincident-[0-9]*.json: frame 0: at least 6 block pairs have overlapping boxes, over the limit of 5 pair tests per frame"
  "run~${DIR}/coincident-4.json~--max-pair-tests~6~--json|0|"
  "run~${DIR}/trees-30.json~--max-pair-tests~500~--frames~1~--pixel-size~0.05|1|recode: error: .*trees-30.json: frame 0: at least 501 block pairs have overlapping boxes, over the limit of 500"
  "run~${DIR}/trees-30.json~--max-pair-tests~900~--frames~1~--quiet~--pixel-size~0.05|0|"
  "run~${DIR}/trees-6.json~--frames~1~--quiet~--threads~1|0|"
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
  set(cap 2097152)
  if(fields MATCHES "trees-6")
    set(cap 409600)
  endif()
  execute_process(COMMAND sh -c "ulimit -v ${cap}; exec \"$0\" \"$@\"" ${RECODE} ${fields}
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
