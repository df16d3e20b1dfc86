# Cross-builds grape for 64-bit Windows with Debian's MinGW-w64 (posix threads) and runs the
# tests under Wine (scripts/run-windows-tests):
#   cmake -S . -B build-windows -DCMAKE_TOOLCHAIN_FILE=cmake/toolchain-mingw-w64.cmake
# Debian has no MinGW builds of cairo, SDL2 or GoogleTest: render and the studio are off, and
# the tests build GoogleTest from its source (GRAPE_GTEST_SOURCE=/usr/src/googletest).
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(triple x86_64-w64-mingw32)

set(CMAKE_C_COMPILER ${triple}-gcc-posix)
set(CMAKE_CXX_COMPILER ${triple}-g++-posix)
set(CMAKE_RC_COMPILER ${triple}-windres)

# Libraries and headers come from the MinGW tree only; programs (pkg-config, python) from the host.
set(CMAKE_FIND_ROOT_PATH /usr/${triple})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# pkg-config would otherwise offer the host's cairo and SDL2.
set(ENV{PKG_CONFIG_LIBDIR} /usr/${triple}/lib/pkgconfig)
set(ENV{PKG_CONFIG_PATH} "")

# The programs carry their runtime (libgcc, libstdc++, winpthread), so Wine runs them without
# copying DLLs next to them.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static-libgcc -static-libstdc++ -static")
set(CMAKE_SHARED_LINKER_FLAGS_INIT "-static-libgcc -static-libstdc++ -static")

# ctest and gtest_discover_tests run the .exe files through Wine, by scripts/wine-run: it runs
# a program again when Wine itself failed to start it (see there).
find_program(GRAPE_WINE NAMES wine64 wine PATHS /usr/lib/wine)
if(GRAPE_WINE)
  get_filename_component(wine_run ${CMAKE_CURRENT_LIST_DIR}/../scripts/wine-run ABSOLUTE)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${wine_run})
endif()

set(GRAPE_WITH_RENDER OFF CACHE STRING "cairo has no MinGW build in Debian")
set(GRAPE_WITH_STUDIO OFF CACHE STRING "SDL2 and Dear ImGui have no MinGW build in Debian")

# The header-only dependencies are used from the host's packages. Their config files put
# /usr/include on the include path, whose glibc headers would shadow MinGW's: a folder holding
# only their headers stands in for /usr (the configs find their prefix from where they lie).
get_property(in_try_compile GLOBAL PROPERTY IN_TRY_COMPILE)
if(NOT in_try_compile AND CMAKE_BINARY_DIR)
  set(host_headers ${CMAKE_BINARY_DIR}/host-headers)
  foreach(link IN ITEMS include/nlohmann include/CLI share/cmake/nlohmann_json share/cmake/CLI11)
    if(EXISTS /usr/${link} AND NOT EXISTS ${host_headers}/${link})
      get_filename_component(parent ${host_headers}/${link} DIRECTORY)
      file(MAKE_DIRECTORY ${parent})
      file(CREATE_LINK /usr/${link} ${host_headers}/${link} SYMBOLIC)
    endif()
  endforeach()
  set(nlohmann_json_DIR ${host_headers}/share/cmake/nlohmann_json CACHE PATH "nlohmann-json's config (host headers)")
  set(CLI11_DIR ${host_headers}/share/cmake/CLI11 CACHE PATH "CLI11's config (host headers)")
  set(Eigen3_DIR /usr/share/eigen3/cmake CACHE PATH "Eigen's config (its include folder holds only Eigen)")
endif()
