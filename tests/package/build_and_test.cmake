# cmake -DSOURCE=<project> -DBINARY=<folder> -DGENERATOR=<generator> -DARGS=<a|b|...>
#       [-DCHECK=<script>] -P build_and_test.cmake
# Configures SOURCE in a fresh BINARY (a stale cache would hide what a new user sees), builds
# it with two jobs, runs its ctest, then CHECK with -DBINARY.
string(REPLACE "|" ";" args "${ARGS}")
file(REMOVE_RECURSE ${BINARY})

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}): ${ARGN}")
  endif()
endfunction()

run(configure ${CMAKE_COMMAND} -S ${SOURCE} -B ${BINARY} -G ${GENERATOR} ${args})
run(build ${CMAKE_COMMAND} --build ${BINARY} -j 2)
run(test ${CMAKE_CTEST_COMMAND} --test-dir ${BINARY} --output-on-failure --no-tests=error)
if(CHECK)
  run(check ${CMAKE_COMMAND} -DBINARY=${BINARY} -P ${CHECK})
endif()
