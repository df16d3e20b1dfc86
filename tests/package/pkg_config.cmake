# cmake -DPKGCONFIG_DIR=<prefix>/lib/pkgconfig -DCXX=<compiler> -DSOURCE=consumer.cpp
#       -DBINARY=<folder> -DMODULES=<dynamics|render|scene> -P pkg_config.cmake
# `c++ -std=c++20 consumer.cpp $(pkg-config --cflags --libs grape)` builds and runs, and every
# optional module's grape-<module>.pc resolves (its Requires included).
find_program(PKG_CONFIG pkg-config REQUIRED)
set(ENV{PKG_CONFIG_PATH} ${PKGCONFIG_DIR})
file(REMOVE_RECURSE ${BINARY})
file(MAKE_DIRECTORY ${BINARY})

function(pkg_config out)
  execute_process(COMMAND ${PKG_CONFIG} ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE text
                  ERROR_VARIABLE error OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "pkg-config ${ARGN} failed: ${error}")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

pkg_config(libdir --variable=libdir grape)

# build_and_run(NAME DEFINES PACKAGES...): compiles consumer.cpp with the packages' flags, runs it.
function(build_and_run name defines)
  pkg_config(flags --cflags --libs ${ARGN})
  message(STATUS "pkg-config --cflags --libs ${ARGN}: ${flags}")
  separate_arguments(flags UNIX_COMMAND "${flags}")
  execute_process(COMMAND ${CXX} -std=c++20 -Wall -Wextra -Wpedantic ${defines} ${SOURCE} ${flags}
                          -Wl,-rpath,${libdir} -o ${BINARY}/${name}
                  RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "compiling ${SOURCE} with the flags of pkg-config ${ARGN} failed")
  endif()
  execute_process(COMMAND ${BINARY}/${name} RESULT_VARIABLE status OUTPUT_VARIABLE out)
  message(STATUS "${name}: ${out}")
  if(NOT status EQUAL 0 OR NOT out MATCHES ": ok\n$")
    message(FATAL_ERROR "${name}, built with the flags of pkg-config ${ARGN}, failed")
  endif()
endfunction()

build_and_run(core -DCONSUMER_CORE_ONLY grape)
string(REPLACE "|" ";" modules "${MODULES}")
set(packages grape)
foreach(module IN LISTS modules)
  list(APPEND packages grape-${module})
endforeach()
build_and_run(all "" ${packages})
