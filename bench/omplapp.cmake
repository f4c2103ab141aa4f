# tmcert_omplapp_fcl (bench/omplapp_fcl.cpp): OMPL.app's own geometry
# (assimp, Debian libassimp-dev) and collision checking (OMPL's
# DiscreteMotionValidator with FCL, libompl-dev and libfcl-dev), for the
# OMPL.app benchmark problems (bench/omplapp_paths.py,
# scripts/omplapp_to_scene.py).  It does not link tmcert.  Optional:
# without assimp or FCL the target is skipped and the rest of the build is
# unchanged.
find_package(fcl QUIET CONFIG)
find_package(assimp QUIET CONFIG)
find_package(ompl QUIET)
if(fcl_FOUND AND TARGET fcl AND assimp_FOUND AND ompl_FOUND)
  add_executable(tmcert_omplapp_fcl ${PROJECT_SOURCE_DIR}/bench/omplapp_fcl.cpp)
  target_include_directories(tmcert_omplapp_fcl SYSTEM PRIVATE ${OMPL_INCLUDE_DIRS})
  if(TARGET assimp::assimp)
    target_link_libraries(tmcert_omplapp_fcl PRIVATE assimp::assimp)
  else()
    target_link_libraries(tmcert_omplapp_fcl PRIVATE ${ASSIMP_LIBRARIES})
  endif()
  target_link_libraries(tmcert_omplapp_fcl PRIVATE fcl ${TMCERT_OMPL_LIBRARY})
else()
  message(STATUS "FCL or assimp not found (Debian: libfcl-dev, libassimp-dev): tmcert_omplapp_fcl is not built")
endif()

# The converter (scripts/omplapp_to_scene.py) and this program end to end on
# a synthetic two-triangle problem (tests/data/omplapp/; under a second).
if(BUILD_TESTING AND TARGET tmcert_omplapp_fcl)
  find_package(Python3 COMPONENTS Interpreter)
  if(Python3_Interpreter_FOUND)
    add_test(NAME omplapp_convert
             COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/regression/omplapp_convert.py
                     $<TARGET_FILE:tmcert_cli> $<TARGET_FILE:tmcert_omplapp_fcl> ${PROJECT_SOURCE_DIR})
  endif()
endif()
