# After the build: grape's libraries are there and none of its programs or test executables.
# -DBINARY=<the consumer's build folder>
file(GLOB_RECURSE libraries RELATIVE ${BINARY}/grape ${BINARY}/grape/*libgrape_*)
if(NOT libraries MATCHES "libgrape_path\\.(a|so)")
  message(FATAL_ERROR "grape's libraries were not built: ${libraries}")
endif()
foreach(pattern grape grape-studio png-check test_* bench_* libgrape_scenes*)
  file(GLOB_RECURSE found ${BINARY}/grape/${pattern})
  list(FILTER found EXCLUDE REGEX "/CMakeFiles/")
  if(found)
    message(FATAL_ERROR "built, but not asked for: ${found}")
  endif()
endforeach()
message(STATUS "built from grape: ${libraries}")
