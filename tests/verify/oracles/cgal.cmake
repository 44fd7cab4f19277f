# The CGAL exact-intersection oracle: exact facts by construction, the judgement's power to
# fail on corrupted results, and the generated pair suite judged pair by pair.
add_executable(recode_verify_cgal_tests oracles/cgal_oracle_test.cpp)
target_link_libraries(recode_verify_cgal_tests PRIVATE recode_verify recode_warnings
                                                       Catch2::Catch2WithMain)
# pair_test_support.hpp: running a pair, boxes and frames, shared with the pair suites.
target_include_directories(recode_verify_cgal_tests PRIVATE ${PROJECT_SOURCE_DIR}/tests/core/pair)
catch_discover_tests(recode_verify_cgal_tests)

# The modes above the reference (core/refine) against CGAL on a third of the suite.
add_executable(recode_verify_modes_tests oracles/modes_test.cpp)
target_link_libraries(recode_verify_modes_tests PRIVATE recode_verify recode_warnings
                                                        Catch2::Catch2WithMain)
catch_discover_tests(recode_verify_modes_tests)

# The modes' promises on generated pairs at and near contact under small turns (a bounded run;
# the long run is the hidden case [.long], its size from RECODE_PROPERTY_CASES).
add_executable(recode_verify_mode_property_tests oracles/mode_properties_test.cpp)
target_link_libraries(recode_verify_mode_property_tests PRIVATE recode_verify recode_warnings
                                                                Catch2::Catch2WithMain)
catch_discover_tests(recode_verify_mode_property_tests)

# The adaptive view axis's rules against CGAL on a third of the suite.
add_executable(recode_verify_view_axis_tests oracles/view_axis_test.cpp)
target_link_libraries(recode_verify_view_axis_tests PRIVATE recode_verify recode_warnings
                                                            Catch2::Catch2WithMain)
catch_discover_tests(recode_verify_view_axis_tests)

# The contact normal against the exact intersection solid's thinnest direction (a slice of the
# suite; the whole suite's table is the hidden case [.normal-accuracy]).
add_executable(recode_verify_normal_tests oracles/contact_normal_oracle_test.cpp)
target_link_libraries(recode_verify_normal_tests PRIVATE recode_verify recode_warnings
                                                         Catch2::Catch2WithMain)
target_include_directories(recode_verify_normal_tests PRIVATE ${PROJECT_SOURCE_DIR}/tests/core/pair)
catch_discover_tests(recode_verify_normal_tests)

# The layered pair against CGAL: pixels against exact crossings, verdicts, the overlap volume.
add_executable(recode_verify_layer_tests oracles/layer_oracle_test.cpp)
target_link_libraries(recode_verify_layer_tests PRIVATE recode_verify recode_warnings
                                                        Catch2::Catch2WithMain)
target_include_directories(recode_verify_layer_tests PRIVATE ${PROJECT_SOURCE_DIR}/tests/core/pair)
catch_discover_tests(recode_verify_layer_tests)

# The layered pair on CGAL's demo meshes (the fixture of tests/core unpacks them at test time).
add_executable(recode_verify_layer_real_tests oracles/layer_real_meshes_test.cpp)
target_link_libraries(recode_verify_layer_real_tests PRIVATE recode_verify recode_warnings
                                                             Catch2::Catch2WithMain)
target_include_directories(recode_verify_layer_real_tests PRIVATE
                           ${PROJECT_SOURCE_DIR}/tests/core/pair)
target_compile_definitions(recode_verify_layer_real_tests PRIVATE
  RECODE_CGAL_DEMO_MESHES="${PROJECT_BINARY_DIR}/tests/core/cgal_demo/data/meshes")
catch_discover_tests(recode_verify_layer_real_tests
                     PROPERTIES FIXTURES_REQUIRED cgal_demo_meshes COST 60)
