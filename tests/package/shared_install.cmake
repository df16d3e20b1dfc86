# cmake -DSOURCE=<grape> -DBINARY=<folder> -DPREFIX=<prefix> -DGENERATOR=<generator> -DARGS=<a|b|...>
#       -P shared_install.cmake
# grape's libraries alone (no tool, tests or studio), shared, built in a fresh BINARY and
# installed to a fresh PREFIX; then how many symbols each library exports, from nm.
string(REPLACE "|" ";" args "${ARGS}")
file(REMOVE_RECURSE ${BINARY} ${PREFIX})

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}): ${ARGN}")
  endif()
endfunction()

run(configure ${CMAKE_COMMAND} -S ${SOURCE} -B ${BINARY} -G ${GENERATOR} -DBUILD_SHARED_LIBS=ON
    -DGRAPE_BUILD_TESTS=OFF -DGRAPE_WITH_TOOL=OFF -DGRAPE_WITH_STUDIO=OFF -DGRAPE_INSTALL=ON ${args})
run(build ${CMAKE_COMMAND} --build ${BINARY} -j 2)
run(install ${CMAKE_COMMAND} --install ${BINARY} --prefix ${PREFIX})

find_program(NM nm)
if(NM)
  file(GLOB libraries ${PREFIX}/lib*/libgrape_*.so)
  foreach(library IN LISTS libraries)
    execute_process(COMMAND ${NM} -D --defined-only ${library} OUTPUT_VARIABLE symbols RESULT_VARIABLE status)
    if(status EQUAL 0)
      string(REGEX MATCHALL "\n" lines "\n${symbols}")
      list(LENGTH lines count)
      math(EXPR count "${count} - 1")
      get_filename_component(name ${library} NAME)
      message(STATUS "${name}: ${count} exported symbols")
    endif()
  endforeach()
endif()
