# `cmake --install` puts the libraries' headers and archives under the prefix and a CMake package,
# recode, whose targets carry their usage requirements (include paths, Eigen, nlohmann_json,
# -ffp-contract=off, on which bit-exact depth depends):
#   find_package(recode 0.1 REQUIRED)
#   target_link_libraries(app PRIVATE recode::pair)      # or recode::recode for all of them
# and one component, conformance: recode::conformance and recode::kit, which it is built on (the
# conformance suite for a user's own back end), with the golden vectors under
# share/recode/golden, whose path the package gives as RECODE_GOLDEN_DIR:
#   find_package(recode 0.1 REQUIRED COMPONENTS conformance)
#   target_link_libraries(app_tests PRIVATE recode::conformance Catch2::Catch2WithMain)
#   target_compile_definitions(app_tests PRIVATE RECODE_GOLDEN_DIR="${RECODE_GOLDEN_DIR}")
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(recode_installed_libraries recode_io recode_raster recode_raster_files recode_json
                               recode_geometry recode_pair recode_refine recode_scene recode_sim recode_api)
# The conformance component: its own export set, read by the package only when asked for.
set(recode_conformance_libraries recode_kit recode_conformance)
install(TARGETS ${recode_installed_libraries} recode_all
        EXPORT recodeTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS ${recode_conformance_libraries}
        EXPORT recodeConformanceTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
foreach(library IN LISTS recode_installed_libraries recode_conformance_libraries)
  get_target_property(source_dir ${library} SOURCE_DIR)
  install(DIRECTORY ${source_dir}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
# The golden vectors (data/golden, about 3 MB of JSON), which the installed suite runs.
set(RECODE_GOLDEN_INSTALL_DIR ${CMAKE_INSTALL_DATADIR}/recode/golden)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/golden/ DESTINATION ${RECODE_GOLDEN_INSTALL_DIR}
        FILES_MATCHING PATTERN "*.json")

set(recode_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/recode)
install(EXPORT recodeTargets NAMESPACE recode:: DESTINATION ${recode_package_dir})
install(EXPORT recodeConformanceTargets NAMESPACE recode:: DESTINATION ${recode_package_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/recodeConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/recodeConfig.cmake
                              INSTALL_DESTINATION ${recode_package_dir}
                              PATH_VARS RECODE_GOLDEN_INSTALL_DIR)
# 0.x: a minor version may change the API, so only the same minor version is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/recodeConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/recodeConfig.cmake
              ${PROJECT_BINARY_DIR}/recodeConfigVersion.cmake
        DESTINATION ${recode_package_dir})
