# tmcert_planner_bench (bench/planner_path.cpp): a planner's path certified by
# tmcert against FCL's discrete checks (Debian libfcl-dev, FCL 0.7, which
# provides the CMake package `fcl`).  Optional: without FCL the target is
# skipped and the rest of the build is unchanged.
find_package(fcl QUIET CONFIG)
if(fcl_FOUND AND TARGET fcl)
  add_executable(tmcert_planner_bench ${PROJECT_SOURCE_DIR}/bench/planner_path.cpp)
  target_link_libraries(tmcert_planner_bench PRIVATE tmcert_lib fcl nlohmann_json::nlohmann_json)
  target_compile_definitions(tmcert_planner_bench PRIVATE TMCERT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
else()
  message(STATUS "FCL not found (Debian: libfcl-dev): tmcert_planner_bench is not built")
endif()
