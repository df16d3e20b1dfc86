# Warnings are errors in grape's own code; third-party headers come in as SYSTEM includes.
function(grape_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Werror)
endfunction()

# grape_module(NAME SOURCES... [DEPS targets...] [PRIVATE_DEPS targets...])
# A static library grape_NAME with the alias grape::NAME, installed and exported.
function(grape_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(grape_${name} STATIC ${ARG_SOURCES})
  add_library(grape::${name} ALIAS grape_${name})
  set_target_properties(grape_${name} PROPERTIES EXPORT_NAME ${name} POSITION_INDEPENDENT_CODE ON)
  target_include_directories(grape_${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(grape_${name} PUBLIC cxx_std_20)
  target_link_libraries(grape_${name} PUBLIC ${ARG_DEPS})
  if(ARG_PRIVATE_DEPS)
    target_link_libraries(grape_${name} PRIVATE ${ARG_PRIVATE_DEPS})
  endif()
  grape_warnings(grape_${name})
  if(GRAPE_INSTALL)
    install(TARGETS grape_${name} EXPORT grape-targets
            ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
            LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  endif()
endfunction()
