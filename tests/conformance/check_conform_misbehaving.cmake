cmake_minimum_required(VERSION 3.25)
# `recode conform --exec` on back ends that break the protocol (misbehaving_backend.sh): each
# run exits 1 with a message naming what went wrong, within the 2-second timeout (plus the
# start-up and the kill). Expects RECODE, BACKEND and GOLDEN (data/golden).
set(dir ${CMAKE_CURRENT_BINARY_DIR}/conform-misbehaving)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})
file(COPY ${GOLDEN}/fill_square.json DESTINATION ${dir})

function(expect_error mode pattern)
  string(TIMESTAMP start "%s")
  execute_process(COMMAND ${RECODE} conform --exec "sh ${BACKEND} ${mode}" --timeout 2
                          --golden ${dir}
                  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc TIMEOUT 60)
  string(TIMESTAMP end "%s")
  math(EXPR took "${end} - ${start}")
  if(NOT rc EQUAL 1)
    message(FATAL_ERROR "${mode}: exit ${rc}, expected 1\n${out}${err}")
  endif()
  if(NOT "${out}${err}" MATCHES "${pattern}")
    message(FATAL_ERROR "${mode}: the message does not match ${pattern}:\n${out}${err}")
  endif()
  if(took GREATER 8)
    message(FATAL_ERROR "${mode}: took ${took} s with a 2 s timeout")
  endif()
  message(STATUS "${mode}: exit 1 in ${took} s: ok")
endfunction()

expect_error(silent "the greeting: no answer within 2 s")
expect_error(bad-greeting "the greeting: expected \"protocol\": \"recode-conform-1\", got \"recode-conform-0\"")
expect_error(hang "fill_square.json: back end [^\n]*: request 1: no answer within 2 s")
expect_error(crash "request 1: the back end exited with status 139 \\(a shell's report of signal 11, SIGSEGV\\)")
expect_error(exit "request 1: the back end exited with status 3")
expect_error(garbage "request 1: answer is not JSON: \"hello, world\"")
expect_error(flood "request 1: answer is not JSON: \"x\"")
expect_error(flood-line "request 1: answer longer than [0-9]+ bytes")
expect_error(stderr-flood "request 1: no answer within 2 s\n  its stderr ended with:\nnoise on stderr")
expect_error(wrong-id "request 1: answer.id: expected 1, got 99")
expect_error(short "request 1: answer.depth: expected an array of width x height = 100 integers, got 3 values")
