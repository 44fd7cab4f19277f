# The bench's peer detectors (FCL, Bullet) and its exact judge on scenes whose answers follow
# from their construction, over the built-in comb and random motions, and Bullet's manifolds.
add_executable(recode_verify_peers_tests peers/peer_detector_test.cpp)
target_link_libraries(recode_verify_peers_tests PRIVATE recode_verify recode_warnings
                                                        Catch2::Catch2WithMain)
# comb_test_support.hpp: the comb's contact frame, shared with the simulation suites.
target_include_directories(recode_verify_peers_tests PRIVATE ${PROJECT_SOURCE_DIR}/tests/core/sim)
catch_discover_tests(recode_verify_peers_tests)
