cmake_minimum_required(VERSION 3.25)
# `recode conform --exec` on back ends that break the protocol (misbehaving_backend.sh): each
# run exits 1 with a message naming what went wrong, within the 2-second timeout (plus the
# start-up and the kill), and its JUnit and JSON reports carry how the back end broke (crashed,
# timed out, flooded, malformed). Expects RECODE, BACKEND and GOLDEN (data/golden).
set(dir ${CMAKE_CURRENT_BINARY_DIR}/conform-misbehaving)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})
file(COPY ${GOLDEN}/fill_square.json DESTINATION ${dir})

function(expect_error mode kind pattern)
  string(TIMESTAMP start "%s")
  execute_process(COMMAND ${RECODE} conform --exec "sh ${BACKEND} ${mode}" --timeout 2
                          --golden ${dir} --junit ${dir}/${mode}.xml
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
  # JUnit: the vector it broke on (or "back end" at the greeting) is an error of that type.
  file(READ ${dir}/${mode}.xml xml)
  if(NOT xml MATCHES "<testcase classname=\"recode.conform\" name=\"[^\"]+\">\n  <error type=\"${kind}\" message=\"")
    message(FATAL_ERROR "${mode}: the JUnit report has no error of type ${kind}:\n${xml}")
  endif()
  # JSON: the same kind, with the message, on stdout; exit 1 still.
  execute_process(COMMAND ${RECODE} conform --exec "sh ${BACKEND} ${mode}" --timeout 2
                          --golden ${dir} --json
                  OUTPUT_VARIABLE json ERROR_VARIABLE err RESULT_VARIABLE rc TIMEOUT 60)
  string(JSON got_kind ERROR_VARIABLE no_kind GET "${json}" error_kind)
  string(JSON got_error ERROR_VARIABLE no_error GET "${json}" error)
  if(NOT rc EQUAL 1 OR NOT got_kind STREQUAL kind OR NOT got_error MATCHES "${pattern}")
    message(FATAL_ERROR "${mode} --json: exit ${rc}, error_kind \"${got_kind}\", expected ${kind}:\n${json}${err}")
  endif()
  message(STATUS "${mode}: exit 1 in ${took} s, ${kind}: ok")
endfunction()

expect_error(silent "timed out" "the greeting: no answer within 2 s")
expect_error(bad-greeting "malformed" "the greeting: expected \"protocol\": \"recode-conform-1\", got \"recode-conform-0\"")
expect_error(hang "timed out" "fill_square.json: back end [^\n]*: request 1: no answer within 2 s")
expect_error(crash "crashed" "request 1: the back end exited with status 139 \\(a shell's report of signal 11, SIGSEGV\\)")
expect_error(exit "crashed" "request 1: the back end exited with status 3")
expect_error(garbage "malformed" "request 1: answer is not JSON: \"hello, world\"")
expect_error(flood "malformed" "request 1: answer is not JSON: \"x\"")
expect_error(flood-line "flooded" "request 1: answer longer than [0-9]+ bytes")
expect_error(stderr-flood "timed out" "request 1: no answer within 2 s\n  its stderr ended with:\nnoise on stderr")
expect_error(wrong-id "malformed" "request 1: answer.id: expected 1, got 99")
expect_error(short "malformed" "request 1: answer.depth: expected an array of width x height = 100 integers, got 3 values")
