# The Embree interval oracle: hand-made pairs, its power to fail on corrupted results, its depth
# tolerance against the device's depth buffer, and the generated suite.
add_executable(recode_verify_embree_tests oracles/embree_oracle_test.cpp)
target_link_libraries(recode_verify_embree_tests PRIVATE recode_verify recode_warnings
                                                         Catch2::Catch2WithMain)
# pair_test_support.hpp: running a pair, boxes and frames, shared with the pair suites.
target_include_directories(recode_verify_embree_tests PRIVATE ${PROJECT_SOURCE_DIR}/tests/core/pair)
catch_discover_tests(recode_verify_embree_tests)
