cmake_minimum_required(VERSION 3.25)
# `recode pair` and `recode run` with --device DEVICE give the CPU device's output bytes, timing
# aside (--no-timing): the built-in pair in every mode and with --pixel, and every built-in scene
# (batched, from the device's summaries, on several devices a frame size, and the hands also pair
# by pair), and the layered pair of two closed meshes. Expects RECODE, DEVICE, OUT, SCENES (the
# project's data/scenes); with LARGE set, the bench's largest meshes instead
# (below); with LIGHT set, a lighter round for a device that is slow
# on this machine's CPU driver (every scene batched and from summaries, one scene on 16 devices,
# the schedules on the hands: the paths of the device interface, not every combination of the
# core's).
# The CPU device's outputs are computed once for every device: with DEVICE=cpu the script writes
# them all (the full round's, of which the light round's are a part) into OUT and compares
# nothing (the test cli/device-same-bytes-cpu-reference); with REFERENCE set to that folder, a
# device's round reads them there instead of running the CPU device again.

# Runs `recode ARGS... --device device`; sets <var> to its standard output.
function(recode_output var device)
  execute_process(COMMAND ${RECODE} ${ARGN} --device ${device}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "recode ${ARGN} --device ${device} exited ${rc}: ${err}")
  endif()
  set(${var} "${out}" PARENT_SCOPE)
endfunction()

function(expect_same what)
  string(MAKE_C_IDENTIFIER "${what}" name)
  if(DEFINED REFERENCE)
    if(NOT EXISTS ${REFERENCE}/${name}.cpu.txt)
      message(FATAL_ERROR "recode ${what}: no CPU output ${REFERENCE}/${name}.cpu.txt (the test "
                          "cli/device-same-bytes-cpu-reference writes it; ctest runs it first)")
    endif()
    file(READ ${REFERENCE}/${name}.cpu.txt reference)
  else()
    recode_output(reference cpu ${ARGN})
  endif()
  file(WRITE ${OUT}/${name}.cpu.txt "${reference}")
  if(NOT reference MATCHES "\"interfering_pixels\": [1-9]|\"pair_tests\": [1-9]")
    message(FATAL_ERROR "recode ${what}: no pixel interfered and no pair was tested: nothing was compared")
  endif()
  if(DEVICE STREQUAL "cpu")
    message(STATUS "recode ${what}: the CPU device's output written")
    return()
  endif()
  recode_output(candidate ${DEVICE} ${ARGN})
  file(WRITE ${OUT}/${name}.${DEVICE}.txt "${candidate}")
  if(NOT reference STREQUAL candidate)
    message(FATAL_ERROR "recode ${what}: --device ${DEVICE} differs from --device cpu "
                        "(diff ${OUT}/${name}.cpu.txt ${OUT}/${name}.${DEVICE}.txt)")
  endif()
  message(STATUS "recode ${what}: ${DEVICE} and cpu give the same bytes")
endfunction()

if(DEVICE STREQUAL "cpu")
  file(REMOVE_RECURSE ${OUT})  # no output of an earlier run read as this one's
endif()
file(MAKE_DIRECTORY ${OUT})
# With LARGE set: the bench's largest tessellation levels instead, a few frames each, where a job
# of the compute device's lists more triangles than a CPU driver lets one invocation loop over.
if(LARGE)
  expect_same("run random-shapes at 11,520 a block" run random-shapes --triangles-per-block 11520
              --frames 3 --json --no-timing)
  expect_same("run comb-rotate-aligned at 4,096 a block" run comb-rotate-aligned
              --triangles-per-block 4096 --frames 3 --json --no-timing)
  expect_same("run random-cones at 1,152 a block" run random-cones --triangles-per-block 1152
              --frames 3 --json --no-timing)
  return()
endif()
foreach(mode reference adaptive conservative skip-apart)
  expect_same("pair --mode ${mode}" pair --json --no-timing --mode ${mode})
endforeach()
expect_same("pair --pixel 128,128" pair --json --no-timing --pixel 128,128)
# Closed meshes: the layered pair's count and capture passes (SCENES: data/scenes).
expect_same("pair rings-overlapping" pair ${SCENES}/rings-overlapping.json --json --no-timing)
expect_same("pair rings-overlapping --mor max" pair ${SCENES}/rings-overlapping.json --json
            --no-timing --mor max)
# Every built-in scene, whole: a frame's pair tests run as one batch on a device that defers
# its commands, so every frame size and contact schedule of the scenes is compared.
foreach(scene comb-translate-aligned comb-translate-offset comb-rotate-aligned comb-rotate-offset
              random-cones random-shapes hand-grasp hierarchy-9)
  expect_same("run ${scene}" run ${scene} --json --no-timing)
endforeach()
# The leaves' boxes made on the host instead of by a device that keeps the blocks
# (vulkan-compute reduces them by default; elsewhere this is the default path): the same bytes.
expect_same("run hand-grasp --leaf-boxes host" run hand-grasp --json --no-timing --leaf-boxes host)
# Pair by pair instead (the path the bench's per-pair column times): the same bytes too.
expect_same("run hand-grasp --per-pair" run hand-grasp --json --no-timing --per-pair)
# The contact passes drawn with the stencil passes, one submission a frame: the same bytes.
expect_same("run hand-grasp --contact-schedule speculative" run hand-grasp --json --no-timing
            --contact-schedule speculative)
# Each pair test concluded from the device's 64-byte summaries (--summaries: a compute shader
# on vulkan, vulkan-32 and gl-exact), speculatively and after the verdict: the same bytes on
# every built-in scene; without the contact passes too.
foreach(scene comb-translate-aligned comb-translate-offset comb-rotate-aligned comb-rotate-offset
              random-cones random-shapes hand-grasp hierarchy-9)
  if(NOT LIGHT)
    expect_same("run ${scene} --summaries --contact-schedule speculative" run ${scene} --json
                --no-timing --summaries --contact-schedule speculative)
  endif()
  expect_same("run ${scene} --summaries" run ${scene} --json --no-timing --summaries)
endforeach()
if(LIGHT)
  expect_same("run hand-grasp --summaries --contact-schedule speculative" run hand-grasp --json
              --no-timing --summaries --contact-schedule speculative)
  expect_same("run hand-grasp --batch-devices 16 --summaries --contact-schedule speculative" run
              hand-grasp --json --no-timing --batch-devices 16 --summaries
              --contact-schedule speculative)
  return()
endif()
expect_same("run hand-grasp --summaries --no-contact" run hand-grasp --json --no-timing
            --summaries --no-contact)
# Up to 16 devices a frame size: a frame's pair tests recorded in waves of pairs on devices of
# their own, after the verdict and speculatively from summaries: the same bytes too.
foreach(scene comb-translate-offset random-shapes hand-grasp)
  expect_same("run ${scene} --batch-devices 16" run ${scene} --json --no-timing --batch-devices 16)
  expect_same("run ${scene} --batch-devices 16 --summaries --contact-schedule speculative" run
              ${scene} --json --no-timing --batch-devices 16 --summaries
              --contact-schedule speculative)
endforeach()
