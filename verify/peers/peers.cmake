# The bench's peers (recode bench, docs/benchmarks.md): FCL 0.7 (fcl::Convex with libccd's GJK,
# and OBBRSS triangle meshes) and Bullet 3.24 (float build, btConvexHullShape in a
# btCollisionWorld; on closed meshes, OBBRSS meshes and btGImpactMeshShape). Their types stay in these translation units: peer_detectors.hpp names
# none. FCL comes from its CMake config (fcl.pc would force -std=c++11), Bullet from pkg-config
# (Debian's BulletConfig.cmake has relative paths); both are looked for in the root
# CMakeLists.txt.
set(missing_peer_packages "")
if(NOT fcl_FOUND)
  list(APPEND missing_peer_packages "FCL 0.7 (libfcl-dev)")
endif()
if(NOT BULLET_FOUND)
  list(APPEND missing_peer_packages "Bullet (libbullet-dev)")
endif()
if(missing_peer_packages)
  list(JOIN missing_peer_packages " and " missing_peer_list)
  message(FATAL_ERROR "RECODE_WITH_PEERS is ON but CMake found no ${missing_peer_list} "
                      "(Debian: apt-get install libfcl-dev libbullet-dev)")
endif()
target_sources(recode_verify PRIVATE
  ${CMAKE_CURRENT_SOURCE_DIR}/peers/src/fcl_scene_detector.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/peers/src/fcl_gjk_detector.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/peers/src/fcl_obbrss_detector.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/peers/src/bullet_detector.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/peers/src/fcl_obbrss_closed_peer.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/peers/src/bullet_gimpact_closed_peer.cpp)
target_link_libraries(recode_verify PRIVATE fcl PkgConfig::BULLET)
target_compile_definitions(recode_verify PUBLIC RECODE_HAVE_PEERS=1)
