# tmcert_ompl_bench (bench/ompl_edges.cpp): time per edge of the certified
# OMPL motion validator against OMPL's DiscreteMotionValidator with FCL as
# the state validity checker (Debian libfcl-dev), on the same edges.
# Skipped without FCL.
find_package(fcl QUIET CONFIG)
if(fcl_FOUND AND TARGET fcl)
  add_executable(tmcert_ompl_bench ${PROJECT_SOURCE_DIR}/bench/ompl_edges.cpp)
  target_link_libraries(tmcert_ompl_bench PRIVATE tmcert_ompl tmcert_lib fcl)
  target_compile_definitions(tmcert_ompl_bench PRIVATE TMCERT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
else()
  message(STATUS "FCL not found (Debian: libfcl-dev): tmcert_ompl_bench is not built")
endif()
