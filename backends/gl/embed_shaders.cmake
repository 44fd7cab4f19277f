# cmake -P embed_shaders.cmake OUT=<file.cpp> NAMES=<a;b> FILES=<a.glsl;b.glsl>
# Writes a C++ source that holds each shader file as a string constant, so the exact devices
# need no shader files at run time. Run at build time: editing a shader rebuilds the device.
set(out_text "// Generated from the exact GL shaders by backends/gl/embed_shaders.cmake. Do not edit.\n")
string(APPEND out_text "#include \"exact_shader_sources.hpp\"\n\nnamespace recode::backends::detail {\n")
list(LENGTH NAMES count)
math(EXPR last "${count} - 1")
foreach(i RANGE ${last})
  list(GET NAMES ${i} name)
  list(GET FILES ${i} file)
  file(READ "${file}" body)
  string(APPEND out_text "\nconst char* const ${name} = R\"glsl(${body})glsl\";\n")
endforeach()
string(APPEND out_text "\n}  // namespace recode::backends::detail\n")
file(WRITE "${OUT}.tmp" "${out_text}")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different "${OUT}.tmp" "${OUT}")
