cmake_minimum_required(VERSION 3.25)
# `recode run` on the Vulkan devices under the Khronos validation layer with synchronization
# validation: no error. The recorder leaves barriers out between commands on different images
# (docs/architecture.md, "Inside the devices"); on lavapipe a missing one would not change a
# result, so this is what holds the rule to the specification. Covers the batch after the
# verdict and speculatively, the waves (--batch-devices) and the summaries' compute pass.
# Expects RECODE; exits 77 (skipped) when the layer is not installed (Debian:
# vulkan-validationlayers).

set(manifest_found FALSE)
foreach(dir /usr/share/vulkan/explicit_layer.d /etc/vulkan/explicit_layer.d
            /usr/local/share/vulkan/explicit_layer.d)
  if(EXISTS ${dir}/VkLayer_khronos_validation.json)
    set(manifest_found TRUE)
  endif()
endforeach()
if(NOT manifest_found)
  message("SKIP: the Khronos validation layer is not installed (vulkan-validationlayers)")
  cmake_language(EXIT 77)
endif()

set(ENV{VK_INSTANCE_LAYERS} VK_LAYER_KHRONOS_validation)
set(ENV{VK_LAYER_ENABLES} VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT)

function(expect_clean)
  execute_process(COMMAND ${RECODE} run ${ARGN} --quiet
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "recode run ${ARGN} exited ${rc}: ${err}")
  endif()
  string(REGEX MATCH "Validation Error: [^\n]*" first "${out}${err}")
  if(first)
    message(FATAL_ERROR "recode run ${ARGN}: ${first}")
  endif()
  if(NOT out MATCHES "contacts [1-9]")
    message(FATAL_ERROR "recode run ${ARGN}: no contact, so little was drawn: ${out}")
  endif()
  message(STATUS "recode run ${ARGN}: no validation error")
endfunction()

foreach(device vulkan vulkan-32 vulkan-compute vulkan-native)
  expect_clean(hand-grasp --frames 80 --device ${device})
  expect_clean(hand-grasp --frames 80 --device ${device} --summaries)
endforeach()
expect_clean(comb-translate-offset --frames 40 --device vulkan --contact-schedule speculative)
expect_clean(comb-translate-offset --frames 40 --device vulkan --batch-devices 16 --summaries
             --contact-schedule speculative)
expect_clean(random-shapes --frames 20 --device vulkan --batch-devices 16)
