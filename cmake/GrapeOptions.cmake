# Optional parts of grape: GRAPE_WITH_<PART> is a cache string AUTO | ON | OFF.
#   AUTO  builds the part when what it needs is found (searched again at every configure, so
#         installing a package later and re-running cmake turns the part on);
#   ON    builds it, and stops the configure naming the missing package if something is missing;
#   OFF   leaves it out.
# The decision is a normal variable of the same name (ON or OFF), so `if(GRAPE_WITH_RENDER)`
# below the top-level CMakeLists.txt reads the decision, never the request.

# grape_option(PART DOC): declares GRAPE_WITH_<PART> (default AUTO).
function(grape_option part doc)
  set(var GRAPE_WITH_${part})
  # OFF cached as BOOL comes from grape's former option(), which stored "not found at the
  # first configure" rather than a choice: such a folder starts again at AUTO.
  get_property(type CACHE ${var} PROPERTY TYPE)
  if(type STREQUAL "BOOL")
    if(NOT ${var})
      set_property(CACHE ${var} PROPERTY VALUE AUTO)
    endif()
    set_property(CACHE ${var} PROPERTY TYPE STRING)
  endif()
  set(${var} AUTO CACHE STRING "${doc}: AUTO (when its packages are found), ON or OFF")
  set_property(CACHE ${var} PROPERTY STRINGS AUTO ON OFF)
endfunction()

# grape_decide(PART MISSING [DETAIL text] [NOT_TOP_LEVEL_OFF]): turns the request into the
# decision. MISSING is "" when everything is found, else why not ("Eigen3 not found: apt
# install libeigen3-dev"); DETAIL says what was found. NOT_TOP_LEVEL_OFF: AUTO means OFF when
# grape is not the top-level project (the tool and the studio are not a consumer's business).
# Appends one line to the configure summary.
function(grape_decide part missing)
  cmake_parse_arguments(ARG "NOT_TOP_LEVEL_OFF" "DETAIL" "" ${ARGN})
  set(var GRAPE_WITH_${part})
  string(TOUPPER "${${var}}" request)
  string(TOLOWER "${part}" name)
  if(request STREQUAL "AUTO")
    if(ARG_NOT_TOP_LEVEL_OFF AND NOT PROJECT_IS_TOP_LEVEL)
      set(enabled OFF)
      set(why "grape is a subproject (${var}=ON builds it)")
    elseif(missing)
      set(enabled OFF)
      set(why "${missing}")
    else()
      set(enabled ON)
      set(why "found ${ARG_DETAIL}")
    endif()
  elseif(request MATCHES "^(ON|YES|TRUE|Y|1)$")
    if(missing)
      message(FATAL_ERROR "${var}=ON, but ${missing} (or set ${var}=AUTO or OFF)")
    endif()
    set(enabled ON)
    set(why "found ${ARG_DETAIL} (${var}=ON)")
  elseif(request MATCHES "^(OFF|NO|FALSE|N|0|)$")
    set(enabled OFF)
    set(why "${var}=OFF")
  else()
    message(FATAL_ERROR "${var} is '${${var}}'; expected AUTO, ON or OFF")
  endif()
  set(${var} ${enabled} PARENT_SCOPE)
  if(enabled)
    set(state "on ")
  else()
    set(state "off")
  endif()
  string(LENGTH "${name}" length)
  math(EXPR pad "9 - ${length}")
  string(REPEAT " " ${pad} spaces)
  set_property(GLOBAL APPEND PROPERTY GRAPE_SUMMARY "  ${name}${spaces}${state}  ${why}")
endfunction()

# grape_summary_line(TEXT): one more line for the summary.
function(grape_summary_line text)
  set_property(GLOBAL APPEND PROPERTY GRAPE_SUMMARY "  ${text}")
endfunction()

function(grape_print_summary)
  get_property(lines GLOBAL PROPERTY GRAPE_SUMMARY)
  set_property(GLOBAL PROPERTY GRAPE_SUMMARY "")
  foreach(line IN LISTS lines)
    message(STATUS "${line}")
  endforeach()
endfunction()
