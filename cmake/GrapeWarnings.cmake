include(GenerateExportHeader)

# grape_warnings(TARGET): the settings of every target grape builds from its own code.
# Warnings are on for grape's code only (third-party headers come in as SYSTEM includes);
# they are errors only with GRAPE_WERROR=ON (CI and scripts/ set it; a project that builds
# grape as a dependency never gets -Werror). GRAPE_SANITIZE adds ASan + UBSan (with
# float-cast-overflow) to these
# targets alone, never to the flags of a project that includes grape.
function(grape_warnings target)
  # The fast paths reproduce the general update bit for bit, so the compiler may not fuse a*b + c
  # differently in each (FMA hardware, -march=native, Apple Silicon); and sqrt must be the
  # correctly rounded instruction, not a libm call kept for errno (MinGW's is an ulp off).
  # No public header needs either, so neither reaches a consumer's build. MSVC does not
  # contract under /fp:precise unless /fp:contract is given.
  if(MSVC)
    target_compile_options(${target} PRIVATE /W4 /permissive- /fp:precise)
  else()
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -ffp-contract=off -fno-math-errno)
  endif()
  if(GRAPE_WERROR)
    set_property(TARGET ${target} PROPERTY COMPILE_WARNING_AS_ERROR ON)
  endif()
  if(GRAPE_SANITIZE AND NOT MSVC)
    # float-cast-overflow: not part of -fsanitize=undefined, and out-of-range float-to-integer
    # conversions are exactly the faults extreme times and lengths provoke.
    set(flags -fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all)
    target_compile_options(${target} PRIVATE ${flags} -fno-omit-frame-pointer)
    # PUBLIC: whatever links a sanitized static library must link the runtimes too.
    get_target_property(type ${target} TYPE)
    if(type STREQUAL "EXECUTABLE" OR type STREQUAL "SHARED_LIBRARY" OR type STREQUAL "MODULE_LIBRARY")
      target_link_options(${target} PRIVATE ${flags})
    endif()
    target_link_options(${target} INTERFACE $<BUILD_INTERFACE:${flags}>)
  endif()
endfunction()

# grape_module(NAME SOURCES... [DEPS targets...] [PRIVATE_DEPS targets...] [HEADER_ONLY_DEPS targets...])
# The library grape_NAME (static, or shared with BUILD_SHARED_LIBS=ON) with the alias
# grape::NAME, installed and exported. HEADER_ONLY_DEPS (Eigen, nlohmann-json) lend only their
# include folders and definitions to the build: they never appear in the exported link
# interface, so a consumer needs neither installed. A shared library exports only what its
# public headers mark GRAPE_NAME_API (grape/export_NAME.hpp, generated): dllexport while it is
# built, dllimport for its users, default visibility on ELF, where everything else is hidden as
# on Windows, so a Linux build catches a missing mark. A static library defines
# GRAPE_NAME_STATIC for itself and whatever links it, which empties the mark.
function(grape_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS;HEADER_ONLY_DEPS" ${ARGN})
  add_library(grape_${name} ${ARG_SOURCES})
  add_library(grape::${name} ALIAS grape_${name})
  set_target_properties(grape_${name} PROPERTIES EXPORT_NAME ${name} POSITION_INDEPENDENT_CODE ON
                        VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
  # Installed shared libraries find each other next to themselves (render needs sprite, ...):
  # a program's own RUNPATH does not apply to its libraries' dependencies.
  set_target_properties(grape_${name} PROPERTIES INSTALL_RPATH "$ORIGIN")
  # One unit per library (batch size 0: CMake's default of 8 split anim, path, scene and
  # dynamics in two or three, each parsing the same headers and instantiating the same
  # templates again; one unit saved ~30 s of a ~200 s build, measured with bench/build-time).
  if(GRAPE_UNITY_BUILD)
    set_target_properties(grape_${name} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 0)
  endif()
  target_include_directories(grape_${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  # The sources' shared internal headers ("internal/compiler.hpp", "path/kernel.hpp"): build only.
  target_include_directories(grape_${name} PRIVATE ${PROJECT_SOURCE_DIR}/src)
  target_compile_features(grape_${name} PUBLIC cxx_std_20)
  target_link_libraries(grape_${name} PUBLIC ${ARG_DEPS})
  if(ARG_PRIVATE_DEPS)
    target_link_libraries(grape_${name} PRIVATE ${ARG_PRIVATE_DEPS})
  endif()
  foreach(dep IN LISTS ARG_HEADER_ONLY_DEPS)
    target_include_directories(grape_${name} SYSTEM PRIVATE $<TARGET_PROPERTY:${dep},INTERFACE_INCLUDE_DIRECTORIES>)
    target_compile_definitions(grape_${name} PRIVATE $<TARGET_PROPERTY:${dep},INTERFACE_COMPILE_DEFINITIONS>)
  endforeach()
  grape_warnings(grape_${name})
  string(TOUPPER ${name} upper)
  set(export_header ${PROJECT_BINARY_DIR}/include/grape/export_${name}.hpp)
  generate_export_header(grape_${name} BASE_NAME grape_${name} EXPORT_MACRO_NAME GRAPE_${upper}_API
                         STATIC_DEFINE GRAPE_${upper}_STATIC EXPORT_FILE_NAME ${export_header})
  set_target_properties(grape_${name} PROPERTIES CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  get_target_property(type grape_${name} TYPE)
  if(NOT type STREQUAL "SHARED_LIBRARY")
    target_compile_definitions(grape_${name} PUBLIC GRAPE_${upper}_STATIC)
  elseif(CMAKE_EXECUTABLE_FORMAT STREQUAL "ELF" AND NOT GRAPE_SANITIZE)
    # As a DLL must: every symbol resolved when the library links, so that a use of another
    # module's unexported function fails here rather than in a program (the sanitizers' runtimes
    # are left to the program).
    target_link_options(grape_${name} PRIVATE LINKER:--no-undefined)
  endif()
  if(GRAPE_INSTALL)
    install(TARGETS grape_${name} EXPORT grape-targets
            ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
            LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
            RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
    install(FILES ${export_header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/grape)
  endif()
endfunction()

# grape_installed_program(TARGET): installs one of grape's programs into the bin folder. With
# shared libraries it finds them through an RPATH relative to itself ($ORIGIN/../lib), so an
# install moved elsewhere, or installed under any prefix, still runs.
function(grape_installed_program target)
  if(NOT GRAPE_INSTALL)
    return()
  endif()
  if(BUILD_SHARED_LIBS AND NOT IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
    file(RELATIVE_PATH to_lib /${CMAKE_INSTALL_BINDIR} /${CMAKE_INSTALL_LIBDIR})
    set_property(TARGET ${target} PROPERTY INSTALL_RPATH "$ORIGIN/${to_lib}")
  endif()
  install(TARGETS ${target} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endfunction()
