# CPU/GL parity on the fixed-function GL device: the golden vectors and the generated suite.
add_executable(recode_verify_gl_parity_tests gl_parity_test.cpp)
# gl_parity_test.cpp reads the golden vectors.
target_link_libraries(recode_verify_gl_parity_tests PRIVATE recode_verify recode_raster_files
                                                            recode_warnings Catch2::Catch2WithMain)
target_compile_definitions(recode_verify_gl_parity_tests PRIVATE
                           RECODE_DATA_DIR="${PROJECT_SOURCE_DIR}/data")
catch_discover_tests(recode_verify_gl_parity_tests)
