# The exact Vulkan device. Its GLSL (vulkan/shaders, around the API-neutral contract in
# gl/shaders/exact_contract.glsl) is compiled to SPIR-V at build time by glslangValidator and
# embedded as words, so the device needs neither a shader compiler nor shader files at run time.
if(NOT Vulkan_FOUND OR NOT RECODE_GLSLANG_VALIDATOR)
  message(FATAL_ERROR "RECODE_WITH_VULKAN is ON but the Vulkan headers and loader or "
                      "glslangValidator are missing (Debian: apt-get install libvulkan-dev "
                      "glslang-tools mesa-vulkan-drivers)")
endif()

set(vk_shader_dir ${CMAKE_CURRENT_SOURCE_DIR}/vulkan/shaders)
set(vk_contract ${CMAKE_CURRENT_SOURCE_DIR}/gl/shaders/exact_contract.glsl)
set(vk_spirv_dir ${CMAKE_CURRENT_BINARY_DIR}/vulkan_spirv)
file(MAKE_DIRECTORY ${vk_spirv_dir})
set(vk_spirv_headers)
foreach(stage exact_vk.vert exact_vk.frag clear_vk.vert clear_vk.frag)
  string(REPLACE "." "_" name ${stage})
  set(header ${vk_spirv_dir}/${stage}.h)
  add_custom_command(
    OUTPUT ${header}
    COMMAND ${RECODE_GLSLANG_VALIDATOR} -V --target-env vulkan1.3 -I${CMAKE_CURRENT_SOURCE_DIR}/gl/shaders
            --vn k_${name} -o ${header} ${vk_shader_dir}/${stage}
    DEPENDS ${vk_shader_dir}/${stage} ${vk_contract}
    COMMENT "Compiling ${stage} to SPIR-V")
  list(APPEND vk_spirv_headers ${header})
endforeach()
# The generated headers are only included by vulkan_spirv.cpp; listing them makes it wait.
set_source_files_properties(${CMAKE_CURRENT_SOURCE_DIR}/vulkan/src/vulkan_spirv.cpp PROPERTIES
                            OBJECT_DEPENDS "${vk_spirv_headers}")

target_sources(recode_verify PRIVATE
  ${CMAKE_CURRENT_SOURCE_DIR}/vulkan/src/vulkan_context.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/vulkan/src/vulkan_enums.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/vulkan/src/vulkan_spirv.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/vulkan/src/vulkan_pipeline.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/vulkan/src/vulkan_device.cpp
  ${vk_spirv_headers})
target_include_directories(recode_verify PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/vulkan/src
                                                 ${vk_spirv_dir})
target_link_libraries(recode_verify PRIVATE Vulkan::Vulkan)
target_compile_definitions(recode_verify PUBLIC RECODE_HAVE_VULKAN=1)
