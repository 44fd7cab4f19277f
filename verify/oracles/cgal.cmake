# The CGAL oracles: the exact intersection of convex blocks and the mode property suite it judges
# (which needs its verdicts), and the layered pair's judge. CGAL is in cgal_oracle.cpp and
# cgal_layer_oracle.cpp alone (CGAL compiles slowly); the judgement and its view-line probes need
# no CGAL and are built by verify/CMakeLists.txt in every configuration. The public headers
# (cgal_oracle.hpp, layer_oracle.hpp) name no CGAL type.
if(NOT CGAL_FOUND)
  message(FATAL_ERROR "RECODE_WITH_CGAL is ON but CMake found no CGAL 5.5 package "
                      "(Debian: apt-get install libcgal-dev)")
endif()
target_sources(recode_verify PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/oracles/src/cgal_oracle.cpp
                                     ${CMAKE_CURRENT_SOURCE_DIR}/oracles/src/cgal_layer_oracle.cpp
                                     ${CMAKE_CURRENT_SOURCE_DIR}/oracles/src/mode_properties.cpp)
target_link_libraries(recode_verify PRIVATE CGAL::CGAL)
target_compile_definitions(recode_verify PUBLIC RECODE_HAVE_CGAL=1)
