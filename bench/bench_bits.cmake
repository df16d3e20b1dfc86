# bench_bits: BitVector against boost::dynamic_bitset (libboost-dev, header-only),
# std::vector<bool>, std::bitset and memcpy.
find_package(Boost 1.74 REQUIRED)
grape_bench(bits grape::bits Boost::headers)
# boost's count() for the popcnt instruction too, in a file of its own (the default build of
# every contender stays the x86-64 baseline).
target_sources(bench_bits PRIVATE bench_bits_boost_popcnt.cpp)
if(CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64")
  set_source_files_properties(bench_bits_boost_popcnt.cpp PROPERTIES COMPILE_OPTIONS -mpopcnt)
endif()
# BitMagic (not a Debian package) as an optional peer of SparseBitVector: point
# GRAPE_BITMAGIC_DIR at a BitMagic source tree; nothing is downloaded.
set(GRAPE_BITMAGIC_DIR "" CACHE PATH "BitMagic source tree for bench_bits (optional peer)")
if(GRAPE_BITMAGIC_DIR)
  if(NOT EXISTS ${GRAPE_BITMAGIC_DIR}/src/bm.h)
    message(FATAL_ERROR "GRAPE_BITMAGIC_DIR (${GRAPE_BITMAGIC_DIR}) has no src/bm.h")
  endif()
  target_sources(bench_bits PRIVATE bench_bits_bitmagic.cpp)
  target_include_directories(bench_bits SYSTEM PRIVATE ${GRAPE_BITMAGIC_DIR}/src)
  target_compile_definitions(bench_bits PRIVATE GRAPE_BENCH_BITMAGIC=1)
  # BitMagic's AVX2 build, in its own translation unit only.
  set_source_files_properties(bench_bits_bitmagic.cpp PROPERTIES
                              COMPILE_OPTIONS "-mavx2;-mpopcnt;-mbmi;-mbmi2;-mlzcnt" COMPILE_DEFINITIONS BMAVX2OPT)
endif()
