cmake_minimum_required(VERSION 3.25)
# `recode conform --exec` for CI: --reduce writes a minimal failing vector and its passing twin,
# --write-baseline writes the failures with their stages, --baseline turns them into expected
# ones, fails a vector listed with another stage than it fails at, refuses a line without a stage
# and reports an unexpected pass, --shard splits the vectors, --junit and --html write their
# reports, and a back end whose two answers differ is nondeterministic. The back end is the
# kit's model (MODEL) with a wrong reading.
# Expects RECODE, MODEL, OUT and GOLDEN (data/golden).
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT}/small)
foreach(name fill_square fill_fan depth_less_crossing two_sided_octahedron)
  file(COPY ${GOLDEN}/${name}.json DESTINATION ${OUT}/small)
endforeach()
set(top_left "${MODEL} --variant top_left_fill")

function(run expect_rc)  # expect_rc: a status or several, "0|2"
  execute_process(COMMAND ${RECODE} conform ${ARGN} OUTPUT_VARIABLE out ERROR_VARIABLE err
                  RESULT_VARIABLE rc TIMEOUT 300)
  if(NOT rc MATCHES "^(${expect_rc})$")
    message(FATAL_ERROR "recode conform ${ARGN}: exit ${rc}, expected ${expect_rc}\n${out}${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()
function(expect_match what pattern)
  if(NOT "${out}" MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: output does not match ${pattern}:\n${out}")
  endif()
  message(STATUS "${what}: ok")
endfunction()

# Which of the small set the top-left reading fails, from the JSON report.
run(2 --exec "${top_left}" --golden ${OUT}/small --json)
string(JSON count LENGTH "${out}" results)
set(failing "")
set(passing "")
math(EXPR last "${count} - 1")
foreach(i RANGE ${last})
  string(JSON file GET "${out}" results ${i} file)
  string(JSON passed GET "${out}" results ${i} passed)
  if(passed)
    list(APPEND passing ${file})
  else()
    list(APPEND failing ${file})
    string(JSON stage GET "${out}" results ${i} stage)
    string(JSON section GET "${out}" results ${i} contract_section)
    string(JSON history LENGTH "${out}" results ${i} explained 0 history events)
    if(NOT stage STREQUAL "coverage" OR NOT section MATCHES "section 4" OR history LESS 1)
      message(FATAL_ERROR "${file}: stage ${stage}, section ${section}, ${history} events")
    endif()
  endif()
endforeach()
list(LENGTH failing nfail)
if(nfail EQUAL 0 OR NOT failing MATCHES "fill_square.json")
  message(FATAL_ERROR "the top-left reading should fail fill_square.json; failing: ${failing}")
endif()

# --write-baseline writes each failure with its stage; --baseline reads it back: the failures
# listed are expected (exit 0).
run(2 --exec "${top_left}" --golden ${OUT}/small --explain 0 --write-baseline ${OUT}/baseline.txt)
expect_match("--write-baseline" "baseline written to [^\n]*baseline.txt: ${nfail} expected failures")
file(READ ${OUT}/baseline.txt baseline)
if(NOT baseline MATCHES "\nfill_square.json,coverage\n")
  message(FATAL_ERROR "--write-baseline: no line fill_square.json,coverage in\n${baseline}")
endif()
run(0 --exec "${top_left}" --golden ${OUT}/small --baseline ${OUT}/baseline.txt)
expect_match("--baseline, every failure listed" "expected failure  fill_square.json")

# A listed vector that fails at another stage than its line says is not expected: it fails the
# run, and the text, JSON and JUnit reports say what the baseline expected.
string(REPLACE "fill_square.json,coverage" "fill_square.json,depth test" changed "${baseline}")
file(WRITE ${OUT}/baseline-changed.txt "${changed}")
run(2 --exec "${top_left}" --golden ${OUT}/small --baseline ${OUT}/baseline-changed.txt
    --junit ${OUT}/changed.xml)
expect_match("--baseline, a stage changed"
             "FAIL  fill_square.json \\(baseline expects depth test, now coverage\\)")
expect_match("--baseline, a stage changed, counted" " failed \\(1 at another stage than the baseline's\\)")
file(READ ${OUT}/changed.xml xml)
if(NOT xml MATCHES "<failure message=\"coverage: [^\"]*\\(baseline expects depth test, now coverage\\)\"")
  message(FATAL_ERROR "--baseline, a stage changed: JUnit says nothing of it:\n${xml}")
endif()
run(2 --exec "${top_left}" --golden ${OUT}/small --baseline ${OUT}/baseline-changed.txt --json)
string(JSON count_after LENGTH "${out}" results)
math(EXPR last_after "${count_after} - 1")
foreach(i RANGE ${last_after})
  string(JSON file GET "${out}" results ${i} file)
  if(file STREQUAL "fill_square.json")
    string(JSON status GET "${out}" results ${i} status)
    string(JSON expected_stage GET "${out}" results ${i} baseline_stage)
    if(NOT status STREQUAL "FAIL" OR NOT expected_stage STREQUAL "depth test")
      message(FATAL_ERROR "--json, a stage changed: status ${status}, baseline_stage ${expected_stage}")
    endif()
  endif()
endforeach()

# A line with a name and no stage is refused, naming the file, the line and the form.
file(WRITE ${OUT}/baseline-names.txt "# old form\nfill_square.json\n")
run(1 --exec "${top_left}" --golden ${OUT}/small --baseline ${OUT}/baseline-names.txt)
set(out "${err}")
expect_match("--baseline, a name without a stage"
             "--baseline [^\n]*baseline-names.txt:2: \"fill_square.json\" has no stage: expected NAME,STAGE")

# A listed vector that passes is an unexpected pass.
if(passing)
  list(GET passing 0 first_passing)
  file(APPEND ${OUT}/baseline.txt "${first_passing},coverage\n")
  run(2 --exec "${top_left}" --golden ${OUT}/small --baseline ${OUT}/baseline.txt)
  expect_match("--baseline, a passing vector listed" "UNEXPECTED PASS  ${first_passing}")
endif()

# --shard: two shards hold every vector once.
run("0|2" --exec "${top_left}" --golden ${OUT}/small --shard 0/2 --explain 0)
string(REGEX MATCH "\n([0-9]+) vectors:" m "${out}")
set(first ${CMAKE_MATCH_1})
run("0|2" --exec "${top_left}" --golden ${OUT}/small --shard 1/2 --explain 0)
string(REGEX MATCH "\n([0-9]+) vectors:" m "${out}")
math(EXPR both "${first} + ${CMAKE_MATCH_1}")
if(NOT both EQUAL count OR first EQUAL 0)
  message(FATAL_ERROR "--shard: ${first} + ${CMAKE_MATCH_1} vectors, expected ${count} in all")
endif()
run(1 --exec "${top_left}" --golden ${OUT}/small --shard 2/2)
expect_match("--shard 2/2 refused" "")

# --junit and --html.
run(2 --exec "${top_left}" --golden ${OUT}/small --junit ${OUT}/report.xml --html ${OUT}/report.html)
file(READ ${OUT}/report.xml xml)
if(NOT xml MATCHES "<testsuite name=\"recode conform: [^\"]*\" tests=\"${count}\" failures=\"${nfail}\""
   OR NOT xml MATCHES "<failure message=\"coverage: rasterization.md section 4")
  message(FATAL_ERROR "--junit: unexpected report:\n${xml}")
endif()
file(READ ${OUT}/report.html html)
if(NOT html MATCHES "<canvas class=\"mask\"" OR NOT html MATCHES "behaves like: [^\n]*top_left_fill"
   OR NOT html MATCHES "the contract's history of the pixel")
  message(FATAL_ERROR "--html: no error mask, reading or history in ${OUT}/report.html")
endif()
message(STATUS "--junit, --html: ok")

# Nondeterministic: every second answer differs.
run(2 --exec "${MODEL} --flaky" --golden ${OUT}/small)
expect_match("--flaky back end" "NONDETERMINISTIC  ")

# --reduce: a minimal vector that still fails the same way, and a passing twin.
run(2 --exec "${top_left}" --golden ${OUT}/small --explain 0 --reduce ${OUT}/reduced)
expect_match("--reduce" "reduced [^ ]+ in [0-9]+ runs to [1-4] draws, [1-8] triangles")
file(GLOB reduced ${OUT}/reduced/*-minimal.json)
if(NOT reduced)
  message(FATAL_ERROR "--reduce wrote no minimal vector")
endif()
run(0 --golden ${OUT}/reduced)
expect_match("the reduced vectors' expected buffers are the reference's" " 0 failed")
run(2 --exec "${top_left}" --golden ${OUT}/reduced --explain 0)
expect_match("the minimal vector still fails" "FAIL  [^\n]*-minimal.json")
if(EXISTS ${OUT}/reduced/)
  file(GLOB twins ${OUT}/reduced/*-passing-twin.json)
  if(twins)
    expect_match("the twin passes" "pass  [^\n]*-passing-twin.json")
  endif()
endif()
