# The CGAL exact-intersection oracle, and the mode property suite it judges (which needs its
# verdicts). CGAL is in cgal_oracle.cpp alone (one translation unit: CGAL compiles slowly); the
# judgement and its view-line probes need no CGAL and are built by verify/CMakeLists.txt in
# every configuration. The public header (cgal_oracle.hpp) names no CGAL type.
if(NOT CGAL_FOUND)
  message(FATAL_ERROR "RECODE_WITH_CGAL is ON but CMake found no CGAL 5.5 package "
                      "(Debian: apt-get install libcgal-dev)")
endif()
target_sources(recode_verify PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/oracles/src/cgal_oracle.cpp
                                     ${CMAKE_CURRENT_SOURCE_DIR}/oracles/src/mode_properties.cpp)
target_link_libraries(recode_verify PRIVATE CGAL::CGAL)
target_compile_definitions(recode_verify PUBLIC RECODE_HAVE_CGAL=1)
