# The exact GL device against the reference, on every context platform the build has.
add_executable(recode_verify_gl_exact_tests gl/gl_exact_device_test.cpp)
target_link_libraries(recode_verify_gl_exact_tests PRIVATE recode_verify recode_raster_files
                                                           recode_exact_test_streams
                                                           recode_warnings Catch2::Catch2WithMain)
target_compile_definitions(recode_verify_gl_exact_tests PRIVATE
                           RECODE_DATA_DIR="${PROJECT_SOURCE_DIR}/data")
catch_discover_tests(recode_verify_gl_exact_tests)
