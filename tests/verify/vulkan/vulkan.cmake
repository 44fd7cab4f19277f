# The exact Vulkan device against the reference (lavapipe here, or whatever driver the loader
# finds first by preference: a GPU before a CPU driver).
add_executable(recode_verify_vulkan_tests vulkan/vulkan_device_test.cpp)
target_link_libraries(recode_verify_vulkan_tests PRIVATE recode_verify recode_raster_files
                                                         recode_exact_test_streams
                                                         recode_warnings Catch2::Catch2WithMain)
catch_discover_tests(recode_verify_vulkan_tests)
