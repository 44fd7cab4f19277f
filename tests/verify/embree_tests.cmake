# The Embree interval oracle: hand-made pairs, its power to fail on corrupted results, its depth
# tolerance against the device's depth buffer, and the generated suite.
add_executable(recode_verify_embree_tests embree_oracle_test.cpp)
target_link_libraries(recode_verify_embree_tests PRIVATE recode_verify recode_warnings
                                                         Catch2::Catch2WithMain)
catch_discover_tests(recode_verify_embree_tests)
