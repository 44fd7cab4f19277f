cmake_minimum_required(VERSION 3.25)
# Output files are written whole or not at all, and every write is checked (apps/atomic_file.hpp):
# a full device fails with a message and a non-zero status, standard output included; a run or
# an explain that fails midway leaves no partial CSV and no directory, and an earlier CSV as it
# was. Expects RECODE, SOURCE (tests/apps) and DIR (a scratch folder).
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})
set(failed "")

# check(<name> <expected stderr regex> <command>...): status 1 and the message.
function(check name expected)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${DIR} TIMEOUT 60
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
  if(rc EQUAL 1 AND err MATCHES "${expected}")
    message(STATUS "ok: ${name}")
  else()
    set(failed "${failed}${name}: status ${rc}, stderr:\n${err}\n  expected: ${expected}\n"
        PARENT_SCOPE)
  endif()
endfunction()

check("pair --json > /dev/full" "recode: error: writing to standard output failed"
      sh -c "exec \"$0\" pair --json > /dev/full" ${RECODE})
check("run --json > /dev/full" "recode: error: writing to standard output failed"
      sh -c "exec \"$0\" run comb-translate-aligned --frames 3 --json > /dev/full" ${RECODE})
check("run --csv /dev/full" "recode: error: --csv /dev/full: write failed \\(No space left on device\\)"
      ${RECODE} run comb-translate-aligned --frames 3 --quiet --csv /dev/full)
check("pair --dump-cases /dev/full" "recode: error: /dev/full: write failed"
      ${RECODE} pair --resolution 64 --dump-cases /dev/full)
check("replay --dump-stencil /dev/full" "recode: error: /dev/full: write failed"
      ${RECODE} replay ${SOURCE}/../../data/golden/fill_square.json --dump-stencil /dev/full)
check("run --write-scene /dev/full" "recode: error: --write-scene /dev/full: write failed"
      ${RECODE} run comb-translate-aligned --write-scene /dev/full)
check("--csv in a missing folder"
      "recode: error: --csv no/such/run.csv: cannot create a temporary file in no/such to write it"
      ${RECODE} run comb-translate-aligned --frames 3 --quiet --csv no/such/run.csv)

# The run fails at frame 10 (the pair's frame needs more than 16384 pixels a side): no CSV,
# no temporary, and an earlier CSV of that name is left as it was.
check("run failing midway" "frame 10, blocks \"floor\" and \"falling\""
      ${RECODE} run ${SOURCE}/run-fails-midway.json --quiet --csv run.csv)
file(WRITE ${DIR}/kept.csv "an earlier run\n")
check("run failing midway over a CSV" "frame 10"
      ${RECODE} run ${SOURCE}/run-fails-midway.json --quiet --csv kept.csv)
file(READ ${DIR}/kept.csv kept)
if(NOT kept STREQUAL "an earlier run\n")
  string(APPEND failed "the earlier kept.csv was changed to:\n${kept}\n")
endif()
# explain fails in the pair's first pass (the objects lie far outside the tiny window), after it
# made its output directory: the directory is removed again.
check("explain failing midway" "beyond the \\+-32768 pixel range"
      ${RECODE} explain ${SOURCE}/explain-fails-midway.json --out new/explain)
file(GLOB left RELATIVE ${DIR} ${DIR}/* ${DIR}/.*)
list(REMOVE_ITEM left kept.csv)
if(left)
  string(APPEND failed "left behind in ${DIR}: ${left}\n")
endif()

# A successful run replaces the earlier file whole.
execute_process(COMMAND ${RECODE} run comb-translate-aligned --frames 3 --quiet --csv kept.csv
                WORKING_DIRECTORY ${DIR} RESULT_VARIABLE rc OUTPUT_QUIET)
file(STRINGS ${DIR}/kept.csv rows)
list(LENGTH rows n)
if(NOT rc EQUAL 0 OR NOT n EQUAL 4)
  string(APPEND failed "a successful --csv over kept.csv: status ${rc}, ${n} lines\n")
endif()
file(REMOVE_RECURSE ${DIR})
if(failed)
  message(FATAL_ERROR "${failed}")
endif()
