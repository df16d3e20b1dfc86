# bench_dynamics: steps per second of a bead, a constrained particle and chains of 10, 100
# and 1,000 particles, with the same chains in Box2D 2.4 (libbox2d-dev) in the same run.
find_package(box2d 2.4 REQUIRED)
grape_bench(dynamics grape::dynamics grape_scenes box2d::box2d)
# Box2D v3 (not a Debian package) as an optional peer of the chains: point GRAPE_BOX2D3_DIR
# at a Box2D v3 source tree; nothing is downloaded. Its C sources are compiled here the way
# its own CMakeLists compiles them by default (C17, -ffp-contract=off, SSE2, no validation).
set(GRAPE_BOX2D3_DIR "" CACHE PATH "Box2D v3 source tree for bench_dynamics (optional peer)")
if(GRAPE_BOX2D3_DIR)
  if(NOT EXISTS ${GRAPE_BOX2D3_DIR}/src/solver.c OR NOT EXISTS ${GRAPE_BOX2D3_DIR}/include/box2d/box2d.h)
    message(FATAL_ERROR "GRAPE_BOX2D3_DIR (${GRAPE_BOX2D3_DIR}) has no src/solver.c and include/box2d/box2d.h")
  endif()
  enable_language(C)
  file(GLOB box2d3_sources CONFIGURE_DEPENDS ${GRAPE_BOX2D3_DIR}/src/*.c)
  add_library(grape_bench_box2d3 STATIC EXCLUDE_FROM_ALL ${box2d3_sources})
  target_include_directories(grape_bench_box2d3 PRIVATE ${GRAPE_BOX2D3_DIR}/include ${GRAPE_BOX2D3_DIR}/src)
  set_target_properties(grape_bench_box2d3 PROPERTIES C_STANDARD 17 C_STANDARD_REQUIRED YES C_EXTENSIONS YES)
  target_compile_options(grape_bench_box2d3 PRIVATE -ffp-contract=off)
  # Box2D 2.4's headers must not shadow v3's in the peer's own file: it gets v3's include
  # path first, and the two libraries' symbols differ (v3 is C, 2.4 is C++).
  target_sources(bench_dynamics PRIVATE bench_dynamics_box2d3.cpp)
  set_source_files_properties(bench_dynamics_box2d3.cpp PROPERTIES INCLUDE_DIRECTORIES ${GRAPE_BOX2D3_DIR}/include)
  target_link_libraries(bench_dynamics PRIVATE grape_bench_box2d3)
  target_compile_definitions(bench_dynamics PRIVATE GRAPE_BENCH_BOX2D3=1)
endif()
