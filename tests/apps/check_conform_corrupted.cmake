cmake_minimum_required(VERSION 3.25)
# A golden vector with one expected byte changed must fail: `recode conform` names it with its
# first differing pixel and exits 2, and `recode replay --diff` (text and --json) lists that
# pixel. Copies data/golden/fill_square.json into OUT with the expected stencil at (2, 2)
# changed from 1 to 7. Expects RECODE, GOLDEN (data/golden) and OUT.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
file(READ ${GOLDEN}/fill_square.json text)
string(JSON before GET "${text}" expected stencil 2 2)
if(NOT before EQUAL 1)
  message(FATAL_ERROR "fill_square.json: expected stencil at (2, 2) is ${before}, not 1")
endif()
string(JSON text SET "${text}" expected stencil 2 2 7)
file(WRITE ${OUT}/fill_square.json "${text}")
file(COPY ${GOLDEN}/fill_fan.json DESTINATION ${OUT})

function(run_expecting status pattern)
  execute_process(COMMAND ${RECODE} ${ARGN} OUTPUT_VARIABLE out ERROR_VARIABLE err
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL ${status})
    message(FATAL_ERROR "recode ${ARGN}: exit ${rc}, expected ${status}\n${out}${err}")
  endif()
  if(NOT out MATCHES "${pattern}")
    message(FATAL_ERROR "recode ${ARGN}: output does not match ${pattern}:\n${out}")
  endif()
endfunction()

run_expecting(2
  "  pass  fill_fan.json\n  FAIL  fill_square.json: 0 depth, 1 stencil pixels differ\n\nFailures explained:\n  FAIL  fill_square.json: 0 depth, 1 stencil pixels differ\n        stage: [^\n]*\n.*pixel \\(2, 2\\): stencil expected 7, got 1\n.*\n2 vectors: 1 passed, 1 failed"
  conform --device cpu --golden ${OUT})
run_expecting(2
  "\"failed\": 1,.*\"depth_pixels\": 0,\n.*\"file\": \"fill_square.json\",\n   \"first_difference\": {\n    \"buffer\": \"stencil\",\n    \"expected\": 7,\n    \"got\": 1,\n    \"x\": 2,\n    \"y\": 2\n   },\n.*\"passed\": false"
  conform --golden ${OUT} --json)
run_expecting(1 "MISMATCH \\(0 depth, 1 stencil pixels differ\\)\n  \\(2, 2\\) stencil expected 7, got 1\n$"
  replay ${OUT}/fill_square.json --diff)
run_expecting(1 "\"differences\": \\[\n  {\n   \"buffer\": \"stencil\",\n   \"expected\": 7,\n   \"got\": 1,\n   \"x\": 2,\n   \"y\": 2\n  }\n \\]"
  replay ${OUT}/fill_square.json --diff --json)
