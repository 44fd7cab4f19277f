# The header-only packages of the WebAssembly build, taken from the host (Debian's packages):
# Eigen, nlohmann/json, tinyobjloader and stb_image_write. Their headers lie in /usr/include
# beside the host's C library, which must stay off emscripten's include path, so each is
# linked into a folder of its own in the build tree and given as the target the native build
# gets from find_package.
set(host_headers ${CMAKE_BINARY_DIR}/host-headers)
foreach(entry eigen3/Eigen:Eigen nlohmann:nlohmann tiny_obj_loader.h:tiny_obj_loader.h
              stb/stb_image_write.h:stb/stb_image_write.h)
  string(REPLACE ":" ";" parts ${entry})
  list(GET parts 0 from)
  list(GET parts 1 to)
  if(NOT EXISTS /usr/include/${from})
    message(FATAL_ERROR "The WebAssembly build needs /usr/include/${from} (scripts/setup.sh "
                        "installs libeigen3-dev, nlohmann-json3-dev, libtinyobjloader-dev and "
                        "libstb-dev)")
  endif()
  get_filename_component(parent ${host_headers}/${to} DIRECTORY)
  file(MAKE_DIRECTORY ${parent})
  file(CREATE_LINK /usr/include/${from} ${host_headers}/${to} SYMBOLIC)
endforeach()
add_library(Eigen3::Eigen INTERFACE IMPORTED)
target_include_directories(Eigen3::Eigen SYSTEM INTERFACE ${host_headers})
add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
target_include_directories(nlohmann_json::nlohmann_json SYSTEM INTERFACE ${host_headers})
set(TINYOBJLOADER_INCLUDE_DIR ${host_headers})
