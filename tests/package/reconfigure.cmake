# cmake -DSOURCE=<grape> -DBINARY=<folder> -DGENERATOR=<generator> -DCXX=<compiler> -P reconfigure.cmake
# GRAPE_WITH_DYNAMICS left at AUTO follows Eigen at every configure: off while Eigen is hidden
# (the summary names libeigen3-dev), on once it can be found, in the same build folder; an
# explicit ON without Eigen stops the configure naming the package. Configures only.
file(REMOVE_RECURSE ${BINARY})
set(lean -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX} -DGRAPE_BUILD_TESTS=OFF -DGRAPE_INSTALL=OFF
    -DGRAPE_WITH_RENDER=OFF -DGRAPE_WITH_SCENE=OFF -DGRAPE_WITH_TOOL=OFF -DGRAPE_WITH_STUDIO=OFF)

# configure(EXPECT_STATUS OUT ARGS...)
function(configure expect_status out)
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${BINARY} ${ARGN}
                  RESULT_VARIABLE status OUTPUT_VARIABLE text ERROR_VARIABLE error)
  if(expect_status STREQUAL "ok" AND NOT status EQUAL 0)
    message(FATAL_ERROR "configure ${ARGN} failed:\n${text}\n${error}")
  elseif(expect_status STREQUAL "fail" AND status EQUAL 0)
    message(FATAL_ERROR "configure ${ARGN} succeeded, expected an error:\n${text}")
  endif()
  set(${out} "${text}${error}" PARENT_SCOPE)
endfunction()

function(expect text pattern what)
  if(NOT text MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: no match for '${pattern}' in:\n${text}")
  endif()
  message(STATUS "ok: ${what}")
endfunction()

function(expect_config value)
  file(READ ${BINARY}/include/grape/config.hpp config)
  expect("${config}" "#define GRAPE_HAS_DYNAMICS ${value}" "config.hpp has GRAPE_HAS_DYNAMICS ${value}")
endfunction()

configure(ok text ${lean} -DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=ON)
expect("${text}" "dynamics +off +Eigen3[^\n]*not found: apt install libeigen3-dev" "Eigen hidden: dynamics off, naming the package")
expect_config(0)

configure(ok text -DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=OFF)
expect("${text}" "dynamics +on +found Eigen [0-9]" "Eigen findable again: dynamics on in the same folder")
expect_config(1)
file(STRINGS ${BINARY}/CMakeCache.txt cached REGEX "^GRAPE_WITH_DYNAMICS:")
expect("${cached}" "^GRAPE_WITH_DYNAMICS:STRING=AUTO$" "the cache keeps the request AUTO")

configure(fail text -DGRAPE_WITH_DYNAMICS=ON -DCMAKE_DISABLE_FIND_PACKAGE_Eigen3=ON)
expect("${text}" "GRAPE_WITH_DYNAMICS=ON, but Eigen3.*libeigen3-dev" "explicit ON without Eigen: an error naming the package")
file(REMOVE_RECURSE ${BINARY})
