# recode_embed_text_files(<target> HEADER <name.hpp> NAMESPACE <ns> NAMES <a> <b>... FILES
#                         <a.txt> <b.txt>...)
# Adds to <target> a source, generated at build time by embed_text.cmake, that defines
# `const char* const <a>` (and so on) in namespace <ns> with the text of each file; HEADER (found
# on the target's include path) declares them. Editing a file regenerates the source.
function(recode_embed_text_files target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "HEADER;NAMESPACE" "NAMES;FILES")
  set(out ${CMAKE_CURRENT_BINARY_DIR}/${target}_embedded_text.cpp)
  string(REPLACE ";" "\;" names "${arg_NAMES}")
  string(REPLACE ";" "\;" files "${arg_FILES}")
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} -DHEADER=${arg_HEADER} -DNAMESPACE=${arg_NAMESPACE}
            "-DNAMES=${names}" "-DFILES=${files}" -P ${PROJECT_SOURCE_DIR}/cmake/embed_text.cmake
    DEPENDS ${arg_FILES} ${PROJECT_SOURCE_DIR}/cmake/embed_text.cmake
    COMMENT "Embedding ${target}'s text files")
  target_sources(${target} PRIVATE ${out})
endfunction()
