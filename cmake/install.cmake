# `cmake --install` puts the libraries' headers and archives under the prefix and a CMake package,
# recode, whose targets carry their usage requirements (include paths, Eigen, nlohmann_json,
# -ffp-contract=off, on which bit-exact depth depends):
#   find_package(recode 0.1 REQUIRED)
#   target_link_libraries(app PRIVATE recode::pair)      # or recode::recode for all of them
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(recode_installed_libraries recode_io recode_raster recode_raster_files recode_json
                               recode_geometry recode_pair recode_refine recode_scene recode_sim recode_api)
install(TARGETS ${recode_installed_libraries} recode_all
        EXPORT recodeTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
foreach(library IN LISTS recode_installed_libraries)
  get_target_property(source_dir ${library} SOURCE_DIR)
  install(DIRECTORY ${source_dir}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()

set(recode_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/recode)
install(EXPORT recodeTargets NAMESPACE recode:: DESTINATION ${recode_package_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/recodeConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/recodeConfig.cmake
                              INSTALL_DESTINATION ${recode_package_dir})
# 0.x: a minor version may change the API, so only the same minor version is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/recodeConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/recodeConfig.cmake
              ${PROJECT_BINARY_DIR}/recodeConfigVersion.cmake
        DESTINATION ${recode_package_dir})
