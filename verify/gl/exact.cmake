# The exact GL device, on whichever context platforms are built (OSMesa, EGL). Its shaders are
# files in gl/shaders, embedded into a generated source at build time.
set(shader_dir ${CMAKE_CURRENT_SOURCE_DIR}/gl/shaders)
set(shader_files ${shader_dir}/exact_contract.glsl ${shader_dir}/exact_gl.vert
                 ${shader_dir}/exact_gl.frag)
set(shader_source ${CMAKE_CURRENT_BINARY_DIR}/exact_shader_sources.cpp)
add_custom_command(
  OUTPUT ${shader_source}
  COMMAND ${CMAKE_COMMAND} -DOUT=${shader_source}
          "-DNAMES=kExactContractGlsl\;kExactGlVertex\;kExactGlFragment"
          "-DFILES=${shader_dir}/exact_contract.glsl\;${shader_dir}/exact_gl.vert\;${shader_dir}/exact_gl.frag"
          -P ${CMAKE_CURRENT_SOURCE_DIR}/gl/embed_shaders.cmake
  DEPENDS ${shader_files} ${CMAKE_CURRENT_SOURCE_DIR}/gl/embed_shaders.cmake
  COMMENT "Embedding the exact devices' shaders")
target_sources(recode_verify PRIVATE
  ${CMAKE_CURRENT_SOURCE_DIR}/gl/src/gl_functions.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/gl/src/exact_program.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/gl/src/gl_exact_device.cpp
  ${shader_source})
target_include_directories(recode_verify PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/gl/src)
target_compile_definitions(recode_verify PUBLIC RECODE_HAVE_GL_EXACT=1)
