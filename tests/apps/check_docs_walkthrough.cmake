cmake_minimum_required(VERSION 3.25)
# docs/algorithm.md section 7 shows pictures of `recode explain --resolution 96` in
# docs/img/walkthrough/: each must be, byte for byte, the picture of that name that the command
# writes today (inspector.png, a browser screenshot, excepted), and every picture the section
# embeds must exist there. Regenerate with the command in section 7 when the pictures change.
# Variables: RECODE, DOCS (the docs directory), OUT (a scratch directory).
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${RECODE} explain --resolution 96 --out ${OUT}
                OUTPUT_QUIET RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "recode explain failed with ${rc}")
endif()
file(GLOB pictures RELATIVE ${DOCS}/img/walkthrough ${DOCS}/img/walkthrough/*.png)
set(compared 0)
foreach(picture IN LISTS pictures)
  if(picture STREQUAL "inspector.png")
    continue()
  endif()
  if(NOT EXISTS ${OUT}/${picture})
    message(FATAL_ERROR "docs/img/walkthrough/${picture}: recode explain no longer writes it")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${DOCS}/img/walkthrough/${picture}
                          ${OUT}/${picture} RESULT_VARIABLE differ)
  if(NOT differ EQUAL 0)
    message(FATAL_ERROR "docs/img/walkthrough/${picture} differs from what recode explain writes")
  endif()
  math(EXPR compared "${compared} + 1")
endforeach()
file(READ ${DOCS}/algorithm.md text)
string(REGEX MATCHALL "img/walkthrough/[A-Za-z0-9_.-]+\\.png" embedded "${text}")
foreach(picture IN LISTS embedded)
  if(NOT EXISTS ${DOCS}/${picture})
    message(FATAL_ERROR "docs/algorithm.md embeds ${picture}, which is missing")
  endif()
endforeach()
list(LENGTH embedded count)
message("walkthrough pictures OK: ${compared} identical, ${count} embedded")
