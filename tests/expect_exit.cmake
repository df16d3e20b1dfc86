# Runs a command as a user would and checks its exit status and output exactly:
#   cmake -DTOOL=exe -DARGS="a|b|c" -DSTATUS=2 [-DSTDERR=regex] [-DSTDOUT=regex] -P expect_exit.cmake
# Arguments are separated by '|' so that they may hold spaces and semicolons.
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND ${TOOL} ${args} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT "${status}" STREQUAL "${STATUS}")
  message(FATAL_ERROR "exit status ${status}, expected ${STATUS}\nstdout: ${out}\nstderr: ${err}")
endif()
if(DEFINED STDERR AND NOT err MATCHES "${STDERR}")
  message(FATAL_ERROR "stderr does not match '${STDERR}':\n${err}")
endif()
if(DEFINED STDOUT AND NOT out MATCHES "${STDOUT}")
  message(FATAL_ERROR "stdout does not match '${STDOUT}':\n${out}")
endif()
if(NOT "${STATUS}" STREQUAL "0" AND NOT out STREQUAL "")
  message(FATAL_ERROR "a failing command printed to stdout:\n${out}")
endif()
